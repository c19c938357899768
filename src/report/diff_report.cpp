// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/diff_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cases/case_info.hpp"
#include "report/case_report.hpp"
#include "report/markdown.hpp"
#include "report/number_format.hpp"
#include "report/page.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;

double FigureDiff::abs_change() const {
  if (!base || !now) return NAN;
  return *now - *base;
}

double FigureDiff::rel_change() const {
  if (!base || !now) return NAN;
  const double d = *now - *base;
  if (d == 0) return 0;
  if (*base == 0) return d > 0 ? INFINITY : -INFINITY;
  // 1e308 to -1e308: the difference overflows, the ratio does not (-2, not "from 0")
  if (!std::isfinite(d)) return *now / std::abs(*base) - (*base > 0 ? 1 : -1);
  return d / std::abs(*base);
}

bool CaseDiff::beyond() const {
  if (presence != Presence::kBoth || status_changed()) return true;
  for (const auto& f : figures)
    if (f.beyond) return true;
  for (const auto& c : checks) {
    if (c.base_passed && c.new_passed && *c.base_passed != *c.new_passed) return true;
    if (!c.base_passed && c.new_passed && !*c.new_passed) return true;  // a new check that fails
  }
  for (const auto& f : frames)
    if (f.beyond) return true;
  return false;
}

bool CaseDiff::changed() const {
  if (beyond() || !checks.empty() || !inputs.empty() || base_message != new_message) return true;
  for (const auto& f : figures)
    if (!(f.base == f.now || (f.base && f.now && std::isnan(*f.base) && std::isnan(*f.now))))
      return true;
  for (const auto& f : frames)
    if (!f.identical) return true;
  return false;
}

size_t RunDiff::beyond_count() const {
  return static_cast<size_t>(
      std::count_if(cases.begin(), cases.end(), [](const CaseDiff& c) { return c.beyond(); }));
}

