// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/merge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "app/run_case.hpp"
#include "cases/input_file.hpp"
#include "report/markdown.hpp"
#include "report/number_format.hpp"
#include "report/owned_output.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "report/text_escape.hpp"

namespace armstudy::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using report::md_cell;
using report::ResultsRecord;
using report::xml_text;

// the case ended as it expects
bool status_as_expected(const ResultsRecord& r) { return r.status == r.expected_status(); }

std::string failure_text(const ResultsRecord& r) {
  if (r.status == "unreadable" || r.status == "duplicate" || r.status == "missing" ||
      r.status == "error")
    return r.message;
  if (!status_as_expected(r) && r.expected_status() == "unsolvable")
    return "solved, but the case expects it to be unsolvable";
  if (!status_as_expected(r)) return "could not be solved: " + r.message;
  std::string s;
  for (const auto& c : r.checks)
    if (!c.passed)
      s += (s.empty() ? "failed checks: " : ", ") + c.name + " (" + report::format_sig(c.value, 4) +
           " > " + report::format_sig(c.tolerance, 4) + ")";
  return s;
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

// key figure names of a study in first-seen order over the (sorted) cases
std::vector<std::pair<std::string, std::string>> figure_columns(
    const std::vector<const CaseOutput*>& cases) {
  std::vector<std::pair<std::string, std::string>> cols;
  std::set<std::string> seen;
  for (const auto* c : cases)
    for (const auto& k : c->record.key_figures)
      if (seen.insert(k.name).second) cols.emplace_back(k.name, k.unit);
  return cols;
}

// a key figure's value; none for a missing one or NaN (how JSON's null reads)
std::optional<double> figure(const ResultsRecord& r, const std::string& name) {
  for (const auto& k : r.key_figures)
    if (k.name == name && std::isfinite(k.value)) return k.value;
  return std::nullopt;
}

}  // namespace

const char* run_level_file(const std::string& name) {
  // every run-level output (report::run_level_outputs), each study's figure over all its
  // cases on the index page included (e.g. placement_root_loci.svg)
  static const std::vector<std::string> names = [] {
    std::vector<std::string> figures;
    for (const app::StudyEntry& e : app::study_registry())
      if (!e.index_figure.file.empty()) figures.emplace_back(e.index_figure.file);
    return report::run_level_outputs(figures);
  }();
  for (const std::string& f : names)
    if (name == f) return f.c_str();
  return nullptr;
}

std::string results_problem(const json& r) {
  try {
    // the shared record, typed and strict (schema_version first), then the study's own
    // section read into its typed result: a misspelt key is an error naming it
    const report::ResultsRecord record = report::read_record(r);
    if (const app::StudyEntry* study = app::find_study(record.study)) study->check_results(r);
  } catch (const report::ResultsError& x) {
    if (x.path() == "/schema_version")
      return std::string(x.what()).substr(std::string("/schema_version: ").size());
    return x.what();
  }
  return "";
}

CaseOutput failed_output(const fs::path& folder, const std::string& name, const std::string& study,
                         const std::string& status, const std::string& message) {
  ResultsRecord bad;
  bad.study = study;
  bad.case_info.name = name;
  bad.status = status;
  bad.message = message;
  return CaseOutput{folder, json::object(), std::move(bad)};
}

namespace {

void check_limits(const fs::path& rj, const ResultsRecord& r, std::set<std::string>* names) {
  if (r.key_figures.size() > kMaxKeyFigures)
    throw InputLimitError(rj.string() + ": " + std::to_string(r.key_figures.size()) +
                          " key figures; expected at most " + std::to_string(kMaxKeyFigures) +
                          " (docs/budgets.md)");
  if (r.frames.size() > kMaxFrames)
    throw InputLimitError(rj.string() + ": " + std::to_string(r.frames.size()) +
                          " frames; expected at most " + std::to_string(kMaxFrames) +
                          " (docs/budgets.md)");
  for (const auto& k : r.key_figures) names->insert(k.name);
  if (names->size() > kMaxKeyFigures)
    throw InputLimitError(rj.string() + ": the cases so far have " + std::to_string(names->size()) +
                          " different key figures; expected at most " +
                          std::to_string(kMaxKeyFigures) + " (docs/budgets.md)");
}

}  // namespace

