// the placement study of 000_bf165d3f0a5605ef.txt: optima, maps, phi curves, time series
#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {

using nlohmann::json;

void placement_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& pl = results.contains("placement") ? results["placement"] : json::object();

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "A 2-link arm in a horizontal plane carries its payload along a straight line of length "
      "L in time T with a rest-to-rest motion program. The line is fixed; the arm's root "
      "location is chosen. As in the thesis (Ch. 4), start points S = (x_S, 0) and direction "
      "angles φ are swept on a grid, the root location in the line's frame is "
      "X = -x_S cos φ, Y = x_S sin φ (4.14), and for every candidate the actuator energy "
      "E = ∫ |M1 dθ1| + |M2 d(θ2 - θ1)| (Ch. 8, no regeneration) is computed from inverse "
      "dynamics for each program and configuration. Candidates that come closer to a "
      "workspace boundary than the singularity margin, or break a torque or power limit, are "
      "excluded from the optimum; the grid optimum is then refined by a bounded local "
      "optimiser.");
  method.note(
      "The thesis's printed example energies cannot be reproduced from its own model and "
      "parameters, and its eq. 7.2 is wrong (M2 is (6.35) itself and M1 = (6.29) + (6.35); "
      "(3.17b) must use sin θ1). Several of its printed optima (Y = 0.1999 or 0.2000) lie on "
      "lines tangent to the inner workspace circle, where the elbow folds completely and the "
      "arm is singular. This report computes from first principles and never presents a "
      "singular trajectory as an ordinary optimum, so its numbers differ from the thesis's.");
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "results";
  res.heading = "Results";
  Table t;
  t.header = {"quantity", "value"};
  for (const auto& [k, v] : pl.items())
    if (v.is_primitive() && !v.is_null()) t.rows.push_back({label_from_key(k), jsonv::str(pl, k.c_str())});
  if (!t.rows.empty()) res.table(std::move(t));
  time_series_figures(pl, "each optimum", figures, res);
  page.sections.push_back(std::move(res));
}

}  // namespace armstudy::report
