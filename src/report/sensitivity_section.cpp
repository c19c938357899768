// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/sensitivity_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "report/number_format.hpp"
#include "report/text_escape.hpp"
#include "sys/atomic_file.hpp"

namespace armstudy::report {
namespace {

double influence(const SensitivityKeyRecord& k) {
  double m = -1;
  for (const SensitivityStepRecord* st : {&k.minus, &k.plus})
    if (st->change) m = std::max(m, std::abs(*st->change));
  return m;
}

// "-10 %" or "-0.25" for one side of a key
std::string step_words(const SensitivityKeyRecord& k, int sign) {
  return std::string(sign < 0 ? "-" : "+") +
         (k.step_kind == "relative" ? format_sig(100 * k.step, 3) + " %" : format_sig(k.step, 3));
}

std::string values_words(const std::vector<double>& v) {
  if (v.size() == 1) return format_sig(v[0], 6);
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + format_sig(v[i], 4);
  return s + "]";
}

std::string list_words(const std::vector<std::string>& v) {
  if (v.empty()) return "none";
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : ", ") + e;
  return s;
}

std::string svg_text(const std::string& s) { return xml_text(s); }

}  // namespace

std::vector<const SensitivityKeyRecord*> by_influence(const SensitivityRecord& s) {
  std::vector<const SensitivityKeyRecord*> out;
  for (const auto& k : s.keys) out.push_back(&k);
  std::stable_sort(out.begin(), out.end(),
                   [](const auto* a, const auto* b) { return influence(*a) > influence(*b); });
  return out;
}

// (over 60 lines, kept whole: one SVG written top to bottom, bar by bar)
std::string write_tornado(const std::filesystem::path& dir, const SensitivityRecord& s,
                          std::string* caption) {
  const auto keys = by_influence(s);
  double span = 0;
  for (const auto* k : keys) span = std::max(span, influence(*k));
  if (keys.empty() || !(span > 0) || !std::isfinite(span)) return "";
  // a bar per step from the nominal value (the centre line): the step below the key's
  // value in blue, above in orange; drawn for the answer box's narrow column
  const int row = 19, top = 32, label_w = 150, plot_w = 150, right = 62;
  const int width = label_w + plot_w + right, height = top + row * int(keys.size()) + 4;
  const double cx = label_w + plot_w / 2.0, scale = (plot_w / 2.0 - 3) / span;
  const char* minus_colour = "#0072b2";
  const char* plus_colour = "#e69f00";
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << " " << height
    << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"11\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  o << "<rect x=\"2\" y=\"4\" width=\"9\" height=\"9\" fill=\"" << minus_colour
    << "\"/><text x=\"14\" y=\"12\" font-size=\"10\">key - step</text>\n";
  o << "<rect x=\"80\" y=\"4\" width=\"9\" height=\"9\" fill=\"" << plus_colour
    << "\"/><text x=\"92\" y=\"12\" font-size=\"10\">key + step</text>\n";
  o << "<text x=\"" << cx << "\" y=\"12\" font-size=\"10\" text-anchor=\"middle\">change"
    << svg_text(s.unit.empty() ? "" : ", " + s.unit) << "</text>\n";
  o << "<text x=\"" << label_w + plot_w + 4 << "\" y=\"12\" font-size=\"10\">elasticity</text>\n";
  // the scale: the largest change at either end
  o << "<text x=\"" << label_w + 2 << "\" y=\"27\" font-size=\"9\" fill=\"#555\">-"
    << svg_text(format_sig(span, 2)) << "</text><text x=\"" << label_w + plot_w - 2
    << "\" y=\"27\" font-size=\"9\" fill=\"#555\" text-anchor=\"end\">+"
    << svg_text(format_sig(span, 2)) << "</text>\n";
  int y = top;
  for (const auto* k : keys) {
    const size_t dot = k->key.rfind('.');
    const std::string name = dot == std::string::npos ? k->key : k->key.substr(dot + 1);
    o << "<text x=\"" << label_w - 4 << "\" y=\"" << y + 10 << "\" text-anchor=\"end\">"
      << svg_text(name) << "</text>\n";
    o << "<text x=\"" << label_w - 4 << "\" y=\"" << y + 19
      << "\" text-anchor=\"end\" font-size=\"8\" fill=\"#555\">"
      << svg_text(values_words(k->nominal) + " ±" + step_words(*k, +1).substr(1)) << "</text>\n";
    int sign = -1;
    for (const SensitivityStepRecord* st : {&k->minus, &k->plus}) {
      const int by = y + (sign < 0 ? 2 : 10);
      if (st->change) {
        const double w = *st->change * scale;
        const double x0 = w < 0 ? cx + w : cx;
        char b[200];
        std::snprintf(b, sizeof b,
                      "<rect x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"7\" fill=\"%s\"/>\n", x0,
                      by, std::max(std::abs(w), 0.8), sign < 0 ? minus_colour : plus_colour);
        o << b;
      } else {
        o << "<text x=\"" << label_w + 2 << "\" y=\"" << by + 7
          << "\" font-size=\"8\" fill=\"#b00\">" << (sign < 0 ? "-" : "+") << "step: no answer ("
          << svg_text(st->status) << ")</text>\n";
      }
      sign = +1;
    }
    o << "<text x=\"" << label_w + plot_w + 4 << "\" y=\"" << y + 13 << "\" font-size=\"10\">"
      << svg_text(k->elasticity ? format_sig(*k->elasticity, 2) : std::string("-")) << "</text>\n";
    y += row;
  }
  o << "<line x1=\"" << cx << "\" y1=\"" << top - 3 << "\" x2=\"" << cx << "\" y2=\"" << y
    << "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
  o << "</svg>\n";
  const std::string file = "sensitivity_tornado.svg";
  sys::write_file_atomic(dir / file, o.str());
  if (caption)
    *caption = "The change of the " + s.label + " (" + format_sig(s.nominal, 5) +
               (s.unit.empty() ? "" : " " + s.unit) +
               ") with each key of the case's sensitivity part at -step and +step, the largest "
               "first; elasticity: relative change of the figure per relative change of the "
               "key (section Sensitivity).";
  return file;
}

