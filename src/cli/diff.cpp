// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "app/run_case.hpp"
#include "cases/case_error.hpp"
#include "cases/input_file.hpp"
#include "cli/diff_frames.hpp"
#include "report/owned_output.hpp"
#include "report/text_escape.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::cli {
namespace fs = std::filesystem;
using nlohmann::json;
using report::CaseDiff;
using report::FigureDiff;

namespace {

// a key figure's value: nullopt when absent, NaN when null
struct Figure {
  std::string unit;
  double value;
};

std::vector<std::pair<std::string, Figure>> figures_of(const report::ResultsRecord& r) {
  std::vector<std::pair<std::string, Figure>> out;
  for (const auto& k : r.key_figures) out.push_back({k.name, {k.unit, k.value}});
  return out;
}

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// moved beyond the tolerance (a figure on one side only, or finite on one side only, moved)
bool beyond(const FigureDiff& f) {
  if (f.tolerance.ignore) return false;
  if (!f.base || !f.now) return true;
  const double a = *f.base, b = *f.now;
  if (same_number(a, b)) return false;
  if (!std::isfinite(a) || !std::isfinite(b)) return true;
  return std::abs(b - a) > std::max(f.tolerance.abs, f.tolerance.rel * std::abs(a));
}

const std::vector<std::pair<std::string, std::string>>& provenance_labels() {
  static const std::vector<std::pair<std::string, std::string>> labels = {
      {"armstudy_version", "armstudy version"},
      {"git_commit", "git commit"},
      {"mujoco_version", "MuJoCo"},
      {"mesa_version", "Mesa"},
      {"gl_renderer", "GL renderer"},
      {"gl_version", "GL version"},
      {"compiler", "compiler"},
      {"cpu_model", "CPU"}};
  return labels;
}

// provenance items of a results.json (top-level version and commit as fallbacks)
std::map<std::string, std::string> provenance_of(const report::ResultsRecord& r) {
  const report::ProvenanceRecord& p = r.provenance;
  std::map<std::string, std::string> m = {{"armstudy_version", p.armstudy_version},
                                          {"mujoco_version", p.mujoco_version},
                                          {"compiler", p.compiler},
                                          {"cpu_model", p.cpu_model}};
  if (p.git_commit) m["git_commit"] = *p.git_commit;
  if (p.gl_renderer) m["gl_renderer"] = *p.gl_renderer;
  if (p.gl_version) m["gl_version"] = *p.gl_version;
  if (p.mesa_version) m["mesa_version"] = *p.mesa_version;
  return m;
}

std::string label_of(const std::string& key) {
  for (const auto& [k, l] : provenance_labels())
    if (k == key) return l;
  std::string l = key;
  std::replace(l.begin(), l.end(), '_', ' ');
  return l;
}

// keys in a stable order: the known ones first, then the rest by name
std::vector<std::string> provenance_keys(const std::set<std::string>& present) {
  std::vector<std::string> keys;
  for (const auto& [k, l] : provenance_labels())
    if (present.count(k)) keys.push_back(k);
  for (const auto& k : present)
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  return keys;
}

// a folder name safe for a case's frame copies
std::string safe_name(const std::string& s) {
  std::string o;
  for (char c : s)
    o +=
        (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return o.empty() || o[0] == '.' ? "_" + o : o;
}

// key figures: the base's order, then the new run's additions; each beyond its tolerance
// or not (an added or removed case counts once, as itself)
void compare_figures(const CaseOutput* b, const CaseOutput* n, const DiffTolerances& tol,
                     CaseDiff& d) {
  std::vector<std::pair<std::string, Figure>> bf, nf;
  if (b) bf = figures_of(b->record);
  if (n) nf = figures_of(n->record);
  std::vector<std::string> order;
  std::map<std::string, Figure> bm, nm;
  for (const auto& [k, v] : bf) {
    if (!bm.count(k)) order.push_back(k);
    bm.emplace(k, v);
  }
  for (const auto& [k, v] : nf) {
    if (!bm.count(k) && !nm.count(k)) order.push_back(k);
    nm.emplace(k, v);
  }
  for (const auto& k : order) {
    FigureDiff f;
    f.name = k;
    if (bm.count(k)) {
      f.base = bm[k].value;
      f.unit = bm[k].unit;
    }
    if (nm.count(k)) {
      f.now = nm[k].value;
      if (f.unit.empty()) f.unit = nm[k].unit;
    }
    f.tolerance = tol.lookup(d.study, k);
    f.beyond = (b && n) ? beyond(f) : false;  // an added or removed case counts once, as itself
    d.figures.push_back(std::move(f));
  }
}

// checks whose verdict changed, and checks of one run only
void compare_checks(const CaseOutput& base, const CaseOutput& now, CaseDiff& d) {
  const CaseOutput* b = &base;
  const CaseOutput* n = &now;
  std::map<std::string, const report::CheckRecord*> bc, nc;
  std::vector<std::string> names;
  for (const auto& c : b->record.checks) {
    if (!bc.count(c.name)) names.push_back(c.name);
    bc[c.name] = &c;
  }
  for (const auto& c : n->record.checks) {
    if (!bc.count(c.name) && !nc.count(c.name)) names.push_back(c.name);
    nc[c.name] = &c;
  }
  auto num = [](const report::CheckRecord* c,
                double report::CheckRecord::*field) -> std::optional<double> {
    if (!c) return std::nullopt;
    return c->*field;
  };
  for (const auto& k : names) {
    const report::CheckRecord* x = bc.count(k) ? bc[k] : nullptr;
    const report::CheckRecord* y = nc.count(k) ? nc[k] : nullptr;
    report::CheckDiff c;
    c.name = k;
    if (x) c.base_passed = x->passed;
    if (y) c.new_passed = y->passed;
    if (c.base_passed == c.new_passed) continue;
    c.base_value = num(x, &report::CheckRecord::value);
    c.new_value = num(y, &report::CheckRecord::value);
    c.base_tolerance = num(x, &report::CheckRecord::tolerance);
    c.new_tolerance = num(y, &report::CheckRecord::tolerance);
    d.checks.push_back(std::move(c));
  }
}

// frames: every file of either run; a run rendered without frames (--no-render) has none
void compare_frames(const CaseOutput& base, const CaseOutput& now, const FrameOptions& fo,
                    CaseDiff& d) {
  const CaseOutput* b = &base;
  const CaseOutput* n = &now;
  const auto& fb = b->record.frames;
  const auto& fn = n->record.frames;
  std::vector<std::string> files = fb;
  for (const auto& f : fn)
    if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
  for (const auto& f : files) {
    const bool in_b = std::find(fb.begin(), fb.end(), f) != fb.end();
    const bool in_n = std::find(fn.begin(), fn.end(), f) != fn.end();
    if (in_b && in_n) {
      d.frames.push_back(compare_frame(b->folder, n->folder, f, fo.channel_tolerance,
                                       fo.pixels_allowed, fo.frames_root,
                                       "diff-frames/" + safe_name(d.name)));
    } else {
      report::FrameDiff x;
      x.file = f;
      x.in_base = in_b;
      x.in_new = in_n;
      // a frame gone or new counts unless that run rendered no frames at all
      x.beyond = !fb.empty() && !fn.empty();
      d.frames.push_back(std::move(x));
    }
  }
}

// the provenance items that differ
void compare_provenance(const CaseOutput& base, const CaseOutput& now, CaseDiff& d) {
  const CaseOutput* b = &base;
  const CaseOutput* n = &now;
  const auto pb = provenance_of(b->record), pn = provenance_of(n->record);
  std::set<std::string> keys;
  for (const auto& [k, v] : pb) keys.insert(k);
  for (const auto& [k, v] : pn) keys.insert(k);
  for (const auto& k : provenance_keys(keys)) {
    const std::string x = pb.count(k) ? pb.at(k) : "", y = pn.count(k) ? pn.at(k) : "";
    if (x != y)
      d.provenance.push_back({k, label_of(k), x.empty() ? "(none)" : x, y.empty() ? "(none)" : y});
  }
}

// the case's inputs that differ (both results.json must echo them: inputs_known)
void compare_inputs(const report::CaseRecord& b, const report::CaseRecord& n, CaseDiff& d) {
  d.inputs_known = b.inputs && n.inputs;
  if (!d.inputs_known) return;
  std::set<std::string> keys;
  for (const auto& [k, v] : *b.inputs) keys.insert(k);
  for (const auto& [k, v] : *n.inputs) keys.insert(k);
  for (const auto& k : keys) {
    const auto x = b.inputs->find(k), y = n.inputs->find(k);
    const std::string bx = x == b.inputs->end() ? "(none)" : x->second;
    const std::string ny = y == n.inputs->end() ? "(none)" : y->second;
    if (bx != ny) d.inputs.push_back({k, bx, ny});
  }
}

CaseDiff compare_case(const CaseOutput* b, const CaseOutput* n, const DiffTolerances& tol,
                      const FrameOptions& fo) {
  CaseDiff d;
  const report::ResultsRecord& any = (n ? n : b)->record;
  d.name = any.case_info.name;
  d.study = any.study;
  d.presence = b && n ? CaseDiff::Presence::kBoth
                      : (n ? CaseDiff::Presence::kAdded : CaseDiff::Presence::kRemoved);
  if (b) {
    d.base_status = b->record.status;
    d.base_passed = case_passed(b->record);
    d.base_message = b->record.message;
  }
  if (n) {
    d.new_status = n->record.status;
    d.new_passed = case_passed(n->record);
    d.new_message = n->record.message;
  }
  compare_figures(b, n, tol, d);
  if (b && n) {
    compare_checks(*b, *n, d);
    compare_frames(*b, *n, fo, d);
    compare_provenance(*b, *n, d);
    compare_inputs(b->record.case_info, n->record.case_info, d);
  }
  return d;
}

std::string point_text(const report::SweepRow& row) {
  std::string s;
  for (const auto& [k, v] : row.parameters)
    s += (s.empty() ? "" : ", ") + k + " = " + v.value_or("null");
  return s;
}

// the unit of figure `f` in table `t` ("" when it has none)
std::string unit_in(const report::SweepTable& t, const std::string& f) {
  const auto it = t.units.find(f);
  return it == t.units.end() ? std::string() : it->second;
}

// figure `f` of `row` (NaN when the row has no number for it); none when the row has no
// such column or is none
std::optional<double> figure_in(const report::SweepRow* row, const std::string& f) {
  if (!row || !row->key_figures.count(f)) return std::nullopt;
  return row->key_figures.at(f).value_or(NAN);
}

// the key figures of one case's rows in the two tables (x: base, y: new; both there) into
// `row`: how many changed and the one that changed most (its relative change is the score)
void compare_row_figures(const report::SweepTable& tb, const report::SweepTable& tn,
                         const report::SweepRow& x, const report::SweepRow& y,
                         const std::set<std::string>& ignored, report::SweepRowDiff* row) {
  std::set<std::string> figs;
  for (const auto* r : {&x, &y})
    for (const auto& [k, v] : r->key_figures) figs.insert(k);
  double best = -1;
  for (const auto& f : figs) {
    if (ignored.count(f)) continue;
    const std::optional<double> a = figure_in(&x, f), b = figure_in(&y, f);
    if (a && b && same_number(*a, *b)) continue;
    ++row->figures_changed;
    double rel = INFINITY;
    if (a && b && std::isfinite(*a) && std::isfinite(*b) && *a != 0)
      rel = std::abs(*b - *a) / std::abs(*a);
    if (rel > best) {
      best = rel;
      row->figure = f;
      row->unit = unit_in(b ? tn : tb, f);
      row->base = a;
      row->now = b;
    }
  }
  if (best >= 0) row->score = std::max(row->score, best);
}

// the sweep tables (cli::sweep_table of each run) row by row by case id
void diff_sweeps(const std::vector<CaseOutput>& base, const std::vector<CaseOutput>& now,
                 report::RunDiff* out) {
  const report::SweepTable tb = sweep_table(base), tn = sweep_table(now);
  out->sweep_rows_base = tb.rows.size();
  out->sweep_rows_new = tn.rows.size();
  if (tb.rows.empty() && tn.rows.empty()) return;
  for (const auto* run : {&now, &base})
    for (const auto& c : *run)
      if (out->sweep_name.empty() && c.record.case_info.sweep)
        out->sweep_name = c.record.case_info.sweep->name;
  std::map<std::string, const report::SweepRow*> rb, rn;
  for (const auto& r : tb.rows) rb[r.case_name] = &r;
  for (const auto& r : tn.rows) rn[r.case_name] = &r;
  std::set<std::string> names;
  for (const auto& [k, v] : rb) names.insert(k);
  for (const auto& [k, v] : rn) names.insert(k);
  std::map<std::string, const CaseDiff*> cases;
  for (const auto& c : out->cases) cases[c.name] = &c;
  for (const auto& name : names) {
    const report::SweepRow* x = rb.count(name) ? rb[name] : nullptr;
    const report::SweepRow* y = rn.count(name) ? rn[name] : nullptr;
    report::SweepRowDiff row;
    row.case_name = name;
    row.point = point_text(y ? *y : *x);
    row.base_status = x ? x->status : "";
    row.new_status = y ? y->status : "";
    row.beyond = cases.count(name) && cases[name]->beyond();
    if (!x || !y || row.base_status != row.new_status) row.score = INFINITY;
    // figures the tolerances ignore (wall-clock run times) rank nothing
    std::set<std::string> ignored;
    if (cases.count(name))
      for (const auto& f : cases[name]->figures)
        if (f.tolerance.ignore) ignored.insert(f.name);
    // a row of one run only ranks as infinite, with no figure
    if (x && y) compare_row_figures(tb, tn, *x, *y, ignored, &row);
    if (row.figures_changed == 0 && row.score == 0 && row.base_status == row.new_status) continue;
    out->sweep.push_back(std::move(row));
  }
  std::stable_sort(out->sweep.begin(), out->sweep.end(), [](const auto& a, const auto& b) {
    if (a.beyond != b.beyond) return a.beyond;
    return a.score > b.score;
  });
}

}  // namespace

std::vector<CaseOutput> read_run(const fs::path& dir) {
  if (!fs::exists(dir))
    throw DiffInputError(
        dir.string() + ": no such folder; expected an output folder of 'armstudy run' or 'merge'");
  if (!fs::is_directory(dir))
    throw DiffInputError(dir.string() +
                         ": not a folder; expected an output folder of 'armstudy run' or 'merge'");
  std::vector<std::string> problems;
  std::vector<CaseOutput> out;
  try {
    out = collect_outputs({dir}, &problems);
  } catch (const InputLimitError& e) {
    throw DiffInputError(report::terminal_text(e.what()));
  } catch (const cases::InputFileError& e) {
    if (e.runtime()) throw;
    throw DiffInputError(report::terminal_text(e.what()));
  }
  // collect_outputs read every shared key of each file strictly (a misspelt, missing or
  // mistyped one is a problem named there), so the records below are whole
  if (!problems.empty()) {
    std::string msg;
    for (const auto& p : problems) {
      if (!msg.empty()) msg += '\n';
      msg += report::terminal_text(p);
    }
    throw DiffInputError(msg);
  }
  if (out.empty())
    throw DiffInputError(dir.string() +
                         ": no case folder with a results.json; expected an output folder of "
                         "'armstudy run' or 'merge'");
  return out;
}

report::RunDiff diff_runs(const std::vector<CaseOutput>& base, const std::vector<CaseOutput>& now,
                          const DiffTolerances& tolerances, const FrameOptions& frames) {
  report::RunDiff d;
  d.tolerances_file = tolerances.file;
  d.pixel_tolerance = frames.channel_tolerance;
  d.pixels_allowed = frames.pixels_allowed;
  d.base_cases = base.size();
  d.new_cases = now.size();
  std::map<std::string, const CaseOutput*> b, n;
  for (const auto& c : base) b[c.record.case_info.name] = &c;
  for (const auto& c : now) n[c.record.case_info.name] = &c;
  std::set<std::string> names;
  for (const auto& [k, v] : b) names.insert(k);
  for (const auto& [k, v] : n) names.insert(k);
  for (const auto& name : names)
    d.cases.push_back(compare_case(b.count(name) ? b[name] : nullptr,
                                   n.count(name) ? n[name] : nullptr, tolerances, frames));
  // the runs' provenance as a whole: each item's distinct values over all cases
  std::map<std::string, std::set<std::string>> pb, pn;
  for (const auto& c : base)
    for (const auto& [k, v] : provenance_of(c.record)) pb[k].insert(v);
  for (const auto& c : now)
    for (const auto& [k, v] : provenance_of(c.record)) pn[k].insert(v);
  std::set<std::string> keys;
  for (const auto& [k, v] : pb) keys.insert(k);
  for (const auto& [k, v] : pn) keys.insert(k);
  auto join = [](const std::set<std::string>& s) {
    std::string o;
    for (const auto& v : s) o += (o.empty() ? "" : "; ") + v;
    return o.empty() ? std::string("(none)") : o;
  };
  for (const auto& k : provenance_keys(keys)) {
    const std::set<std::string> x = pb.count(k) ? pb[k] : std::set<std::string>{};
    const std::set<std::string> y = pn.count(k) ? pn[k] : std::set<std::string>{};
    if (x != y) d.provenance.push_back({k, label_of(k), join(x), join(y)});
  }
  diff_sweeps(base, now, &d);
  return d;
}

// (over 60 lines, kept whole: the steps of a diff in order: read both runs, compare, write, exit
// code)
int run_diff(const DiffOptions& o) {
  constexpr int kSame = 0, kMoved = 1, kBadInput = 2, kRuntime = 3;
  std::vector<CaseOutput> base, now;
  DiffTolerances tol;
  try {
    base = read_run(o.base);
    now = read_run(o.now);
    if (!o.tolerances_file.empty()) tol = load_diff_tolerances(o.tolerances_file);
  } catch (const DiffInputError& e) {
    std::fprintf(stderr, "%s\nnothing was written\n", e.what());
    return kBadInput;
  } catch (const cases::CaseErrors& e) {
    std::fprintf(stderr, "%s\nnothing was written\n", e.what());
    return kBadInput;
  } catch (const cases::InputFileError& e) {  // out of file descriptors, an I/O error
    std::fprintf(stderr, "armstudy diff: %s\nnothing was written\n", e.what());
    return kRuntime;
  }
  // never over a diff.md, diff.html, report.css or diff-frames/ armstudy did not write
  if (const auto foreign = report::foreign_outputs(o.out, {}, report::kDiffOutputs);
      !foreign.empty()) {
    for (const std::string& f : foreign)
      std::fprintf(stderr, "armstudy diff: %s\n", report::terminal_text(f).c_str());
    std::fprintf(stderr,
                 "nothing was written: armstudy replaces only what it wrote; move these away or "
                 "choose another --out\n");
    return kBadInput;
  }
  FrameOptions fo;
  fo.channel_tolerance = o.pixel_tolerance.value_or(tol.pixel_channel.value_or(0));
  fo.pixels_allowed = o.pixels_allowed.value_or(tol.pixels.value_or(0));
  report::RunDiff d;
  try {
    // frame copies go to a hidden sibling first; the old diff's frames go only once the new
    // ones are complete
    fs::create_directories(o.out);
    const fs::path tmp = o.out / (".diff.tmp-" + app::process_tag());
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    fo.frames_root = tmp;
    d = diff_runs(base, now, tol, fo);
    d.base_dir = o.base;
    d.new_dir = o.now;
    fs::remove_all(o.out / "diff-frames");
    if (fs::exists(tmp / "diff-frames")) fs::rename(tmp / "diff-frames", o.out / "diff-frames");
    fs::remove_all(tmp);
    app::write_file_atomic(o.out / "diff.md", report::diff_markdown(d));
    report::write_diff_page(o.out, d);
  } catch (const cases::InputFileError& e) {  // a frame that is a FIFO, a device, a link
    std::error_code ec;
    fs::remove_all(o.out / (".diff.tmp-" + app::process_tag()), ec);
    std::fprintf(stderr, "armstudy diff: %s\nnothing was written\n", e.what());
    return e.runtime() ? kRuntime : kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy diff: cannot write the diff into %s: %s\n", o.out.c_str(),
                 e.what());
    return kRuntime;
  }
  const size_t moved = d.beyond_count();
  std::string names;
  size_t listed = 0;
  for (const auto& c : d.cases)
    if (c.beyond() && listed++ < 10) names += "\n  " + c.name;
  if (listed > 10) names += "\n  ... and " + std::to_string(listed - 10) + " more";
  std::fprintf(stderr, "%zu case(s) in %s, %zu in %s: %s%s\ndiff: %s, %s\n", base.size(),
               o.base.c_str(), now.size(), o.now.c_str(),
               moved ? (std::to_string(moved) + " moved beyond tolerance:").c_str()
                     : "nothing moved beyond tolerance",
               names.c_str(), (o.out / "diff.html").c_str(), (o.out / "diff.md").c_str());
  return moved ? kMoved : kSame;
}

}  // namespace armstudy::cli
