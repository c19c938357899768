// the throwing study of 003_a986fd825f31d3e2.txt sec. 4: method, idp convergence, motor plots
#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {

using nlohmann::json;

void throwing_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& th = results.contains("throwing") ? results["throwing"] : json::object();

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "A 4-coordinate arm in a vertical plane throws a ball from a tray: links 1 and 2 are "
      "driven by DC servomotors, the tray hangs on a passive joint and the ball rolls in it. "
      "The joint-velocity profiles of the active joints over P time stages are optimised by "
      "iterative dynamic programming (Luus): candidates in a region around the best "
      "trajectory, the region shifted to the best and shrunk each iteration, starting from the "
      "trajectory of eq. 8 (in its corrected form). The criterion is the electrical energy "
      "E = Σ ∫ e i dt of the motors (eq. 5-7) plus the penalties of eq. 9 that keep the ball "
      "in the tray (|θ4| ≤ λ/2) and meet the release state; the tray's release angle follows "
      "from the passive dynamics, it is not commanded.");
  method.note(
      "Several printed coefficients of 003's equations of motion are inconsistent with its "
      "kinematics (a3's m4 term, two lines labelled A45, a5's inverted ratio, the ball spin "
      "of eq. 3, S234 in eq. 4); the model here is derived from first principles instead, so "
      "energies and angles differ from the paper's figures by design. What the paper leaves "
      "open (ball circle centre on the tray, ball inertia, motor 2 mounting, rotor inertia, "
      "tray width λ) is set in the case and listed in its parameters.");
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "results";
  res.heading = "Results";
  Table t;
  t.header = {"quantity", "value"};
  for (const auto& [k, v] : th.items())
    if (v.is_primitive() && !v.is_null()) t.rows.push_back({label_from_key(k), jsonv::str(th, k.c_str())});
  if (!t.rows.empty()) {
    t.caption = "Scalar results (SI units).";
    res.table(std::move(t));
  }
  time_series_figures(th, "the throwing motion", figures, res);
  page.sections.push_back(std::move(res));
}

}  // namespace armstudy::report