Section sensitivity_section(const SensitivityRecord& s) {
  Section sec;
  sec.id = "sensitivity";
  sec.heading = "Sensitivity";
  sec.paragraph(
      "How much the answer depends on the values the case assumes: the case was solved again "
      "with each key of its sensitivity part at its value minus and plus the step, every other "
      "key as written (warm-started from this answer where the study allows it: such a step "
      "follows this answer's local optimum, where a solve from scratch may land on another; "
      "no frames). "
      "The figure is the " +
      s.label + ", " + format_sig(s.nominal, 6) + (s.unit.empty() ? "" : " " + s.unit) +
      " in this case's answer. The elasticity is the central difference ((f+ - f-) / f) / "
      "((k+ - k-) / k): the relative change of the figure per relative change of the key. "
      "The binding constraints are those the study names for the answer at each step (" +
      list_words(s.binding) + " here); a step at which they differ is marked. Re-solves took " +
      format_sig(s.seconds, 3) + " s in all.");
  if (s.resolved_from)
    sec.paragraph(
        "Solved again: the answers of these steps met the case's own limits for less than its "
        "first answer, so the case was solved again with them as starts, and the steps in the "
        "table are around that answer: " +
        *s.resolved_from + ".");
  if (s.undercut)
    sec.paragraph(
        "NOT the optimum: after that, these steps still found answers within the case's own "
        "limits below the answer, and the check sensitivity_steps_do_not_undercut_the_answer "
        "fails: " +
        *s.undercut + ".");
  Table t;
  t.caption = "Every key of the case's sensitivity part, largest influence first.";
  t.header = {"What is varied",   "Case key, value, step", "At -step",
              "At +step",         "Change - / +",          "Elasticity",
              "Binding at -step", "Binding at +step"};
  const std::string unit = s.unit.empty() ? "" : " " + s.unit;
  auto at = [&](const SensitivityStepRecord& st) {
    const std::string v = "key " + values_words(st.key_value) + ": ";
    if (!st.value) return v + "no answer (" + st.status + "): " + st.message;
    return v + format_sig(*st.value, 6) + unit +
           (st.status == "solved" ? "" : " (" + st.status + ")") + (st.warm ? "" : ", solved anew");
  };
  auto change = [&](const SensitivityStepRecord& st) {
    return st.change ? format_sig(*st.change, 3) : std::string("-");
  };
  auto binding = [&](const SensitivityStepRecord& st) {
    if (!st.value) return std::string("-");
    return list_words(st.binding) + (st.binding_changed ? " (changed)" : "");
  };
  for (const auto* k : by_influence(s)) {
    t.rows.push_back(
        {k->why.empty() ? k->key : k->why,
         k->key + " = " + values_words(k->nominal) + ", ±" + step_words(*k, +1).substr(1),
         at(k->minus), at(k->plus), change(k->minus) + " / " + change(k->plus),
         k->elasticity ? format_sig(*k->elasticity, 4) : std::string("-"), binding(k->minus),
         binding(k->plus)});
  }
  sec.table(std::move(t));
  for (const auto& k : s.keys)
    if (!k.range.empty()) sec.note(k.key + ": " + k.range + ".");
  return sec;
}

}  // namespace armstudy::report