// (over 60 lines, kept whole: one pass over the folders' entries, each kind of entry a branch)
std::vector<CaseOutput> collect_outputs(const std::vector<fs::path>& dirs,
                                        std::vector<std::string>* warnings) {
  std::map<std::string, CaseOutput> by_name;
  std::set<std::string> duplicates, figure_names;
  size_t files = 0;
  std::uintmax_t total_bytes = 0;
  for (const auto& dir : dirs) {
    if (!fs::is_directory(dir)) {
      if (warnings) warnings->push_back(dir.string() + ": not a folder");
      continue;
    }
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_directory() && e.path().filename().string()[0] != '.') folders.push_back(e.path());
    std::sort(folders.begin(), folders.end());
    for (const auto& f : folders) {
      const fs::path rj = f / "results.json";
      std::error_code ec;
      if (!fs::exists(fs::symlink_status(rj, ec))) continue;
      if (++files > kMaxMergedCases)
        throw InputLimitError(dir.string() + ": more than " + std::to_string(kMaxMergedCases) +
                              " results.json files; expected at most that many cases "
                              "(docs/budgets.md)");
      const std::uintmax_t size = fs::is_regular_file(rj, ec) ? fs::file_size(rj, ec) : 0;
      if (!ec && size > kMaxResultsBytes)
        throw InputLimitError(rj.string() + ": " + std::to_string(size) +
                              " bytes; expected a results.json of at most " +
                              std::to_string(kMaxResultsBytes) + " bytes (docs/budgets.md)");
      // a FIFO, device, link or oversized file is refused (InputFileError), never read
      const std::string bytes = cases::read_input_file(
          rj.string(), {cases::kMaxResultsJsonBytes, "results.json file", false});
      total_bytes += bytes.size();
      if (total_bytes > kMaxMergedBytes)
        throw InputLimitError(rj.string() + ": the results.json files so far hold " +
                              std::to_string(total_bytes) + " bytes; expected at most " +
                              std::to_string(kMaxMergedBytes) + " together (docs/budgets.md)");
      CaseOutput c{f, json(), {}};
      std::string problem;
      try {
        c.results = json::parse(bytes);
        problem = results_problem(c.results);
        if (problem.empty()) c.record = report::read_record(c.results);
      } catch (const json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 3, column 1: ..." without the tag
        std::string what = e.what();
        if (const size_t at = what.find("] "); at != std::string::npos) what = what.substr(at + 2);
        problem = "truncated or not JSON (" + what + ")";
      } catch (const std::exception& e) {
        problem = e.what();
      }
      if (problem.empty()) check_limits(rj, c.record, &figure_names);
      if (!problem.empty()) {
        // a failed case, named after its folder: CI must not go green on it
        const std::string reason = rj.string() + ": " + problem;
        if (warnings) warnings->push_back(reason);
        const std::string study =
            c.results.is_object() && c.results.contains("study") && c.results["study"].is_string()
                ? c.results["study"].get<std::string>()
                : std::string("unreadable");
        c = failed_output(f, f.filename().string(), study, "unreadable",
                          "results.json unreadable: " + reason);
      }
      const std::string n = c.record.case_info.name;
      if (auto it = by_name.find(n); it != by_name.end()) {
        // two results for one case: neither is the case's result
        const std::string reason = "case '" + n + "' has results in " + it->second.folder.string() +
                                   " and " + f.string() + "; expected one (remove the stale one)";
        if (warnings) warnings->push_back(reason);
        if (!duplicates.count(n))
          it->second =
              failed_output(it->second.folder, n, it->second.record.study, "duplicate", reason);
        duplicates.insert(n);
        continue;
      }
      by_name.emplace(n, std::move(c));
    }
  }
  std::vector<CaseOutput> out;
  for (auto& [n, c] : by_name) out.push_back(std::move(c));
  return out;
}

size_t apply_manifest(const SweepManifest& m, const fs::path& where, std::vector<CaseOutput>* cases,
                      std::vector<std::string>* warnings) {
  const std::set<std::string> ids(m.cases.begin(), m.cases.end());
  std::vector<CaseOutput> kept;
  std::set<std::string> found;
  for (auto& c : *cases) {
    const std::string& n = c.record.case_info.name;
    if (ids.count(n)) {
      found.insert(n);
      kept.push_back(std::move(c));
    } else if (warnings) {
      warnings->push_back(c.folder.string() + ": case '" + n + "' is not in sweep '" + m.sweep +
                          "' (" + where.string() + "); left out");
    }
  }
  size_t missing = 0;
  for (const auto& id : m.cases) {
    if (found.count(id)) continue;
    ++missing;
    kept.push_back(failed_output(fs::path(), id, "missing", "missing",
                                 "no results.json: case '" + id + "' of sweep '" + m.sweep +
                                     "' did not run or its output is not in the merged folders"));
  }
  std::sort(kept.begin(), kept.end(), [](const CaseOutput& a, const CaseOutput& b) {
    return a.record.case_info.name < b.record.case_info.name;
  });
  *cases = std::move(kept);
  return missing;
}

