// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/templates.hpp"

#include <kainjow/mustache.hpp>

#include <cstdlib>

#include "cases/input_file.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;

fs::path template_dir() {
  if (const char* env = std::getenv("ARMSTUDY_TEMPLATE_DIR"); env && *env) return env;
  // installed: <prefix>/bin/armstudy reads <prefix>/share/armstudy/templates; a program of
  // the build tree (armstudy, the tests) reads the source tree's templates/
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path installed = self.parent_path().parent_path() / "share" / "armstudy" / "templates";
#if defined(ARMSTUDY_BUILD_TREE) && defined(ARMSTUDY_TEMPLATE_DIR)
  const std::string build = ARMSTUDY_BUILD_TREE "/";
  if (ec || self.string().rfind(build, 0) == 0) return ARMSTUDY_TEMPLATE_DIR;
#endif
  return installed;
}

std::string read_template(const fs::path& p) {
  return cases::read_input_file(p.string(), {kMaxTemplateBytes, "template file", true});
}

void check_templates() {
  const fs::path dir = template_dir();
  for (const char* name : kTemplateNames) {
    std::string text;
    try {
      text = read_template(dir / name);
    } catch (const cases::InputFileError& e) {
      throw cases::InputFileError(std::string("the report template ") + e.what() +
                                      " (the folder is $ARMSTUDY_TEMPLATE_DIR, or the installed "
                                      "share/armstudy/templates)",
                                  e.runtime());
    }
    if (std::string(name).ends_with(".html")) {
      kainjow::mustache::mustache tmpl{text};
      if (!tmpl.is_valid())
        throw cases::InputFileError(
            "the report template " + (dir / name).string() + ": " + tmpl.error_message(), false);
    }
  }
}

}  // namespace armstudy::report
