// the time-optimal study of 004_87cbdf4981aa31c3.txt: method, phase plane, limits, dp table
#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {

using nlohmann::json;

void time_optimal_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& to = results.contains("time_optimal") ? results["time_optimal"] : json::object();

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "The tip of a 2-link arm in a horizontal plane follows a given path; the speed along it "
      "is chosen to reach the end in the least time under joint velocity and torque limits, "
      "at rest at both ends. Three solvers work on the same problem: dynamic programming as "
      "in the source (N segments of constant acceleration, Bellman recursion over a grid of "
      "velocity states; the path speed s' is the default state because joint 1 need not move "
      "monotonically), Box's Complex method on the same discretisation, and an exact solver "
      "on a fine grid (reachability analysis: backward controllable sets, then a greedy "
      "forward pass). Every solution is re-checked by dense resampling against every limit.");
  method.note(
      "The source is an abstract: link lengths, limits and the path are not given, so the "
      "case chooses them; there are no printed numbers to compare with. The comparison that "
      "matters is between the solvers: the exact solver is never slower than DP or Complex on "
      "the same problem.");
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "results";
  res.heading = "Results";
  Table t;
  t.header = {"quantity", "value"};
  for (const auto& [k, v] : to.items())
    if (v.is_primitive() && !v.is_null()) t.rows.push_back({label_from_key(k), jsonv::str(to, k.c_str())});
  if (!t.rows.empty()) {
    t.caption = "Scalar results (SI units).";
    res.table(std::move(t));
  }
  time_series_figures(to, "each solver", figures, res);
  page.sections.push_back(std::move(res));
}

}  // namespace armstudy::report