bool case_passed(const ResultsRecord& r) { return status_as_expected(r) && r.checks_passed(); }

std::string summary_markdown(const std::vector<CaseOutput>& cases, size_t max_bytes) {
  size_t failed = 0;
  for (const auto& c : cases) failed += !case_passed(c.record);
  std::ostringstream md;
  md << "# armstudy: " << cases.size() << " case(s), " << failed << " failed\n\n";
  if (failed) {
    md << "## Failures\n\n| case | study | what failed |\n|---|---|---|\n";
    for (const auto& c : cases)
      if (!case_passed(c.record))
        md << "| " << md_cell(c.record.case_info.name) << " | " << md_cell(c.record.study) << " | "
           << md_cell(failure_text(c.record)) << " |\n";
    md << "\n";
  }
  std::map<std::string, std::vector<const CaseOutput*>> by_study;
  for (const auto& c : cases) by_study[c.record.study].push_back(&c);
  for (const auto& [study, list] : by_study) {
    const auto cols = figure_columns(list);
    md << "## " << md_cell(study) << " (" << list.size() << ")\n\n| case | status | checks |";
    for (const auto& [n, u] : cols)
      md << " " << md_cell(u.empty() ? n : n + " (" + u + ")") << " |";
    md << "\n|---|---|---|";
    for (size_t i = 0; i < cols.size(); ++i) md << "---:|";
    md << "\n";
    for (const auto* c : list) {
      const auto& r = c->record;
      size_t passed = 0, total = 0;
      for (const auto& ch : r.checks) {
        ++total;
        passed += ch.passed;
      }
      md << "| " << md_cell(r.case_info.name) << " | " << (case_passed(r) ? "ok" : "FAILED")
         << " | " << passed << "/" << total << " |";
      for (const auto& [n, u] : cols) {
        const auto v = figure(r, n);
        md << " " << (v ? report::format_sig(*v, 6) : "") << " |";
      }
      md << "\n";
    }
    md << "\n";
  }
  std::string s = md.str();
  if (s.size() > max_bytes) {
    const std::string note = "\n\n*Truncated: the full summary is larger than " +
                             std::to_string(max_bytes) +
                             " bytes; see junit.xml and each case's results.json.*\n";
    s.resize(max_bytes - note.size());
    s.resize(s.rfind('\n') + 1);
    s += note;
  }
  return s;
}

namespace {
// seconds as junit.xml writes them: milliseconds, never negative
std::string junit_seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", std::isfinite(s) && s > 0 ? s : 0.0);
  return text;
}
}  // namespace

std::string junit_xml(const std::vector<CaseOutput>& cases) {
  std::map<std::string, std::vector<const CaseOutput*>> by_study;
  for (const auto& c : cases) by_study[c.record.study].push_back(&c);
  size_t tests = 0, failures = 0;
  double total_s = 0;
  std::ostringstream body;
  for (const auto& [study, list] : by_study) {
    size_t st = 0, sf = 0;
    double suite_s = 0;
    std::ostringstream tc;
    for (const auto* c : list) {
      const auto& r = c->record;
      const std::string cls = xml_text(study + "." + r.case_info.name);
      ++st;
      // the case's run is its "solve" test case's time; its checks ran within it
      const double case_s = r.run_time_s.value_or(0.0);
      suite_s += std::isfinite(case_s) && case_s > 0 ? case_s : 0.0;
      tc << "    <testcase classname=\"" << cls << "\" name=\"solve\" time=\""
         << junit_seconds(case_s) << "\"";
      if (!status_as_expected(r)) {
        ++sf;
        tc << "><failure message=\"" << xml_text(failure_text(r)) << "\"/></testcase>\n";
      } else {
        tc << "/>\n";
      }
      for (const auto& ch : r.checks) {
        ++st;
        tc << "    <testcase classname=\"" << cls << "\" name=\"" << xml_text(ch.name)
           << "\" time=\"0.000\"";
        if (!ch.passed) {
          ++sf;
          tc << "><failure message=\""
             << xml_text("value " + report::format_sig(ch.value, 6) + " exceeds tolerance " +
                         report::format_sig(ch.tolerance, 6))
             << "\">" << xml_text(ch.description) << "</failure></testcase>\n";
        } else {
          tc << "/>\n";
        }
      }
    }
    body << "  <testsuite name=\"" << xml_text(study) << "\" tests=\"" << st << "\" failures=\""
         << sf << "\" errors=\"0\" time=\"" << junit_seconds(suite_s) << "\">\n"
         << tc.str() << "  </testsuite>\n";
    tests += st;
    failures += sf;
    total_s += suite_s;
  }
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"armstudy\" tests=\"" << tests
    << "\" failures=\"" << failures << "\" errors=\"0\" time=\"" << junit_seconds(total_s)
    << "\">\n"
    << body.str() << "</testsuites>\n";
  return x.str();
}