namespace {

std::string num(const std::optional<double>& v) { return v ? format_sig(*v, 6) : "(none)"; }

std::string signed_num(double v) {
  if (std::isnan(v)) return "n/a";
  return (v > 0 ? "+" : "") + format_sig(v, 4);
}

std::string percent_change(double rel) {
  if (std::isnan(rel)) return "n/a";
  if (std::isinf(rel)) return "from 0";
  return (rel > 0 ? "+" : "") + format_sig(100 * rel, 3) + " %";
}

std::string with_unit(const std::string& v, const std::string& unit) {
  return unit.empty() || v == "(none)" ? v : v + " " + unit;
}

std::string tolerance_text(const FigureTolerance& t, const std::string& unit) {
  if (t.ignore) return "ignored";
  if (t.abs == 0 && t.rel == 0) return "exact";
  std::string s;
  if (t.abs > 0) s = with_unit(format_sig(t.abs, 3), unit);
  if (t.rel > 0) s += (s.empty() ? "" : " or ") + format_sig(100 * t.rel, 3) + " %";
  return s;
}

std::string verdict(const FigureDiff& f) {
  if (f.beyond) return "BEYOND";
  if (f.tolerance.ignore) return "ignored";
  const bool same =
      f.base == f.now || (f.base && f.now && std::isnan(*f.base) && std::isnan(*f.now));
  return same ? "same" : "within";
}

std::string status_text(const std::string& status, bool passed) {
  if (status.empty()) return "(absent)";
  return status + (passed ? "" : " (FAILED)");
}

std::string check_side(const std::optional<bool>& passed, const std::optional<double>& value,
                       const std::optional<double>& tol) {
  if (!passed) return "(no such check)";
  return std::string(*passed ? "passed" : "FAILED") + " (" + num(value) + " against " + num(tol) +
         ")";
}

std::string frame_result(const FrameDiff& f, int pixel_tolerance) {
  if (!f.error.empty()) return "unreadable: " + f.error;
  if (!f.in_base) return "only in the new run";
  if (!f.in_new) return "only in the base run";
  if (f.identical) return "byte-identical";
  if (f.size_differs) return "sizes differ";
  return std::to_string(f.pixels_beyond) + " px beyond ±" + std::to_string(pixel_tolerance) +
         " (largest channel difference " + std::to_string(f.max_channel_delta) + ")";
}

// one line: what moved in a case (for the tables of cases)
std::string what_moved(const CaseDiff& c, int pixel_tolerance, bool beyond_only) {
  if (c.presence == CaseDiff::Presence::kAdded)
    return "added (only in the new run): " + status_text(c.new_status, c.new_passed);
  if (c.presence == CaseDiff::Presence::kRemoved)
    return "removed (only in the base run): " + status_text(c.base_status, c.base_passed);
  std::vector<std::string> parts;
  if (c.status_changed())
    parts.push_back("status " + status_text(c.base_status, c.base_passed) + " → " +
                    status_text(c.new_status, c.new_passed));
  size_t figs = 0;
  for (const auto& f : c.figures) {
    const std::string v = verdict(f);
    if (v == "same" || v == "ignored" || (beyond_only && v != "BEYOND")) continue;
    if (++figs > 4) continue;
    parts.push_back(f.name + " " + with_unit(num(f.base), f.unit) + " → " +
                    with_unit(num(f.now), f.unit) + " (" + percent_change(f.rel_change()) + ")");
  }
  if (figs > 4) parts.push_back("and " + std::to_string(figs - 4) + " more key figure(s)");
  for (const auto& ch : c.checks)
    parts.push_back("check " + ch.name + " " +
                    (ch.base_passed ? (*ch.base_passed ? "passed" : "FAILED") : "(none)") + " → " +
                    (ch.new_passed ? (*ch.new_passed ? "passed" : "FAILED") : "(none)"));
  size_t frames = 0;
  for (const auto& f : c.frames)
    if (f.beyond || (!beyond_only && !f.identical)) {
      if (++frames <= 3)
        parts.push_back("frame " + f.file + ": " + frame_result(f, pixel_tolerance));
    }
  if (frames > 3) parts.push_back("and " + std::to_string(frames - 3) + " more frame(s)");
  if (parts.empty() && c.base_message != c.new_message) parts.push_back("message changed");
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : "; ") + p;
  return s;
}

std::string renderer_note(const CaseDiff& c) {
  std::string base, now;
  for (const auto& p : c.provenance)
    if (p.key == "gl_renderer" || p.key == "mesa_version") {
      base += (base.empty() ? "" : ", ") + p.base;
      now += (now.empty() ? "" : ", ") + p.now;
    }
  if (base.empty()) return "";
  return "The runs rendered with different renderers (base: " + base + "; new: " + now +
         "): frames may differ because of the machine, not the change.";
}

std::string tolerances_sentence(const RunDiff& d) {
  std::string s = d.tolerances_file.empty()
                      ? "Built-in tolerances (key figures exact, wall-clock run times ignored)"
                      : "Tolerances from " + d.tolerances_file;
  s += "; frames: a pixel counts when a channel differs by more than " +
       std::to_string(d.pixel_tolerance) + " (of 255), a frame moves when more than " +
       std::to_string(d.pixels_allowed) + " pixel(s) do";
  return s;
}

std::string headline(const RunDiff& d) {
  const size_t n = d.beyond_count();
  return n == 0 ? "nothing moved beyond tolerance"
                : std::to_string(n) + " case(s) moved beyond tolerance";
}

size_t count_presence(const RunDiff& d, CaseDiff::Presence p) {
  return static_cast<size_t>(std::count_if(d.cases.begin(), d.cases.end(),
                                           [&](const CaseDiff& c) { return c.presence == p; }));
}

