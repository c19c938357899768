// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// armstudy's rules for sys::remove_stale_scratch: which entries of an output folder it wrote
// (report/owned_output.hpp)
#include <algorithm>

#include "report/owned_output.hpp"

namespace armstudy::report {

sys::StaleCleanup remove_stale_scratch(const std::filesystem::path& dir) {
  sys::StaleRules rules;
  // a sub-folder of the output folder that armstudy wrote, where runs leave scratch folders
  // and part files: a case folder or the sweep report
  rules.own_sub_folder = [](const std::filesystem::path& d, const std::string& name) {
    return name == "sweep" ? foreign_run_level_output(d, name).empty()
                           : foreign_case_folder(d / name, name).empty();
  };
  rules.run_level_file = [run_level = run_level_outputs({})](const std::string& base) {
    return base.ends_with(".svg") ||
           std::find(run_level.begin(), run_level.end(), base) != run_level.end();
  };
  return sys::remove_stale_scratch(dir, rules);
}

}  // namespace armstudy::report
