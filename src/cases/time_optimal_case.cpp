#include "cases/time_optimal_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cases/arm_loader.hpp"

namespace armstudy::cases {
namespace {
namespace to = studies::time_optimal;

// a per-joint pair of limits >= 0
std::optional<Eigen::Vector2d> joint_pair(Map& m, std::string_view key, const std::string& unit) {
  if (const auto v = m.numbers(key, NumberRule::non_negative(unit), 2)) return Eigen::Vector2d((*v)[0], (*v)[1]);
  return std::nullopt;
}

void load_path(Map& t, to::Spec* spec) {
  auto path = t.map("path");
  if (!path) {
    if (!t.has("path"))
      t.error_here("missing required key 'time_optimal.path'; expected the tip path (kind and points_m)");
    return;
  }
  const auto kind = path->choice("kind", {"line", "polyline", "spline"});
  spec->path.kind = !kind || *kind == "line" ? to::PathKind::kLine
                    : *kind == "polyline"   ? to::PathKind::kPolyline
                                            : to::PathKind::kSpline;
  auto pts = path->seq("points_m");
  if (!pts) {
    if (!path->has("points_m"))
      path->error_here("missing required key 'time_optimal.path.points_m'; expected a list of [x, y] tip points in m");
    path->finish();
    return;
  }
  for (size_t i = 0; i < pts->size(); ++i) {
    const YAML::Node n = pts->at(i);
    if (!n.IsSequence() || n.size() != 2) {
      pts->diag().error(n.Mark(), "'" + pts->path_at(i) + "' is not a point; expected [x, y] in m");
      continue;
    }
    const auto x = read_number(n[0], pts->diag(), pts->path_at(i) + "[1]", NumberRule::any("m"));
    const auto y = read_number(n[1], pts->diag(), pts->path_at(i) + "[2]", NumberRule::any("m"));
    if (!x || !y) continue;
    const Eigen::Vector2d p(*x, *y);
    if (!spec->path.points.empty() && (p - spec->path.points.back()).norm() < 1e-9) {
      pts->diag().error(n.Mark(), "'" + pts->path_at(i) + "' repeats the point before it; expected "
                                  "distinct consecutive points");
      continue;
    }
    spec->path.points.push_back(p);
  }
  const size_t n = spec->path.points.size();
  if (spec->path.kind == to::PathKind::kLine && pts->size() != 2) {
    path->error("points_m", "'time_optimal.path.points_m' has " + std::to_string(pts->size()) +
                                " points; expected exactly 2 for kind 'line' (polyline or spline for more)");
  } else if (pts->size() < 2) {
    path->error("points_m", "'time_optimal.path.points_m' has " + std::to_string(n) +
                                " point(s); expected at least 2");
  }
  path->finish();
}

void load_dp(Map& t, to::DpSettings* dp) {
  auto m = t.map("dp");
  if (!m) return;
  dp->segments = m->integer_or("segments", dp->segments, 2, 2000);
  dp->levels = m->integer_or("levels", dp->levels, 2, 20000);
  dp->checks_per_segment = m->integer_or("checks_per_segment", dp->checks_per_segment, 1, 1000);
  if (auto st = m->seq("states")) {
    dp->states.clear();
    for (size_t i = 0; i < st->size(); ++i) {
      const YAML::Node n = st->at(i);
      const std::string name = n.IsScalar() ? n.Scalar() : "";
      if (name == "path_speed") {
        dp->states.push_back(to::DpState::kPathSpeed);
      } else if (name == "joint1_velocity") {
        dp->states.push_back(to::DpState::kJoint1Velocity);
      } else {
        std::string msg = "'" + st->path_at(i) + "' is '" + brief(name) + "'; expected path_speed or joint1_velocity";
        if (const auto c = closest(name, {"path_speed", "joint1_velocity"})) msg += " (did you mean '" + *c + "'?)";
        st->diag().error(n.Mark(), msg);
      }
    }
    if (st->size() == 0) m->error("states", "'time_optimal.dp.states' is empty; expected path_speed and/or joint1_velocity");
  }
  if (m->has("convergence_segments")) {
    const YAML::Node n = m->get("convergence_segments");
    dp->convergence_segments.clear();
    if (!(n.IsSequence() && n.size() == 0)) {
      if (const auto v = m->numbers("convergence_segments", NumberRule::range(2, 2000, ""))) {
        for (size_t i = 0; i < v->size(); ++i) {
          if ((*v)[i] != std::floor((*v)[i])) {
            m->error("convergence_segments", "'time_optimal.dp.convergence_segments[" + std::to_string(i + 1) +
                                                 "]' is " + format_number((*v)[i]) + "; expected a whole number of segments");
            continue;
          }
          dp->convergence_segments.push_back(static_cast<int>((*v)[i]));
        }
      }
    }
  }
  m->finish();
}
}  // namespace

studies::time_optimal::Spec load_time_optimal(Map& root) {
  to::Spec spec;
  spec.chain = load_arm(root, to::default_arm(), 2);
  for (int i = 0; i < spec.chain.num_links(); ++i) {
    if (!spec.chain.links[i].active)
      root.error("arm", "'arm.links[" + std::to_string(i + 1) +
                            "]' has a passive joint; expected both joints active for a time-optimal study");
  }
  auto t = root.map("time_optimal");
  if (!t) {
    if (!root.has("time_optimal"))
      root.error_here("missing required key 'time_optimal'; expected the path and the joint limits");
    return spec;
  }
  load_path(*t, &spec);
  spec.configuration = t->integer_or("configuration", 1, 1, 2);
  if (const auto v = joint_pair(*t, "velocity_limit_rad_s", "rad/s")) spec.velocity_limit = *v;
  if (const auto v = joint_pair(*t, "torque_limit_Nm", "N m")) spec.torque_limit = *v;
  if (const auto v = joint_pair(*t, "acceleration_limit_rad_s2", "rad/s^2")) spec.acceleration_limit = *v;
  load_dp(*t, &spec.dp);
  if (auto c = t->map("complex")) {
    spec.complex.enabled = c->boolean_or("enabled", true);
    spec.complex.max_iterations = c->integer_or("max_iterations", spec.complex.max_iterations, 1, 10000000);
    spec.complex.tolerance = c->number_or("tolerance", spec.complex.tolerance, NumberRule::positive(""));
    spec.complex.seed = static_cast<unsigned>(c->integer_or("seed", 1, 0, 2147483647));
    c->finish();
  }
  if (auto e = t->map("exact")) {
    spec.exact.grid_points = e->integer_or("grid_points", spec.exact.grid_points, 3, 100000);
    spec.exact.checks_per_interval = e->integer_or("checks_per_interval", spec.exact.checks_per_interval, 1, 100);
    spec.exact.grid_tolerance = e->number_or("grid_tolerance", spec.exact.grid_tolerance, NumberRule::positive(""));
    e->finish();
  }
  spec.motion_steps = t->integer_or("motion_steps", spec.motion_steps, 1, 100000);
  // a polyline needs at least one segment per piece
  if (spec.path.kind == to::PathKind::kPolyline && spec.path.points.size() >= 2) {
    const int pieces = static_cast<int>(spec.path.points.size()) - 1;
    if (spec.dp.segments < 2 * pieces)
      root.error("time_optimal", "'time_optimal.dp.segments' is " + std::to_string(spec.dp.segments) +
                                     "; expected at least two segments per polyline piece (" +
                                     std::to_string(pieces) + " pieces): the arm stops at both ends of each");
    if (spec.exact.grid_points - 1 < 2 * pieces)
      root.error("time_optimal", "'time_optimal.exact.grid_points' is " + std::to_string(spec.exact.grid_points) +
                                     "; expected at least " + std::to_string(2 * pieces + 1) +
                                     " (two intervals per polyline piece)");
    for (int n : spec.dp.convergence_segments)
      if (n < 2 * pieces)
        root.error("time_optimal", "'time_optimal.dp.convergence_segments' holds " + std::to_string(n) +
                                       "; expected at least two segments per polyline piece (" +
                                       std::to_string(pieces) + " pieces)");
  }
  t->finish();
  if (t->diag().empty()) t->diag().demand(time_optimal_demand(spec, t->node().Mark()));
  return spec;
}

Demand time_optimal_demand(const studies::time_optimal::Spec& spec, const YAML::Mark& mark) {
  // the DP: one run per state kind on segments + 1 nodes of `levels` states, and one per row
  // of the convergence table with levels x N / segments states; every state checks the
  // limits at checks_per_segment + 1 points per transition band (counted once). The
  // Complex: each iteration times every segment at its check points.
  const double checks = spec.dp.checks_per_segment + 1.0;
  const double nodes = spec.dp.segments + 1.0;
  double states = double(spec.dp.states.size()) * nodes * spec.dp.levels, largest = nodes * spec.dp.levels;
  for (const int n : spec.dp.convergence_segments) {
    const double levels = std::round(spec.dp.levels * std::max(1.0, double(n) / spec.dp.segments));
    states += (n + 1.0) * levels;
    largest = std::max(largest, (n + 1.0) * levels);
  }
  const double complex = spec.complex.enabled ? double(spec.complex.max_iterations) * nodes : 0.0;
  const double exact = double(spec.exact.grid_points) * spec.exact.checks_per_interval;
  Demand d;
  d.what = "the time-optimal study";
  d.keys = "time_optimal.dp.segments, time_optimal.dp.levels, time_optimal.dp.checks_per_segment, "
           "time_optimal.dp.convergence_segments and time_optimal.complex.max_iterations";
  d.unit = "limit checks";
  d.work = (states + complex) * checks + exact;
  d.work_budget = 1e9;
  // a DP state holds its speed, speed squared, cost and choice (~32 B); the check points
  // of a segment ~100 B each
  d.memory_bytes = largest * 32.0 + nodes * checks * 100.0 + double(spec.motion_steps) * 100.0;
  char detail[240];
  std::snprintf(detail, sizeof detail, "%.3g DP states (the largest run %.3g) and %.3g Complex segment "
                "evaluations, x %.0f check points", states, largest, complex, checks);
  d.detail = detail;
  d.mark = mark;
  return d;
}

}  // namespace armstudy::cases