// the figure table of a case: the figures that changed (all of them with `all`)
Table figure_table(const CaseDiff& c, bool all) {
  Table t;
  t.header = {"key figure", "base", "new", "change", "relative", "tolerance", "verdict"};
  for (const auto& f : c.figures) {
    const std::string v = verdict(f);
    if (!all && v == "same") continue;
    t.rows.push_back({f.name, with_unit(num(f.base), f.unit), with_unit(num(f.now), f.unit),
                      with_unit(signed_num(f.abs_change()), f.unit), percent_change(f.rel_change()),
                      tolerance_text(f.tolerance, f.unit), v});
  }
  return t;
}

Table check_table(const CaseDiff& c) {
  Table t;
  t.caption = "Checks whose verdict changed (value against the check's tolerance)";
  t.header = {"check", "base", "new"};
  for (const auto& ch : c.checks)
    t.rows.push_back({ch.name, check_side(ch.base_passed, ch.base_value, ch.base_tolerance),
                      check_side(ch.new_passed, ch.new_value, ch.new_tolerance)});
  return t;
}

Table frame_table(const CaseDiff& c, int pixel_tolerance) {
  Table t;
  t.caption = "Frames";
  t.header = {"frame", "result", "verdict"};
  for (const auto& f : c.frames)
    t.rows.push_back({f.file, frame_result(f, pixel_tolerance),
                      f.beyond ? "BEYOND" : (f.identical ? "same" : "within")});
  return t;
}

Table provenance_table(const std::vector<ProvenanceDiff>& p) {
  Table t;
  t.header = {"item", "base", "new"};
  for (const auto& x : p) t.rows.push_back({x.label, x.base, x.now});
  return t;
}

std::string truncate(std::string s, size_t max_bytes) {
  if (s.size() <= max_bytes) return s;
  const std::string note = "\n\n*Truncated: the full diff is larger than " +
                           std::to_string(max_bytes) + " bytes; see diff.html.*\n";
  s.resize(max_bytes - note.size());
  s.resize(s.rfind('\n') + 1);
  return s + note;
}

void md_table(std::ostringstream& md, const Table& t) {
  if (t.rows.empty()) return;
  md << "|";
  for (const auto& h : t.header) md << " " << md_cell(h) << " |";
  md << "\n|";
  for (size_t k = 0; k < t.header.size(); ++k) md << (k == 0 ? "---|" : "---|");
  md << "\n";
  for (const auto& r : t.rows) {
    md << "|";
    for (const auto& c : r) md << " " << md_cell(c == "BEYOND" ? "**BEYOND**" : c) << " |";
    md << "\n";
  }
  md << "\n";
}

Table sweep_table(const RunDiff& d, size_t limit) {
  Table t;
  t.header = {"case", "point",    "status",          "largest change", "base",
              "new",  "relative", "figures changed", "verdict"};
  for (size_t k = 0; k < d.sweep.size() && k < limit; ++k) {
    const auto& r = d.sweep[k];
    const std::string status = r.base_status == r.new_status
                                   ? r.new_status
                                   : (r.base_status.empty() ? "(absent)" : r.base_status) + " → " +
                                         (r.new_status.empty() ? "(absent)" : r.new_status);
    FigureDiff f;
    f.base = r.base;
    f.now = r.now;
    t.rows.push_back({r.case_name, r.point, status, r.figure, with_unit(num(r.base), r.unit),
                      with_unit(num(r.now), r.unit),
                      r.figure.empty() ? "" : percent_change(f.rel_change()),
                      std::to_string(r.figures_changed), r.beyond ? "BEYOND" : "within"});
  }
  return t;
}

// the cases beyond tolerance, failures of the new run first, then by name
std::vector<const CaseDiff*> moved_cases(const RunDiff& d) {
  std::vector<const CaseDiff*> out;
  for (const auto& c : d.cases)
    if (c.beyond()) out.push_back(&c);
  auto fails = [](const CaseDiff* c) {
    return c->presence != CaseDiff::Presence::kRemoved && !c->new_passed;
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const CaseDiff* a, const CaseDiff* b) { return fails(a) && !fails(b); });
  return out;
}

}  // namespace

