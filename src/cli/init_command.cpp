// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/init_command.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "app/case_keys.hpp"
#include "app/run_case.hpp"
#include "app/study_loaders.hpp"
#include "cases/input_file.hpp"
#include "report/text_escape.hpp"

namespace armstudy::cli {
namespace {
constexpr int kDone = 0, kBadInput = 2, kRuntime = 3;

// why `path` may not be replaced ("" when it is absent or is an init case left as written)
std::string refusal(const std::filesystem::path& path) {
  std::error_code ec;
  const auto st = std::filesystem::symlink_status(path, ec);
  if (!std::filesystem::exists(st)) return "";
  if (!std::filesystem::is_regular_file(st))
    return "is not a regular file; armstudy writes a new file or replaces only a case it wrote";
  std::string bytes, why;
  bool runtime = false;
  if (!cases::read_input_file(path.string(), {1 << 20, "YAML file", false}, &bytes, &why, &runtime))
    return why;
  for (const app::StudyLoader& l : app::study_loaders())
    if (bytes == app::init_case(l.study)) return "";
  return "exists and is not a case armstudy init wrote (or it was edited since); armstudy "
         "never replaces a file it did not write: choose another -o or move it away";
}
}  // namespace

int cmd_init(const std::string& study, const std::string& out_file) {
  std::string text;
  try {
    text = app::init_case(study);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "armstudy init: %s\n", report::terminal_text(e.what()).c_str());
    return kBadInput;
  }
  if (out_file.empty()) {
    std::fputs(text.c_str(), stdout);
    return kDone;
  }
  if (const std::string why = refusal(out_file); !why.empty()) {
    std::fprintf(stderr, "armstudy init: %s %s; nothing was written\n",
                 report::terminal_text(out_file).c_str(), why.c_str());
    return kBadInput;
  }
  try {
    app::write_file_atomic(out_file, text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy init: cannot write %s: %s\n",
                 report::terminal_text(out_file).c_str(), e.what());
    return kRuntime;
  }
  std::fprintf(stderr, "wrote %s: a %s case with every key at its default\n",
               report::terminal_text(out_file).c_str(), study.c_str());
  return kDone;
}

}  // namespace armstudy::cli