namespace {
// the sweep's cases (sorted by case id), its parameters (sorted) and its key figures' columns
struct SweepColumns {
  std::vector<std::string> params;
  std::vector<std::pair<std::string, std::string>> figures;
  std::vector<const CaseOutput*> rows;
};

SweepColumns sweep_columns(const std::vector<CaseOutput>& cases) {
  SweepColumns t;
  for (const auto& c : cases) {
    if (!c.record.case_info.sweep) continue;
    t.rows.push_back(&c);
    for (const auto& [key, value] : c.record.case_info.sweep->point)
      if (std::find(t.params.begin(), t.params.end(), key) == t.params.end())
        t.params.push_back(key);
  }
  std::sort(t.params.begin(), t.params.end());
  t.figures = figure_columns(t.rows);
  return t;
}
}  // namespace

report::SweepTable sweep_table(const std::vector<CaseOutput>& cases) {
  const SweepColumns t = sweep_columns(cases);
  report::SweepTable table;
  table.parameters = t.params;
  for (const auto& [n, u] : t.figures) {
    table.figures.push_back(n);
    table.units[n] = u;
  }
  for (const auto* c : t.rows) {
    const auto& r = c->record;
    report::SweepRow row;
    row.case_name = r.case_info.name;
    row.status = case_passed(r) ? "ok" : "failed";
    const auto& point = r.case_info.sweep->point;
    for (const auto& p : t.params)
      row.parameters[p] = point.count(p) ? std::optional(point.at(p)) : std::nullopt;
    for (const auto& [n, u] : t.figures) row.key_figures[n] = figure(r, n);
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::string sweep_csv(const std::vector<CaseOutput>& cases) {
  const report::SweepTable t = sweep_table(cases);
  if (t.rows.empty()) return "";
  std::ostringstream csv;
  csv << "case,status";
  for (const auto& p : t.parameters) csv << "," << csv_cell(p);
  for (const auto& n : t.figures) {
    const std::string& u = t.units.at(n);
    csv << "," << csv_cell(u.empty() ? n : n + " (" + u + ")");
  }
  csv << "\n";
  for (const auto& row : t.rows) {
    csv << csv_cell(row.case_name) << "," << row.status;
    for (const auto& p : t.parameters) csv << "," << csv_cell(row.parameters.at(p).value_or(""));
    for (const auto& n : t.figures) {
      const auto& v = row.key_figures.at(n);
      csv << "," << (v ? report::format_sig(*v, 10) : "");
    }
    csv << "\n";
  }
  return csv.str();
}

json sweep_json(const std::vector<CaseOutput>& cases) {
  return report::to_json(sweep_table(cases));
}

size_t write_merged(const std::vector<CaseOutput>& cases, const fs::path& out_dir) {
  fs::create_directories(out_dir);
  // never over a file of these names that armstudy did not write (report/owned_output.hpp)
  const std::string csv = sweep_csv(cases);
  for (const char* name : {"summary.md", "junit.xml", "sweep.csv", "sweep.json"})
    if (!csv.empty() || std::string(name).ends_with(".md") || std::string(name).ends_with(".xml"))
      report::check_run_level_output(out_dir, name);
  app::write_file_atomic(out_dir / "summary.md", summary_markdown(cases));
  app::write_file_atomic(out_dir / "junit.xml", junit_xml(cases));
  if (!csv.empty()) {
    app::write_file_atomic(out_dir / "sweep.csv", csv);
    app::write_file_atomic(out_dir / "sweep.json", sweep_json(cases).dump(2) + "\n");
  }
  size_t failed = 0;
  for (const auto& c : cases) failed += !case_passed(c.record);
  return failed;
}

}  // namespace armstudy::cli