namespace {
// the inputs that differ between the runs, per case, before what moved (from each
// results.json's case.inputs); the cases whose runs do not both record them are named
void md_inputs(std::ostringstream& md, const RunDiff& d) {
  Table t;
  t.header = {"case", "input", "base", "new"};
  std::string unknown;
  for (const auto& c : d.cases) {
    if (c.presence != CaseDiff::Presence::kBoth) continue;
    if (!c.inputs_known) unknown += (unknown.empty() ? "" : ", ") + c.name;
    for (const auto& i : c.inputs) t.rows.push_back({c.name, i.key, i.base, i.now});
  }
  if (t.rows.empty() && unknown.empty()) {
    md << "## Inputs\n\nEvery case of both runs has the same inputs.\n\n";
    return;
  }
  md << "## Inputs that differ\n\n";
  if (!t.rows.empty())
    md_table(md, t);
  else
    md << "No recorded input differs.\n\n";
  if (!unknown.empty())
    md << "Not recorded in both runs (a results.json of an older armstudy): " << md_cell(unknown)
       << ".\n\n";
}
}  // namespace

std::string diff_markdown(const RunDiff& d, size_t max_bytes) {
  std::ostringstream md;
  const size_t moved = d.beyond_count();
  md << "# armstudy diff: " << headline(d) << "\n\n";
  md << "Base `" << d.base_dir.string() << "` (" << d.base_cases << " case(s)) against new `"
     << d.new_dir.string() << "` (" << d.new_cases
     << " case(s)): " << count_presence(d, CaseDiff::Presence::kAdded) << " added, "
     << count_presence(d, CaseDiff::Presence::kRemoved) << " removed. " << tolerances_sentence(d)
     << ".\n\n";
  md_inputs(md, d);
  if (moved) {
    md << "## Beyond tolerance (" << moved << ")\n\n| case | study | what moved |\n|---|---|---|\n";
    for (const CaseDiff* c : moved_cases(d))
      md << "| " << md_cell(c->name) << " | " << md_cell(c->study) << " | "
         << md_cell(what_moved(*c, d.pixel_tolerance, true)) << " |\n";
    md << "\n";
    for (const CaseDiff* cp : moved_cases(d)) {
      const CaseDiff& c = *cp;
      if (c.presence != CaseDiff::Presence::kBoth) continue;
      md << "### " << md_cell(c.name) << " (" << md_cell(c.study) << ")\n\n";
      if (c.status_changed())
        md << "Status " << status_text(c.base_status, c.base_passed) << " → "
           << status_text(c.new_status, c.new_passed) << ": " << md_cell(c.new_message) << "\n\n";
      md_table(md, figure_table(c, false));
      md_table(md, check_table(c));
      Table ft = frame_table(c, d.pixel_tolerance);
      ft.rows.erase(std::remove_if(ft.rows.begin(), ft.rows.end(),
                                   [](const auto& r) { return r[2] == "same"; }),
                    ft.rows.end());
      md_table(md, ft);
      if (const std::string note = renderer_note(c); !note.empty()) md << note << "\n\n";
    }
  }
  if (!d.sweep_name.empty()) {
    md << "## Sweep " << md_cell(d.sweep_name) << ": " << d.sweep.size() << " of "
       << std::max(d.sweep_rows_base, d.sweep_rows_new)
       << " row(s) changed, largest change first\n\n";
    md_table(md, sweep_table(d, 50));
    if (d.sweep.size() > 50) md << "*" << d.sweep.size() - 50 << " more row(s) in diff.html.*\n\n";
  }
  size_t within = 0;
  for (const auto& c : d.cases) within += !c.beyond() && c.changed();
  if (within) {
    md << "## Changed within tolerance (" << within
       << ")\n\n| case | study | what changed |\n|---|---|---|\n";
    for (const auto& c : d.cases)
      if (!c.beyond() && c.changed())
        md << "| " << md_cell(c.name) << " | " << md_cell(c.study) << " | "
           << md_cell(what_moved(c, d.pixel_tolerance, false)) << " |\n";
    md << "\n";
  }
  const size_t same = static_cast<size_t>(std::count_if(
      d.cases.begin(), d.cases.end(), [](const CaseDiff& c) { return !c.changed(); }));
  md << "## Unchanged\n\n"
     << same << " case(s) have the same status, key figures, checks and frames.\n\n";
  if (!d.provenance.empty()) {
    md << "## Provenance\n\n";
    md_table(md, provenance_table(d.provenance));
  }
  return truncate(md.str(), max_bytes);
}

