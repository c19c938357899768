// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/time_optimal_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cases/arm_loader.hpp"
#include "studies/time_optimal/joint_path.hpp"

namespace armstudy::cases {
namespace {

// why a point `d` from the one before it is refused: a repeat, or nearer than 1e-9
std::string too_close(double d, const std::string& what, const std::string& unit) {
  const std::string want = "; expected consecutive " + what + "s at least 1e-09 " + unit + " apart";
  if (d == 0) return "repeats the " + what + " before it" + want;
  return "is only " + format_number(d) + " " + unit + " from the " + what + " before it" + want;
}
namespace to = studies::time_optimal;

// a per-joint list of limits >= 0, one per joint of the arm
std::optional<core::JointVector> joint_limits(Map& m, std::string_view key, const std::string& unit,
                                              int joints) {
  const YAML::Node n = m.has(key) ? m.get(key) : YAML::Node();
  if (n.IsDefined() && n.IsSequence() && n.size() != static_cast<size_t>(joints)) {
    m.diag().error(n.Mark(), "'" + m.path_of(key) + "' has " + std::to_string(n.size()) +
                                 " entries; expected " + std::to_string(joints) +
                                 ", one per joint of the arm");
    return std::nullopt;
  }
  // (its length checked above: the key reference says "one per joint", not a count)
  if (const auto v = m.numbers(key, NumberRule::non_negative(unit))) {
    core::JointVector out(joints);
    for (int j = 0; j < joints; ++j) out[j] = (*v)[j];
    return out;
  }
  return std::nullopt;
}

std::string kind_text(to::PathKind k) {
  return k == to::PathKind::kLine ? "line" : k == to::PathKind::kPolyline ? "polyline" : "spline";
}

// the waypoints of `time_optimal.joint_path.points_rad`, each `joints` angles, distinct
// consecutive ones; their YAML nodes in `nodes`. False when any could not be read.
bool read_waypoints(Seq& pts, int joints, const std::string& want, to::Spec* spec,
                    std::vector<YAML::Node>* nodes) {
  bool all_read = true;
  for (size_t i = 0; i < pts.size(); ++i) {
    const YAML::Node n = pts.at(i);
    if (!n.IsSequence() || n.size() != static_cast<size_t>(joints)) {
      std::string what = "'";
      what += pts.path_at(i);
      what += "' ";
      what += n.IsSequence() ? "has " + std::to_string(n.size()) + " angle(s)"
                             : std::string("is not a list of angles");
      pts.diag().error(n.Mark(), what + "; expected " + want);
      all_read = false;
      continue;
    }
    core::JointVector q(joints);
    bool ok = true;
    for (int j = 0; j < joints; ++j) {
      const auto v =
          read_number(n[j], pts.diag(), pts.path_at(i) + "[" + std::to_string(j + 1) + "]",
                      NumberRule::range(-100.0, 100.0, "rad"));
      if (v)
        q[j] = *v;
      else
        ok = false;
    }
    if (!ok) {
      all_read = false;
      continue;
    }
    if (!spec->joint_path.points.empty() && (q - spec->joint_path.points.back()).norm() < 1e-9) {
      pts.diag().error(
          n.Mark(), "'" + pts.path_at(i) + "' " +
                        too_close((q - spec->joint_path.points.back()).norm(), "waypoint", "rad"));
      all_read = false;
      continue;
    }
    spec->joint_path.points.push_back(q);
    nodes->push_back(n);
  }
  return all_read;
}

// the number of waypoints for the path's kind: 2 for a line, at least 2 otherwise
bool check_waypoint_count(Map& path, size_t count, to::PathKind kind) {
  if (kind == to::PathKind::kLine && count != 2) {
    path.error("points_rad",
               "'time_optimal.joint_path.points_rad' has " + std::to_string(count) +
                   " waypoints; expected exactly 2 for kind 'line' (polyline or spline for more)");
    return false;
  }
  if (count < 2) {
    path.error("points_rad", "'time_optimal.joint_path.points_rad' has " + std::to_string(count) +
                                 " waypoint(s); expected at least 2 for kind '" + kind_text(kind) +
                                 "'");
    return false;
  }
  return true;
}

// `time_optimal.joint_path.range_rad`: one [lo, hi] per joint (none read when any is wrong)
bool read_joint_ranges(Map& path, int joints, to::Spec* spec) {
  bool range_ok = true;
  auto rs = path.seq("range_rad");
  if (!rs) return range_ok;
  if (rs->size() != static_cast<size_t>(joints)) {
    path.error("range_rad", "'time_optimal.joint_path.range_rad' has " +
                                std::to_string(rs->size()) + " entries; expected " +
                                std::to_string(joints) + " [lo, hi] pairs in rad, one per joint");
    range_ok = false;
  }
  for (size_t i = 0; i < rs->size() && range_ok; ++i) {
    const YAML::Node n = rs->at(i);
    if (!n.IsSequence() || n.size() != 2) {
      rs->diag().error(n.Mark(),
                       "'" + rs->path_at(i) + "' is not a range; expected [lo, hi] in rad");
      range_ok = false;
      continue;
    }
    const auto lo = read_number(n[0], rs->diag(), rs->path_at(i) + "[1]",
                                NumberRule::range(-100.0, 100.0, "rad"));
    const auto hi = read_number(n[1], rs->diag(), rs->path_at(i) + "[2]",
                                NumberRule::range(-100.0, 100.0, "rad"));
    if (!lo || !hi) {
      range_ok = false;
      continue;
    }
    if (!(*lo < *hi)) {
      rs->diag().error(n.Mark(), "'" + rs->path_at(i) + "' is [" + format_number(*lo) + ", " +
                                     format_number(*hi) + "]; expected lo < hi");
      range_ok = false;
      continue;
    }
    spec->joint_path.range.emplace_back(*lo, *hi);
  }
  if (!range_ok) spec->joint_path.range.clear();
  return range_ok;
}

// the whole path inside the ranges: a waypoint outside is named itself; a spline that
// swings out between two waypoints is named at the first of them
void check_path_in_ranges(Seq& pts, const std::vector<YAML::Node>& nodes, int joints,
                          const to::Spec& spec) {
  const to::JointPathGeometry geometry(spec.joint_path);
  const auto e = to::range_excursion(geometry, spec.joint_path.range);
  if (!e) return;
  const to::JointPathSpec& jp = spec.joint_path;
  for (size_t i = 0; i < jp.points.size(); ++i)
    for (int j = 0; j < joints; ++j)
      if (jp.points[i][j] < jp.range[j][0] || jp.points[i][j] > jp.range[j][1]) {
        pts.diag().error(nodes[i][j].Mark(),
                         "'" + pts.path_at(i) + "[" + std::to_string(j + 1) + "]' is " +
                             format_number(jp.points[i][j]) + " rad, outside joint " +
                             std::to_string(j + 1) + "'s range [" + format_number(jp.range[j][0]) +
                             ", " + format_number(jp.range[j][1]) +
                             "] rad ('time_optimal.joint_path.range_rad[" + std::to_string(j + 1) +
                             "]'); expected a waypoint inside every joint's range");
        return;
      }
  pts.diag().error(nodes[e->piece].Mark(), "'" + pts.path_at(e->piece) + "': " + e->text +
                                               ", outside it although the waypoints are inside; "
                                               "expected a path inside every joint's range (move "
                                               "these waypoints, add one between them, or "
                                               "use kind polyline)");
}

// `time_optimal.joint_path`: waypoints in joint space, one angle per joint, and the joints'
// optional ranges (the whole path must stay inside them)
void load_joint_path(Map& path, int joints, to::Spec* spec,
                     const std::vector<Eigen::Vector2d>& model_range) {
  spec->space = to::PathSpace::kJoint;
  if (joints < 1 || joints > core::kMaxLinks) {
    // the arm is already refused (arm.links, or 0 when it was): no joints to read against
    for (const char* k : {"kind", "points_rad", "range_rad"}) path.get(k);
    path.finish();
    return;
  }
  const auto kind = path.choice("kind", {"line", "polyline", "spline"});
  spec->joint_path.kind = !kind || *kind == "line" ? to::PathKind::kLine
                          : *kind == "polyline"    ? to::PathKind::kPolyline
                                                   : to::PathKind::kSpline;
  const std::string want = std::to_string(joints) + " angle" + (joints == 1 ? "" : "s") +
                           " in rad, one per joint of the arm's " + std::to_string(joints) +
                           " links";
  auto pts = path.seq("points_rad");
  if (!pts) {
    if (!path.has("points_rad"))
      path.error_here(
          "missing required key 'time_optimal.joint_path.points_rad'; expected a list of "
          "waypoints, each " +
          want);
    path.get("range_rad");
    path.finish();
    return;
  }
  std::vector<YAML::Node> nodes;  // the YAML node of each waypoint read
  const bool all_read = read_waypoints(*pts, joints, want, spec, &nodes);
  const bool count_ok = check_waypoint_count(path, pts->size(), spec->joint_path.kind);
  const bool range_ok = read_joint_ranges(path, joints, spec);
  if (!path.has("range_rad") && model_range.size() == static_cast<size_t>(joints))
    spec->joint_path.range = model_range;  // the model's joint ranges (arm.model)
  path.finish();
  if (!all_read || !count_ok || !range_ok || spec->joint_path.range.empty()) return;
  check_path_in_ranges(*pts, nodes, joints, *spec);
}

void load_path(Map& t, to::Spec* spec) {
  auto path = t.map("path");
  if (!path) {
    if (!t.has("path"))
      t.error_here(
          "missing required key 'time_optimal.path'; expected the tip path (kind and points_m)");
    return;
  }
  const auto kind = path->choice("kind", {"line", "polyline", "spline"});
  spec->path.kind = !kind || *kind == "line" ? to::PathKind::kLine
                    : *kind == "polyline"    ? to::PathKind::kPolyline
                                             : to::PathKind::kSpline;
  auto pts = path->seq("points_m");
  if (!pts) {
    if (!path->has("points_m"))
      path->error_here(
          "missing required key 'time_optimal.path.points_m'; expected a list of [x, y] tip points "
          "in m");
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
      pts->diag().error(n.Mark(),
                        "'" + pts->path_at(i) + "' " +
                            too_close((p - spec->path.points.back()).norm(), "point", "m"));
      continue;
    }
    spec->path.points.push_back(p);
  }
  const size_t n = spec->path.points.size();
  if (spec->path.kind == to::PathKind::kLine && pts->size() != 2) {
    path->error("points_m",
                "'time_optimal.path.points_m' has " + std::to_string(pts->size()) +
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
  std::vector<std::string> default_states;
  for (const auto state : dp->states)
    default_states.emplace_back(state == to::DpState::kPathSpeed ? "path_speed"
                                                                 : "joint1_velocity");
  if (auto st = m->seq("states", default_states)) {
    dp->states.clear();
    for (size_t i = 0; i < st->size(); ++i) {
      const YAML::Node n = st->at(i);
      const std::string name = n.IsScalar() ? n.Scalar() : "";
      if (name == "path_speed") {
        dp->states.push_back(to::DpState::kPathSpeed);
      } else if (name == "joint1_velocity") {
        dp->states.push_back(to::DpState::kJoint1Velocity);
      } else {
        std::string msg = "'" + st->path_at(i) + "' is '" + brief(name) +
                          "'; expected path_speed or joint1_velocity";
        if (const auto c = closest(name, {"path_speed", "joint1_velocity"}))
          msg += " (did you mean '" + *c + "'?)";
        st->diag().error(n.Mark(), msg);
      }
    }
    if (st->size() == 0)
      m->error("states",
               "'time_optimal.dp.states' is empty; expected path_speed and/or joint1_velocity");
  }
  if (m->has("convergence_segments")) {
    const YAML::Node n = m->get("convergence_segments");
    const std::vector<double> default_segments(dp->convergence_segments.begin(),
                                               dp->convergence_segments.end());
    dp->convergence_segments.clear();
    if (!(n.IsSequence() && n.size() == 0)) {
      if (const auto v = m->numbers("convergence_segments", NumberRule::range(2, 2000, ""), 0,
                                    default_segments)) {
        for (size_t i = 0; i < v->size(); ++i) {
          if ((*v)[i] != std::floor((*v)[i])) {
            m->error("convergence_segments",
                     "'time_optimal.dp.convergence_segments[" + std::to_string(i + 1) + "]' is " +
                         format_number((*v)[i]) + "; expected a whole number of segments");
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

namespace {
// the arm: 2 to kMaxLinks links, every joint active
void check_time_optimal_arm(Map& root, const core::PlanarChain& chain, bool arm_ok) {
  const int joints = chain.num_links();
  if (arm_ok && joints < 2)
    root.error("arm", "'arm.links' has " + std::to_string(joints) + " link; expected 2 to " +
                          std::to_string(core::kMaxLinks) + " links for a time-optimal study");
  for (int i = 0; i < joints; ++i) {
    if (!chain.links[i].active)
      root.error(
          "arm",
          "'arm.links[" + std::to_string(i + 1) +
              "]' has a passive joint; expected every joint active for a time-optimal study");
  }
}

// exactly one of time_optimal.path (a tip path, 2 links) and time_optimal.joint_path
void load_either_path(Map& t, bool arm_ok, int joints, to::Spec* spec,
                      const std::vector<Eigen::Vector2d>& model_range) {
  if (t.has("path") && t.has("joint_path")) {
    t.error("joint_path",
            "'time_optimal' has both 'path' (a tip path) and 'joint_path'; expected one of them");
    t.get("path");
  } else if (t.has("joint_path")) {
    if (auto jp = t.map("joint_path")) load_joint_path(*jp, arm_ok ? joints : 0, spec, model_range);
    spec->space = to::PathSpace::kJoint;
    if (t.has("configuration"))
      t.error(
          "configuration",
          "'time_optimal.configuration' chooses the elbow of a tip path's inverse "
          "kinematics; expected no configuration with a joint_path (its joint angles are given)");
  } else {
    if (arm_ok && joints != 2 && t.has("path")) {
      t.error("path",
              "'time_optimal.path' is a tip path, but the arm has " + std::to_string(joints) +
                  " links: " +
                  (joints > 2 ? "a redundant arm follows a tip path with many joint motions, "
                                "so the path does not fix one; "
                              : "") +
                  "expected a path in joint space, 'time_optimal.joint_path' with points_rad (one "
                  "angle per joint in every waypoint), or an arm of 2 links");
      t.get("path");
    } else if (!t.has("path")) {
      t.error_here(
          "missing required key 'time_optimal.path'; expected the tip path (kind and points_m) "
          "or 'time_optimal.joint_path' (kind and points_rad)");
    } else {
      load_path(t, spec);
    }
  }
}

// one per-joint limit of an imported arm's model, if it states it for every joint
std::optional<core::JointVector> model_limit(
    const std::vector<std::optional<model_import::ModelLimit>>& per_joint, std::string* from) {
  if (per_joint.empty()) return std::nullopt;
  core::JointVector v(static_cast<int>(per_joint.size()));
  for (size_t i = 0; i < per_joint.size(); ++i) {
    if (!per_joint[i]) return std::nullopt;
    v[static_cast<int>(i)] = per_joint[i]->value;
    *from += (i ? "; " : "") + per_joint[i]->from;
  }
  return v;
}

std::string joint_values(const core::JointVector& v) {
  std::string s = "[";
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + format_number(v[i]);
  return s + "]";
}

// the per-joint limits, judged against a valid arm only (a refused arm is reported once).
// An imported arm's model states its own (arm.model); a case key still overrides them.
void load_limits(Map& t, bool arm_ok, int joints, to::Spec* spec,
                 const model_import::ImportedArm* model) {
  std::vector<std::string>& origin = spec->arm_origin.limits;
  if (arm_ok) {
    const int nl = std::clamp(joints, 1, core::kMaxLinks);
    if (const auto v = joint_limits(t, "velocity_limit_rad_s", "rad/s", nl))
      spec->velocity_limit = *v;
    if (const auto v = joint_limits(t, "torque_limit_Nm", "N m", nl)) spec->torque_limit = *v;
    if (const auto v = joint_limits(t, "acceleration_limit_rad_s2", "rad/s^2", nl))
      spec->acceleration_limit = *v;
  } else {
    for (const char* key : {"velocity_limit_rad_s", "torque_limit_Nm", "acceleration_limit_rad_s2"})
      t.get(key);
  }
  struct Key {
    const char* key;
    const char* unit;
    core::JointVector* value;
    const std::vector<std::optional<model_import::ModelLimit>>* from_model;
  };
  const std::vector<std::optional<model_import::ModelLimit>> none;
  for (const Key& k :
       {Key{"velocity_limit_rad_s", "rad/s", &spec->velocity_limit,
            model ? &model->velocity : &none},
        Key{"torque_limit_Nm", "N m", &spec->torque_limit, model ? &model->torque : &none}}) {
    if (!arm_ok) break;
    std::string from;
    const std::string key = std::string("time_optimal.") + k.key;
    if (t.has(k.key)) {
      if (model)
        origin.push_back(key + " " + joint_values(*k.value) + " " + k.unit +
                         ": the case (over the model's)");
    } else if (const auto v = model_limit(*k.from_model, &from)) {
      *k.value = *v;
      origin.push_back(key + " " + joint_values(*v) + " " + k.unit + ": the model's " + from);
    } else if (model || joints != 2) {
      // the default limits are the 2-link source's: a longer chain, or a model's arm, states
      // its own
      t.error_here("missing required key '" + key + "' for an arm of " + std::to_string(joints) +
                   " links; expected " + std::to_string(joints) + " limits, one per joint " +
                   (model ? "(the model " + model->path + " does not state them for every joint)"
                          : std::string("(the defaults are a 2-link arm's)")));
    }
  }
  if (model && spec->acceleration_limit)
    origin.push_back("time_optimal.acceleration_limit_rad_s2 " +
                     joint_values(*spec->acceleration_limit) + " rad/s^2: the case");
}

// time_optimal.complex and time_optimal.exact
void load_complex_and_exact(Map& t, to::Spec* spec) {
  if (auto c = t.map("complex")) {
    spec->complex.enabled = c->boolean_or("enabled", true);
    spec->complex.max_iterations =
        c->integer_or("max_iterations", spec->complex.max_iterations, 1, 10000000);
    spec->complex.tolerance =
        c->number_or("tolerance", spec->complex.tolerance, NumberRule::positive(""));
    spec->complex.seed = static_cast<unsigned>(c->integer_or("seed", 1, 0, 2147483647));
    c->finish();
  }
  if (auto e = t.map("exact")) {
    spec->exact.grid_points = e->integer_or("grid_points", spec->exact.grid_points, 3, 100000);
    spec->exact.checks_per_interval =
        e->integer_or("checks_per_interval", spec->exact.checks_per_interval, 1, 100);
    spec->exact.grid_tolerance =
        e->number_or("grid_tolerance", spec->exact.grid_tolerance, NumberRule::positive(""));
    spec->exact.tolerance_rel =
        e->number_or("tolerance_rel", spec->exact.tolerance_rel, NumberRule::non_negative(""));
    spec->exact.max_grid_points =
        e->integer_or("max_grid_points", spec->exact.max_grid_points, 3, 1000000);
    e->finish();
  }
}

// a polyline needs at least one segment per piece
void check_polyline_segments(Map& root, const to::Spec& spec) {
  const bool joint_space = spec.space == to::PathSpace::kJoint;
  const to::PathKind kind = joint_space ? spec.joint_path.kind : spec.path.kind;
  const size_t waypoints = joint_space ? spec.joint_path.points.size() : spec.path.points.size();
  if (kind != to::PathKind::kPolyline || waypoints < 2) return;
  const int pieces = static_cast<int>(waypoints) - 1;
  if (spec.dp.segments < 2 * pieces)
    root.error("time_optimal", "'time_optimal.dp.segments' is " + std::to_string(spec.dp.segments) +
                                   "; expected at least two segments per polyline piece (" +
                                   std::to_string(pieces) +
                                   " pieces): the arm stops at both ends of each");
  if (spec.exact.grid_points - 1 < 2 * pieces)
    root.error("time_optimal", "'time_optimal.exact.grid_points' is " +
                                   std::to_string(spec.exact.grid_points) + "; expected at least " +
                                   std::to_string(2 * pieces + 1) +
                                   " (two intervals per polyline piece)");
  for (int n : spec.dp.convergence_segments)
    if (n < 2 * pieces)
      root.error("time_optimal", "'time_optimal.dp.convergence_segments' holds " +
                                     std::to_string(n) +
                                     "; expected at least two segments per polyline piece (" +
                                     std::to_string(pieces) + " pieces)");
}
}  // namespace

studies::time_optimal::Spec load_time_optimal(Map& root) {
  to::Spec spec;
  const size_t errors_before = root.diag().count();
  std::optional<model_import::ImportedArm> model;
  spec.chain = load_arm(root, to::default_arm(), 0, &model);
  const bool arm_ok = root.diag().count() == errors_before;
  if (model) spec.arm_origin = arm_origin(*model);
  const int joints = spec.chain.num_links();
  check_time_optimal_arm(root, spec.chain, arm_ok);
  auto t = root.map("time_optimal");
  if (!t) {
    if (!root.has("time_optimal"))
      root.error_here(
          "missing required key 'time_optimal'; expected the path and the joint limits");
    return spec;
  }
  load_either_path(*t, arm_ok, joints, &spec,
                   model ? model_ranges(*model) : std::vector<Eigen::Vector2d>{});
  if (model && spec.space == to::PathSpace::kJoint && !spec.joint_path.range.empty()) {
    const YAML::Node jp = t->node()["joint_path"];
    const bool own = jp.IsMap() && jp["range_rad"].IsDefined();
    std::string from;
    for (const auto& r : model->range)
      if (r) from += (from.empty() ? "" : "; ") + r->from;
    spec.arm_origin.limits.push_back("time_optimal.joint_path.range_rad: " +
                                     (own ? std::string("the case") : "the model's " + from));
  }
  spec.configuration = t->integer_or("configuration", 1, 1, 2);
  load_limits(*t, arm_ok, joints, &spec, model ? &*model : nullptr);
  load_dp(*t, &spec.dp);
  load_complex_and_exact(*t, &spec);
  spec.motion_steps = t->integer_or("motion_steps", spec.motion_steps, 1, 100000);
  check_polyline_segments(root, spec);
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
  double states = double(spec.dp.states.size()) * nodes * spec.dp.levels,
         largest = nodes * spec.dp.levels;
  for (const int n : spec.dp.convergence_segments) {
    const double levels = std::round(spec.dp.levels * std::max(1.0, double(n) / spec.dp.segments));
    states += (n + 1.0) * levels;
    largest = std::max(largest, (n + 1.0) * levels);
  }
  const double complex = spec.complex.enabled ? double(spec.complex.max_iterations) * nodes : 0.0;
  const double exact = double(spec.exact.grid_points) * spec.exact.checks_per_interval;
  Demand d;
  d.what = "the time-optimal study";
  d.keys =
      "time_optimal.dp.segments, time_optimal.dp.levels, time_optimal.dp.checks_per_segment, "
      "time_optimal.dp.convergence_segments and time_optimal.complex.max_iterations";
  d.unit = "limit checks";
  d.work = (states + complex) * checks + exact;
  d.work_budget = 1e9;
  d.work_per_second = 1.5e7;  // the bundled cases: 1e7-4e7 checks a second
  d.frames_rendered = 45.0;   // the motion's animation and strips
  // a DP state holds its speed, speed squared, cost and choice (~32 B); the check points
  // of a segment ~100 B each
  d.memory_bytes = largest * 32.0 + nodes * checks * 100.0 + double(spec.motion_steps) * 100.0;
  char detail[240];
  std::snprintf(detail, sizeof detail,
                "%.3g DP states (the largest run %.3g) and %.3g Complex segment "
                "evaluations, x %.0f check points",
                states, largest, complex, checks);
  d.detail = detail;
  d.mark = mark;
  return d;
}

}  // namespace armstudy::cases
