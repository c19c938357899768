// the pendulum test of 003_a986fd825f31d3e2.txt sec. 3: method, energy and angle plots
#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {

using nlohmann::json;

void pendulum_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& p = results.contains("pendulum") ? results["pendulum"] : json::object();

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "The tray arm of 003 with joints 1 and 2 locked is a passive double pendulum: the tray "
      "swings on its hinge and the ball rolls without slipping on a circle in the tray "
      "(r_b φ' = -r4 θ4'). The equations of motion come from first principles (Lagrange, the "
      "ball's spin including the tray's rotation) and are integrated from rest with an "
      "adaptive Runge-Kutta method" +
      std::string(jsonv::has(p, "integrator") ? " (" + jsonv::str(p, "integrator") + ")" : "") +
      ". With no actuator and no friction the mechanical energy K + U must stay constant; its "
      "drift measures the model and the integrator together (the paper's Figure 3).");
  method.note(
      "The paper leaves open where joints 1 and 2 are locked (at -π/4, -π/4 the ball starts "
      "above the hinge and falls out; 0, 0 matches its figures), the tray's centre of mass and "
      "inertia, and the ball's inertia. The values used are in the case parameters above and "
      "in results.json. The paper's printed energy curve is not reproduced number for "
      "number: the check is conservation, which holds for any consistent choice.");
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "results";
  res.heading = "Results";
  Table t;
  t.header = {"quantity", "value"};
  for (const auto& [k, v] : p.items())
    if (v.is_primitive() && !v.is_null()) t.rows.push_back({label_from_key(k), jsonv::str(p, k.c_str())});
  if (!t.rows.empty()) {
    t.caption = "Scalar results of the simulation (SI units).";
    res.table(std::move(t));
  }
  time_series_figures(p, "the locked-arm pendulum", figures, res);
  page.sections.push_back(std::move(res));
}

}  // namespace armstudy::report