namespace {

// what moved: the rule, the tolerances and the cases beyond them
Section moved_section(const RunDiff& d) {
  Section about;
  about.id = "summary";
  about.heading = "What moved";
  about.new_page = false;
  about.paragraph(
      "Cases are matched by name. A key figure moves when |new − base| exceeds max(abs, rel · "
      "|base|) of its "
      "tolerance; a status change, a check whose verdict changed, an added or removed case and a "
      "frame "
      "beyond its pixel tolerance move too. " +
      tolerances_sentence(d) + ".");
  Table moved_t;
  moved_t.caption = "Cases that moved beyond tolerance";
  moved_t.header = {"case", "study", "what moved"};
  for (const CaseDiff* c : moved_cases(d))
    moved_t.rows.push_back({c->name, c->study, what_moved(*c, d.pixel_tolerance, true)});
  if (moved_t.rows.empty())
    about.paragraph("Nothing moved beyond its tolerance.");
  else
    about.table(std::move(moved_t));
  return about;
}

// a frame's base, new and difference images side by side, for each frame that has them
void add_frame_strips(const CaseDiff& c, int pixel_tolerance, Section& s) {
  for (const auto& f : c.frames) {
    if (f.diff_image.empty() && f.base_copy.empty()) continue;
    Strip st;
    st.caption = f.file + ": " + frame_result(f, pixel_tolerance) +
                 (f.diff_image.empty()
                      ? ""
                      : "; in the difference image the pixels beyond are red and boxed in magenta, "
                        "the rest is the base in grey");
    const bool wide = f.file.find("_strip") != std::string::npos;
    for (const auto& [file, label] : std::vector<std::pair<std::string, std::string>>{
             {f.base_copy, "base"}, {f.new_copy, "new"}, {f.diff_image, "difference"}}) {
      if (file.empty()) continue;
      st.files.push_back(file);
      st.labels.push_back(label + ": " + f.file);
      st.wide.push_back(wide);
    }
    s.strip(std::move(st));
  }
}

// a case that moved (present in both runs): figures, checks, frames, provenance
Section moved_case_section(const RunDiff& d, const CaseDiff& c) {
  Section s;
  s.id = "case-" + std::to_string(&c - d.cases.data());
  s.heading = c.name + " (" + c.study + ")";
  s.new_page = false;
  if (c.status_changed())
    s.paragraph("Status " + status_text(c.base_status, c.base_passed) + " → " +
                status_text(c.new_status, c.new_passed) + ". Base: " + c.base_message +
                " New: " + c.new_message);
  Table ft = figure_table(c, true);
  ft.caption = "Every key figure, side by side";
  if (!ft.rows.empty()) s.table(std::move(ft));
  if (!c.checks.empty()) s.table(check_table(c));
  if (!c.frames.empty()) s.table(frame_table(c, d.pixel_tolerance));
  if (const std::string note = renderer_note(c); !note.empty()) s.note(note);
  add_frame_strips(c, d.pixel_tolerance, s);
  if (!c.provenance.empty()) {
    Table pt = provenance_table(c.provenance);
    pt.caption = "Provenance that differs";
    s.table(std::move(pt));
  }
  return s;
}

// the sweep table's rows by case id
Section sweep_section(const RunDiff& d) {
  Section s;
  s.id = "sweep";
  s.heading = "Sweep " + d.sweep_name + ": rows by case id";
  s.new_page = false;
  s.paragraph(std::to_string(d.sweep.size()) + " of " +
              std::to_string(std::max(d.sweep_rows_base, d.sweep_rows_new)) +
              " row(s) of the sweep table changed; those beyond tolerance first, then by the "
              "largest relative "
              "change of a key figure (added, removed and status changes count as infinite).");
  Table t = sweep_table(d, d.sweep.size());
  if (!t.rows.empty()) s.table(std::move(t));
  return s;
}

// the cases that changed within their tolerances
Section within_section(const RunDiff& d) {
  Section s;
  s.id = "within";
  s.heading = "Changed within tolerance";
  s.new_page = false;
  Table t;
  t.header = {"case", "study", "what changed"};
  for (const auto& c : d.cases)
    if (!c.beyond() && c.changed())
      t.rows.push_back({c.name, c.study, what_moved(c, d.pixel_tolerance, false)});
  s.table(std::move(t));
  return s;
}

// the cases that did not change
Section unchanged_section(const RunDiff& d, size_t same) {
  Section un;
  un.id = "unchanged";
  un.heading = "Unchanged cases";
  un.new_page = false;
  std::string names;
  for (const auto& c : d.cases)
    if (!c.changed()) names += (names.empty() ? "" : ", ") + c.name;
  un.paragraph(same == 0 ? "Every case changed."
                         : std::to_string(same) +
                               " case(s) have the same status, key figures, checks and frames: " +
                               names + ".");
  return un;
}

// the provenance that differs between the runs
Section provenance_section(const RunDiff& d) {
  Section prov;
  prov.id = "provenance";
  prov.heading = "Provenance";
  prov.new_page = false;
  if (d.provenance.empty()) {
    prov.paragraph(
        "Both runs have the same provenance (armstudy version and commit, MuJoCo, renderer, "
        "compiler, CPU).");
  } else {
    prov.paragraph(
        "Provenance items that differ between the runs (each item's distinct values over all "
        "cases). A "
        "different GL renderer or Mesa version explains frame differences; a different CPU can "
        "explain "
        "last-digit differences of the numbers.");
    prov.table(provenance_table(d.provenance));
  }
  return prov;
}

}  // namespace

