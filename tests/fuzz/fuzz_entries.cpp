// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "fuzz/fuzz_entries.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>

#include "app/pipeline.hpp"
#include "cases/case_error.hpp"
#include "cases/input_file.hpp"
#include "cli/diff_tolerances.hpp"
#include "cli/merge.hpp"
#include "cli/sweep.hpp"
#include "report/templates.hpp"

#include <kainjow/mustache.hpp>

namespace armstudy::fuzz {
namespace {
namespace fs = std::filesystem;

const char* kBase =
    "study: placement\nname: base\nplacement: {length_fraction: 0.5, nx_s: 4, samples: 21}\n";
const char* kSweep =
    "sweep: fuzz\nbase: fuzz-base.yaml\nmode: grid\naxes:\n"
    "  - path: placement.length_fraction\n    values: [0.4, 0.6]\n";

// this process's folder for the files the readers take by path, removed at exit
struct WorkDir {
  fs::path path = fs::temp_directory_path() / ("armstudy-fuzz-" + std::to_string(getpid()));
  WorkDir() {
    fs::create_directories(path / "run" / "case-a");
    fs::create_directories(path / "templates");
  }
  ~WorkDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

const fs::path& work_dir() {
  static const WorkDir dir;
  return dir.path;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
}

// "" when `load` loaded or refused with CaseErrors that each say why
template <class Load>
std::string only_case_errors(const char* what, Load load) {
  try {
    load();
  } catch (const cases::CaseErrors& e) {
    if (e.errors().empty()) return std::string(what) + ": refused without an error";
    for (const auto& err : e.errors())
      if (err.message.empty()) return std::string(what) + ": an error without a message";
  }
  return "";
}

// small valid templates beside the one the input stands for
const char* kStandIn[] = {
    "<html><body>{{title}}{{#sections}}{{heading}}{{/sections}}</body></html>",
    "<html><body>{{#cases}}{{name}}{{/cases}}</body></html>", "body { color: #000; }"};

// ARMSTUDY_TEMPLATE_DIR set for one call, put back (or unset) after
struct TemplateDirScope {
  std::optional<std::string> before;
  explicit TemplateDirScope(const fs::path& dir) {
    if (const char* v = std::getenv("ARMSTUDY_TEMPLATE_DIR")) before = v;
    ::setenv("ARMSTUDY_TEMPLATE_DIR", dir.c_str(), 1);
  }
  ~TemplateDirScope() {
    if (before)
      ::setenv("ARMSTUDY_TEMPLATE_DIR", before->c_str(), 1);
    else
      ::unsetenv("ARMSTUDY_TEMPLATE_DIR");
  }
};

}  // namespace

std::string case_and_sweep_loaders(const std::string& input) {
  std::string problem =
      only_case_errors("as a case", [&] { app::load_case_text(input, "fuzz.yaml"); });
  if (!problem.empty()) return problem;
  const fs::path& d = work_dir();
  const std::string sweep = (d / "fuzz-sweep.yaml").string();
  // the input as a sweep over the fixed base
  write(d / "fuzz-base.yaml", kBase);
  write(sweep, input);
  problem = only_case_errors("as a sweep", [&] { cli::load_sweep(sweep); });
  if (!problem.empty()) return problem;
  // the input as the base of the fixed sweep
  write(d / "fuzz-base.yaml", input);
  write(sweep, kSweep);
  return only_case_errors("as a sweep's base", [&] { cli::load_sweep(sweep); });
}

std::string results_and_tolerances_readers(const std::string& input) {
  const fs::path& d = work_dir();
  write(d / "run" / "case-a" / "results.json", input);
  std::vector<std::string> warnings;
  const std::vector<cli::CaseOutput> outputs = cli::collect_outputs({d / "run"}, &warnings);
  if (outputs.size() != 1)
    return "as results.json: " + std::to_string(outputs.size()) + " cases read";
  const report::ResultsRecord& r = outputs[0].record;
  if (warnings.empty() && r.status != "solved" && r.status != "unsolvable")
    return "as results.json: read without a warning, status '" + r.status + "'";
  if (!warnings.empty() && (r.status != "unreadable" || r.message.empty() ||
                            warnings[0].find("results.json") == std::string::npos))
    return "as results.json: refused without a failed case naming the file";
  // what merge writes from it
  (void)cli::summary_markdown(outputs);
  (void)cli::junit_xml(outputs);
  (void)cli::sweep_csv(outputs);
  (void)cli::sweep_json(outputs).dump();

  const std::string tolerances = (d / "tolerances.yaml").string();
  write(tolerances, input);
  return only_case_errors("as --tolerances", [&] {
    const cli::DiffTolerances t = cli::load_diff_tolerances(tolerances);
    (void)t.lookup("placement", "min_energy_J");
    (void)t.lookup("throwing", "idp_run_time_s");
  });
}

std::string template_folder_reader(const std::string& input) {
  const fs::path dir = work_dir() / "templates";
  const TemplateDirScope scope(dir);
  constexpr size_t kNames = std::size(report::kTemplateNames);
  for (size_t as = 0; as < kNames; ++as) {
    for (size_t k = 0; k < kNames; ++k)
      write(dir / report::kTemplateNames[k], k == as ? input : std::string(kStandIn[k]));
    const std::string name = report::kTemplateNames[as];
    try {
      report::check_templates();
    } catch (const cases::InputFileError& e) {
      if (std::string(e.what()).empty()) return "as " + name + ": refused without a message";
      continue;
    }
    if (!name.ends_with(".html")) continue;
    // accepted: it renders (as a run's page writer does) without crashing
    kainjow::mustache::mustache page{report::read_template(dir / name)};
    kainjow::mustache::data d;
    d.set("title", "fuzz");
    (void)page.render(d);
  }
  return "";
}

}  // namespace armstudy::fuzz