void write_diff_page(const fs::path& dir, const RunDiff& d) {
  CasePage page;
  page.title = "armstudy diff";
  page.study = "diff";
  const size_t moved = d.beyond_count();
  page.status = headline(d);
  page.status_ok = moved == 0;
  page.message = "Base " + d.base_dir.string() + " against new " + d.new_dir.string() + ".";
  const size_t added = count_presence(d, CaseDiff::Presence::kAdded),
               removed = count_presence(d, CaseDiff::Presence::kRemoved);
  size_t within = 0, same = 0;
  for (const auto& c : d.cases) {
    within += !c.beyond() && c.changed();
    same += !c.changed();
  }
  page.key_figures = {{"base cases", std::to_string(d.base_cases)},
                      {"new cases", std::to_string(d.new_cases)},
                      {"beyond tolerance", std::to_string(moved)},
                      {"within tolerance", std::to_string(within)},
                      {"unchanged", std::to_string(same)},
                      {"added / removed", std::to_string(added) + " / " + std::to_string(removed)}};
  page.links = {{"diff.md (job summary)", "diff.md"}};

  page.sections.push_back(moved_section(d));
  // each case that moved (present in both runs): figures, checks, frames, provenance
  for (const CaseDiff* cp : moved_cases(d))
    if (cp->presence == CaseDiff::Presence::kBoth)
      page.sections.push_back(moved_case_section(d, *cp));
  if (!d.sweep_name.empty()) page.sections.push_back(sweep_section(d));
  if (within) page.sections.push_back(within_section(d));
  page.sections.push_back(unchanged_section(d, same));
  page.sections.push_back(provenance_section(d));

  cases::CaseInfo info;
  info.name = "diff";
  info.study = "diff";
  write_page(dir, page, info, "diff.md", "diff.html");
}

}  // namespace armstudy::report
