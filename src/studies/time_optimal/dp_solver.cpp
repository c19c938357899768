// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// dynamic programming (Ozkipcak 1994) and Box's Complex on the same discretisation
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/opt/box_complex.hpp"
#include "core/opt/dynamic_programming.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kComplexRestarts = 10;   // restarts of the Complex method from its best point
constexpr double kRestartGain = 1e-6;  // relative gain a restart must make to go on

// The limits at the check points of one segment in flat arrays (within_limits' numbers:
// q'^2, a, b, c, q'' and q' per joint and point), for the path-speed recursion's hot test.
struct SegmentLimits {
  int checks = 1, nj = 0;
  bool acceleration = false;
  std::vector<double> v;  // per point m, per joint: dq^2, a, b, c, ddq, dq
  double ds = 0;
  double vlim2[core::kMaxLinks] = {};  // velocity limits squared
};

SegmentLimits segment_limits(const Problem& pb, const std::vector<double>& nodes,
                             const std::vector<JointPoint>& pts, int k, int checks) {
  SegmentLimits g;
  g.checks = checks;
  g.nj = pb.limits.joints();
  g.acceleration = pb.limits.acceleration.has_value();
  g.ds = nodes[k + 1] - nodes[k];
  for (int j = 0; j < g.nj; ++j) g.vlim2[j] = pb.limits.velocity[j] * pb.limits.velocity[j];
  for (int m = 0; m <= checks; ++m) {
    const JointPoint& jp = pts[m];
    for (int j = 0; j < g.nj; ++j)
      g.v.insert(g.v.end(), {jp.dq[j] * jp.dq[j], jp.a[j], jp.b[j], jp.c[j], jp.ddq[j], jp.dq[j]});
  }
  return g;
}

// within_limits at every check point of the move x0 -> x1 (path_speed_cost's test, the same
// operations in the same order)
bool segment_within_limits(const SegmentLimits& seg, const Limits& lim, double x0, double x1) {
  const double* vlim2 = seg.vlim2;
  const double u = (x1 - x0) / (2 * seg.ds);
  const double* p = seg.v.data();
  for (int m = 0; m <= seg.checks; ++m) {
    const double x = x0 + (x1 - x0) * m / seg.checks;
    for (int j = 0; j < seg.nj; ++j, p += 6) {
      if (p[0] * x > vlim2[j]) return false;
      const double tau = p[1] * u + p[2] * x + p[3];
      if (tau > lim.torque[j] || tau < -lim.torque[j]) return false;
      if (seg.acceleration) {
        const double qdd = p[5] * u + p[4] * x;
        if (qdd > (*lim.acceleration)[j] || qdd < -(*lim.acceleration)[j]) return false;
      }
    }
  }
  return true;
}

// the discretisation shared by the path-speed DP and the Complex method
struct Discretisation {
  std::vector<double> nodes;
  std::vector<bool> rest;
  std::vector<std::vector<JointPoint>> pts;  // [interval][check point]
  std::vector<double> mvc;                   // m/s per node
  int checks = 1;
  std::vector<SegmentLimits> seg;  // the limits at pts[k] in flat arrays
};

Discretisation discretise(const Problem& pb, int segments, int checks) {
  Discretisation d;
  d.nodes = make_nodes(pb.path, segments);
  d.rest = rest_nodes(pb.path, d.nodes);
  d.pts = interval_points(pb, d.nodes, checks);
  d.checks = checks;
  for (size_t k = 0; k + 1 < d.nodes.size(); ++k)
    d.seg.push_back(segment_limits(pb, d.nodes, d.pts[k], static_cast<int>(k), checks));
  std::vector<double> vel;
  max_velocity_curve(pb, d.nodes, &d.mvc, &vel);
  return d;
}

// time of interval k from s'^2 = x0 to x1 at constant s'' if every limit holds at its check
// points, else +inf
double path_speed_cost(const Problem& pb, const Discretisation& d, int k, double x0, double x1,
                       double sd0, double sd1) {
  if (sd0 + sd1 <= 0) return kInf;
  const double ds = d.nodes[k + 1] - d.nodes[k];
  const double u = (x1 - x0) / (2 * ds);
  const auto& pts = d.pts[k];
  for (int m = 0; m <= d.checks; ++m) {
    const double x = x0 + (x1 - x0) * m / d.checks;
    if (!within_limits(pts[m], pb.limits, x, u)) return kInf;
  }
  return 2 * ds / (sd0 + sd1);
}

// path_speed_cost from the segment's flat arrays (the same numbers)
double path_speed_cost_flat(const Problem& pb, const Discretisation& d, int k, double x0, double x1,
                            double sd0, double sd1) {
  if (sd0 + sd1 <= 0) return kInf;
  if (!segment_within_limits(d.seg[k], pb.limits, x0, x1)) return kInf;
  const double ds = d.nodes[k + 1] - d.nodes[k];
  return 2 * ds / (sd0 + sd1);
}

// the largest use of any limit at (x, u) of jp, as ratio - 1 (> 0: broken), and which
struct Use {
  double excess = -kInf;
  RowTag tag;
};

Use worst_use(const JointPoint& jp, const Limits& lim, double x, double u) {
  Use out;
  const auto take = [&](double value, int j, LimitKind kind) {
    const double l = lim.of(kind, j);
    const double r = l > 0 ? std::abs(value) / l : (std::abs(value) > 1e-12 ? kInf : 0.0);
    if (r - 1 > out.excess) {
      out.excess = r - 1;
      out.tag = RowTag{j, kind, 0, jp.s};
    }
  };
  for (int j = 0; j < lim.joints(); ++j) {
    take(jp.dq[j] * std::sqrt(std::max(0.0, x)), j, LimitKind::kVelocity);
    take(jp.a[j] * u + jp.b[j] * x + jp.c[j], j, LimitKind::kTorque);
    if (lim.acceleration) take(jp.dq[j] * u + jp.ddq[j] * x, j, LimitKind::kAcceleration);
  }
  return out;
}

Use max_use(const Use& a, const Use& b) { return b.excess > a.excess ? b : a; }

// the worst limit use over the check points of interval k from x0 to x1 at constant s''
Use path_speed_use(const Problem& pb, const Discretisation& d, int k, double x0, double x1) {
  const double ds = d.nodes[k + 1] - d.nodes[k];
  const double u = (x1 - x0) / (2 * ds);
  Use out;
  for (int m = 0; m <= d.checks; ++m)
    out = max_use(out, worst_use(d.pts[k][m], pb.limits, x0 + (x1 - x0) * m / d.checks, u));
  return out;
}

std::string segment_text(const Problem& pb, const Discretisation& d, int k) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(3);
  os << "segment " << k + 1 << " of " << d.nodes.size() - 1 << " (s = " << d.nodes[k] << " to "
     << d.nodes[k + 1] << " " << pb.path.unit() << ", ";
  if (pb.path.joint_space()) {
    const auto q = [&](double s, bool left) {
      const core::JointVector v = pb.path.joint().at(s, left).q;
      std::ostringstream o;
      o.setf(std::ios::fixed);
      o.precision(3);
      for (int j = 0; j < v.size(); ++j) o << (j ? ", " : "(") << v[j];
      o << ")";
      return o.str();
    };
    os << "q = " << q(d.nodes[k], false) << " to " << q(d.nodes[k + 1], true) << " rad)";
  } else {
    const Eigen::Vector2d a = pb.tip(d.nodes[k]), b = pb.tip(d.nodes[k + 1], true);
    os << "(x, y) = (" << a.x() << ", " << a.y() << ") to (" << b.x() << ", " << b.y() << ") m)";
  }
  return os.str();
}

std::string use_text(const Use& u, const Limits& lim, const char* unit) {
  std::ostringstream os;
  os.precision(4);
  os << describe(u.tag, lim, unit) << ", used to " << 100 * (1 + u.excess) << " %";
  return os.str();
}

// Why a staged DP found no sequence: the first segment that no state reachable from the
// start can cross, and the least breach of any limit over the moves across it.
// feasible(k, i, j): the DP's transition is allowed; use(k, i, j): its worst limit use;
// rest(k, i, j): the move stays at rest (no progress, infinite time); band(k, i): the
// successors the DP tried (every other one is known to break a limit).
template <typename Feasible, typename UseFn, typename Rest, typename Band>
std::string dp_failure(const Problem& pb, const Discretisation& d, const std::vector<int>& count,
                       Feasible&& feasible, UseFn&& use, Rest&& rest, Band&& band) {
  const int n = static_cast<int>(count.size());
  std::vector<int> reach(1, 0);  // state indices reachable at node k (node 0: rest)
  for (int i = 1; i < count[0]; ++i) reach.push_back(i);
  for (int k = 0; k + 1 < n; ++k) {
    std::vector<char> next(count[k + 1], 0);
    bool any = false;
    for (int i : reach) {
      const auto [first, last] = band(k, i);
      for (int j = std::max(0, first); j < std::min(count[k + 1], last); ++j)
        if (!next[j] && feasible(k, i, j)) next[j] = 1, any = true;
    }
    if (any) {
      reach.clear();
      for (int j = 0; j < count[k + 1]; ++j)
        if (next[j]) reach.push_back(j);
      continue;
    }
    // the least breach over the moves from (at most 64 of) the reachable states
    Use least;
    least.excess = kInf;
    const size_t stride = std::max<size_t>(1, reach.size() / 64);
    for (size_t r = 0; r < reach.size(); r += stride)
      for (int j = 0; j < count[k + 1]; ++j) {
        if (rest(k, reach[r], j)) continue;
        const Use u = use(k, reach[r], j);
        if (u.excess < least.excess) least = u;
      }
    std::ostringstream os;
    os << segment_text(pb, d, k) << " cannot be crossed from any of the " << reach.size()
       << " state(s) reachable at its start";
    if (std::isfinite(least.excess))
      os << ": every move breaks a limit, the least breach is "
         << use_text(least, pb.limits, pb.path.unit());
    else
      os << ": only staying at rest meets the limits there";
    return os.str();
  }
  return "every segment can be crossed, but no sequence reaches the end at rest";
}

std::string where(const Problem& pb, double s) { return pb.where(s); }

// The DP's Bellman recursion: core::opt::solve_staged_dp's answer with the cost
// time(k, i, j) where feasible(k, i, j), else +inf (the same cost, states and transition
// count, bitwise) without evaluating most transitions. From state i at node k the successors
// j of the band are taken from the fastest down: where monotone(k), the segment time does
// not grow with j (path speed: 2 ds / (s'_i + s'_j) with levels growing with j; rounding is
// monotonic), so time(k, i, j) + min(J(k+1, 0..j)) bounds from below every move to a level
// <= j, and once the bound exceeds the best move found no lower level can beat or tie it.
// Ties go to the lowest level, as in the ascending scan. `evaluations` counts the band's
// transitions into states that reach the end, as solve_staged_dp does.
template <typename Time, typename Feasible, typename Band, typename Monotone>
core::opt::DpSolution pruned_recursion(const std::vector<int>& levels, Time&& time,
                                       Feasible&& feasible, Band&& band, Monotone&& monotone) {
  const int nodes = static_cast<int>(levels.size());
  core::opt::DpSolution sol;
  std::vector<std::vector<double>> value(nodes);
  std::vector<std::vector<int>> next(nodes);
  value[nodes - 1].assign(levels[nodes - 1], 0.0);
  next[nodes - 1].assign(levels[nodes - 1], -1);
  std::vector<double> floor;   // floor[j] = min J(k+1, 0..j)
  std::vector<long> reaching;  // reaching[j] = how many of J(k+1, 0..j-1) are finite
  for (int k = nodes - 2; k >= 0; --k) {
    value[k].assign(levels[k], kInf);
    next[k].assign(levels[k], -1);
    const std::vector<double>& later = value[k + 1];
    const int n1 = levels[k + 1];
    floor.resize(n1);
    reaching.resize(n1 + 1);
    reaching[0] = 0;
    for (int j = 0; j < n1; ++j) {
      floor[j] = j == 0 ? later[0] : std::min(floor[j - 1], later[j]);
      reaching[j + 1] = reaching[j] + (std::isfinite(later[j]) ? 1 : 0);
    }
    // (a segment whose time is not known to fall with j is scanned whole, in the same order)
    const bool prune = monotone(k);
    for (int i = 0; i < levels[k]; ++i) {
      const std::pair<int, int> range = band(k, i);
      const int first = range.first < 0 ? 0 : range.first;
      const int last = range.second > n1 ? n1 : range.second;
      if (first >= last) continue;
      sol.evaluations += reaching[last] - reaching[first];
      double best = kInf;
      int arg = -1;
      for (int j = last - 1; j >= first; --j) {
        if (!std::isfinite(floor[j])) break;  // no state at or below j reaches the end
        if (!std::isfinite(later[j])) continue;
        const double c = time(k, i, j);
        if (prune && c + floor[j] > best) break;
        if (!std::isfinite(c) || !feasible(k, i, j)) continue;
        if (c + later[j] <= best) {
          best = c + later[j];
          arg = j;
        }
      }
      value[k][i] = best;
      next[k][i] = arg;
    }
  }
  core::opt::read_out_staged_dp(value, next, sol);
  return sol;
}
}  // namespace

namespace {
// the DP with the path speed s' as its state: s' levels on [0, MVC(s_k)] at each node
// (over 60 lines, kept whole: the band, cost and limit lambdas share the state grid and
// are passed to the recursion as they are)
SolverOutput dp_path_speed(const Problem& pb, const Discretisation& d,
                           const std::vector<int>& count, int segments, int levels, int checks,
                           bool reference) {
  SolverOutput out;
  const int n = static_cast<int>(d.nodes.size());
  // the state grid of the source's step 1, per node
  std::vector<std::vector<double>> sd(n), x(n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < count[k]; ++i) {
      const double v = count[k] == 1 ? 0.0 : d.mvc[k] * i / (count[k] - 1);
      sd[k].push_back(v);
      x[k].push_back(v * v);
    }
  }
  // the limits at the check points of interval k as rows in (x_k, u): from x_k, only
  // the u in u_range(rows, x_k) can meet them, i.e. x_k+1 = x_k + 2 ds u in a band
  std::vector<std::vector<Row>> rows(n - 1);
  for (int k = 0; k + 1 < n; ++k) {
    const double ds = d.nodes[k + 1] - d.nodes[k];
    for (int m = 0; m <= checks; ++m)
      append_rows(d.pts[k][m], pb.limits, 2.0 * ds * m / checks, m, &rows[k]);
  }
  const auto band = [&](int k, int i) {
    const double x0 = x[k][i], ds = d.nodes[k + 1] - d.nodes[k];
    for (const Row& r : rows[k])
      if (r.cu == 0.0 && (r.cx * x0 < r.lo || r.cx * x0 > r.hi)) return std::pair<int, int>(0, 0);
    const URange ur = u_range(rows[k], x0);
    if (ur.lo > ur.hi) return std::pair<int, int>(0, 0);
    const std::vector<double>& next = x[k + 1];
    // one level of slack on each side: the cost function decides exactly
    const double lo = x0 + 2 * ds * ur.lo, hi = x0 + 2 * ds * ur.hi;
    const int first =
        static_cast<int>(std::lower_bound(next.begin(), next.end(), lo) - next.begin()) - 1;
    const int last =
        static_cast<int>(std::upper_bound(next.begin(), next.end(), hi) - next.begin()) + 1;
    return std::pair<int, int>(first, last);
  };
  const core::opt::DpSolution sol =
      reference
          ? core::opt::solve_staged_dp(
                count,
                [&](int k, int i, int j) {
                  return path_speed_cost(pb, d, k, x[k][i], x[k + 1][j], sd[k][i], sd[k + 1][j]);
                },
                band)
          : pruned_recursion(
                count,
                [&](int k, int i, int j) {
                  const double v = sd[k][i] + sd[k + 1][j];
                  return v <= 0 ? kInf : 2 * (d.nodes[k + 1] - d.nodes[k]) / v;
                },
                [&](int k, int i, int j) {
                  return segment_within_limits(d.seg[k], pb.limits, x[k][i], x[k + 1][j]);
                },
                band, [](int) { return true; });
  out.evaluations = sol.evaluations;
  if (!sol.feasible()) {
    out.message =
        "no sequence of the " + std::to_string(levels) +
        " velocity levels per node meets every limit on " + std::to_string(segments) +
        " segments: " +
        dp_failure(
            pb, d, count,
            [&](int k, int i, int j) {
              return std::isfinite(
                  path_speed_cost(pb, d, k, x[k][i], x[k + 1][j], sd[k][i], sd[k + 1][j]));
            },
            [&](int k, int i, int j) { return path_speed_use(pb, d, k, x[k][i], x[k + 1][j]); },
            [&](int k, int i, int j) { return sd[k][i] + sd[k + 1][j] <= 0; }, band) +
        "; more levels or segments may help";
    return out;
  }
  out.profile.law = SegmentLaw::kPathAcceleration;
  out.profile.s = d.nodes;
  for (int k = 0; k < n; ++k) out.profile.sd.push_back(sd[k][sol.states[k]]);
  out.duration = sol.cost;
  out.solved = true;
  return out;
}

// the direction joint 1 moves in along the whole path (+1 or -1); none, with `message`
// set, when it reverses or stops (dq1/ds = 0), where the joint-1 velocity state breaks down
std::optional<double> joint1_direction(const Problem& pb, const Discretisation& d, int checks,
                                       std::string* message) {
  const int n = static_cast<int>(d.nodes.size());
  double sign = 0;
  for (int k = 0; k + 1 < n; ++k) {
    for (int m = 0; m <= checks; ++m) {
      const JointPoint& jp = d.pts[k][m];
      const double v = jp.dq[0];
      const double sg = std::abs(v) < 1e-9 ? 0.0 : (v > 0 ? 1.0 : -1.0);
      if (k == 0 && m == 0) sign = sg;
      if (sg == 0 || sg != sign) {
        *message = "joint 1 reverses (dq1/ds = 0) near " + where(pb, jp.s) +
                   ": the source's joint-1 velocity state cannot describe this path (its "
                   "segment time 2 dq1 / (q1'(k) + q1'(k+1)) breaks down); the path-speed "
                   "state s' can";
        return std::nullopt;
      }
    }
  }
  return sign;
}

// the DP with the joint-1 velocity q1' as its state (the source's): q1' levels on
// [0, qd_max_1] in the direction of motion (over 60 lines, kept whole: the use, cost and
// bound lambdas share the state grid and are passed to the recursion as they are)
SolverOutput dp_joint1(const Problem& pb, const Discretisation& d, const std::vector<int>& count,
                       int segments, int levels, int checks, bool reference) {
  SolverOutput out;
  const int n = static_cast<int>(d.nodes.size());
  // q1 must move one way along the whole path
  const std::optional<double> direction = joint1_direction(pb, d, checks, &out.message);
  if (!direction) return out;
  const double sign = *direction;
  std::vector<double> q1(n), dq1(n);
  for (int k = 0; k < n; ++k) {
    const JointPoint& jp = k + 1 < n ? d.pts[k][0] : d.pts[k - 1][checks];
    q1[k] = jp.q[0];
    dq1[k] = jp.dq[0];
  }
  // q1' levels on [0, qd_max_1] in the direction of motion (the source's state grid)
  std::vector<std::vector<double>> v(n);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < count[k]; ++i)
      v[k].push_back(count[k] == 1 ? 0.0 : sign * pb.limits.velocity[0] * i / (count[k] - 1));
  // the worst limit use of the move from level i at node k to level j at node k+1
  const auto joint1_use = [&](int k, int i, int j) {
    const double v0 = v[k][i], v1 = v[k + 1][j];
    const double dq = q1[k + 1] - q1[k];
    // constant joint-1 acceleration over the joint-1 travel
    const double a1 = (v1 * v1 - v0 * v0) / (2 * dq);
    Use worst;
    for (int m = 0; m <= checks; ++m) {
      const JointPoint& jp = d.pts[k][m];
      const double w2 = std::max(0.0, v0 * v0 + 2 * a1 * (jp.q[0] - q1[k]));
      const double x = w2 / (jp.dq[0] * jp.dq[0]);
      const double u = (a1 - jp.ddq[0] * x) / jp.dq[0];
      worst = max_use(worst, worst_use(jp, pb.limits, x, u));
    }
    return worst;
  };
  const auto joint1_cost = [&](int k, int i, int j) {
    const double v0 = v[k][i], v1 = v[k + 1][j];
    if (v0 + v1 == 0) return kInf;
    const double dq = q1[k + 1] - q1[k];
    const double a1 = (v1 * v1 - v0 * v0) / (2 * dq);
    const auto& pts = d.pts[k];
    for (int m = 0; m <= checks; ++m) {
      const JointPoint& jp = pts[m];
      const double w2 = std::max(0.0, v0 * v0 + 2 * a1 * (jp.q[0] - q1[k]));
      const double x = w2 / (jp.dq[0] * jp.dq[0]);
      const double u = (a1 - jp.ddq[0] * x) / jp.dq[0];
      if (!within_limits(jp, pb.limits, x, u)) return kInf;
    }
    return 2 * dq / (v0 + v1);
  };
  const auto every = [&](int k, int) { return std::pair<int, int>(0, count[k + 1]); };
  const core::opt::DpSolution sol =
      reference
          ? core::opt::solve_staged_dp(count, joint1_cost)
          : pruned_recursion(
                count,
                [&](int k, int i, int j) {
                  const double v0 = v[k][i], v1 = v[k + 1][j];
                  return v0 + v1 == 0 ? kInf : 2 * (q1[k + 1] - q1[k]) / (v0 + v1);
                },
                [&](int k, int i, int j) { return std::isfinite(joint1_cost(k, i, j)); }, every,
                // the levels run towards the motion: the time falls with j when joint 1
                // moves that way over the segment
                [&](int k) { return sign * (q1[k + 1] - q1[k]) > 0; });
  out.evaluations = sol.evaluations;
  if (!sol.feasible()) {
    out.message =
        "no sequence of the " + std::to_string(levels) +
        " joint-1 velocity levels meets every limit on " + std::to_string(segments) +
        " segments: " +
        dp_failure(
            pb, d, count, [&](int k, int i, int j) { return std::isfinite(joint1_cost(k, i, j)); },
            joint1_use, [&](int k, int i, int j) { return v[k][i] + v[k + 1][j] == 0; },
            [&](int k, int) { return std::pair<int, int>(0, count[k + 1]); }) +
        "; more levels or segments may help";
    return out;
  }
  out.profile.law = SegmentLaw::kJoint1Acceleration;
  out.profile.s = d.nodes;
  for (int k = 0; k < n; ++k) {
    out.profile.qd1.push_back(v[k][sol.states[k]]);
    out.profile.sd.push_back(std::abs(v[k][sol.states[k]] / dq1[k]));
  }
  out.duration = sol.cost;
  out.solved = true;
  return out;
}

SolverOutput dp(const Problem& pb, int segments, int levels, int checks, DpState state,
                bool reference) {
  const Discretisation d = discretise(pb, segments, checks);
  const int n = static_cast<int>(d.nodes.size());
  std::vector<int> count(n);
  for (int k = 0; k < n; ++k) count[k] = d.rest[k] ? 1 : levels;
  return state == DpState::kPathSpeed
             ? dp_path_speed(pb, d, count, segments, levels, checks, reference)
             : dp_joint1(pb, d, count, segments, levels, checks, reference);
}

}  // namespace

SolverOutput solve_dp(const Problem& pb, int segments, int levels, int checks, DpState state) {
  return dp(pb, segments, levels, checks, state, false);
}

SolverOutput solve_dp_reference(const Problem& pb, int segments, int levels, int checks,
                                DpState state) {
  return dp(pb, segments, levels, checks, state, true);
}

namespace {
// why the Complex method has no start: the first segment the slowest crawl tried (speeds
// sd, at most `top`, after `halvings` halvings) cannot cross, and its worst limit
std::string no_crawl_message(const Problem& pb, const Discretisation& d,
                             const std::vector<double>& sd, double top, int halvings) {
  const int n = static_cast<int>(d.nodes.size());
  std::ostringstream os;
  os.precision(3);
  os << "the Complex method found no feasible crawl to start from: even at " << top << " "
     << pb.path.unit() << "/s at most (2^-" << std::min(halvings, 60) + 1
     << " of the maximum velocity curve)";
  for (int k = 0; k + 1 < n; ++k) {
    if (std::isfinite(
            path_speed_cost(pb, d, k, sd[k] * sd[k], sd[k + 1] * sd[k + 1], sd[k], sd[k + 1])))
      continue;
    if (sd[k] + sd[k + 1] <= 0) {
      // the maximum velocity curve is 0 at both ends: no speed, not even rest, is allowed
      const Use at_rest = path_speed_use(pb, d, k, 0.0, 0.0);
      os << ", " << segment_text(pb, d, k) << " allows no speed";
      if (at_rest.excess > 0)
        os << ": even at rest it breaks " << use_text(at_rest, pb.limits, pb.path.unit());
    } else {
      os << ", " << segment_text(pb, d, k) << " breaks "
         << use_text(path_speed_use(pb, d, k, sd[k] * sd[k], sd[k + 1] * sd[k + 1]), pb.limits,
                     pb.path.unit());
    }
    break;
  }
  return os.str();
}

// Box's Complex method on the node speeds in [lo, hi] from z0, minimising `time` (infinite
// where a limit breaks). A complex collapses onto the constraint boundary it first meets (Box
// 1965 restarts it): restarted from the best point with fresh random points until a restart
// gains nothing; the evaluations, iterations and restarts are added to out.
template <typename Time>
core::opt::ComplexResult restarted_complex(const Time& time, const Eigen::VectorXd& lo,
                                           const Eigen::VectorXd& hi, Eigen::VectorXd z0,
                                           const ComplexSettings& settings, SolverOutput& out) {
  core::opt::ComplexOptions opt;
  opt.max_iterations = settings.max_iterations;
  opt.tolerance = settings.tolerance;
  opt.seed = settings.seed;
  core::opt::ComplexResult r;
  for (int restart = 0; restart <= kComplexRestarts; ++restart) {
    opt.seed = settings.seed + restart;
    // (box_complex asks whether a point is feasible and then its time: the time of the last
    // point asked is kept, the same number)
    Eigen::VectorXd last_z;
    double last_t = kInf;
    const auto timed = [&](const Eigen::VectorXd& z) {
      if (last_z.size() != z.size() || last_z != z) {
        last_t = time(z);
        last_z = z;
      }
      return last_t;
    };
    const core::opt::ComplexResult next = core::opt::box_complex(
        [&](const Eigen::VectorXd& z) { return timed(z); },
        [&](const Eigen::VectorXd& z) { return std::isfinite(timed(z)); }, lo, hi, z0, opt);
    out.evaluations += next.evaluations;
    out.iterations += next.iterations;
    const bool gained = restart == 0 || next.f < r.f * (1 - kRestartGain);
    if (restart == 0 || next.f < r.f) r = next;
    out.restarts = restart;
    if (!gained) break;
    z0 = r.x;
  }
  return r;
}
}  // namespace

SolverOutput solve_complex(const Problem& pb, int segments, int checks,
                           const ComplexSettings& settings) {
  SolverOutput out;
  const Discretisation d = discretise(pb, segments, checks);
  const int n = static_cast<int>(d.nodes.size());
  std::vector<int> var;  // node of each variable
  for (int k = 0; k < n; ++k)
    if (!d.rest[k]) var.push_back(k);
  const int nv = static_cast<int>(var.size());
  const auto speeds = [&](const Eigen::VectorXd& z) {
    std::vector<double> sd(n, 0.0);
    for (int i = 0; i < nv; ++i) sd[var[i]] = z[i];
    return sd;
  };
  const auto total_time = [&](const std::vector<double>& sd) {
    double t = 0;
    for (int k = 0; k + 1 < n; ++k) {
      const double c =
          path_speed_cost_flat(pb, d, k, sd[k] * sd[k], sd[k + 1] * sd[k + 1], sd[k], sd[k + 1]);
      if (!std::isfinite(c)) return kInf;
      t += c;
    }
    return t;
  };
  if (nv == 0) {
    // every node is a rest node: nothing to optimise, the profile is fixed
    out.profile.s = d.nodes;
    out.profile.sd.assign(n, 0.0);
    out.message = "every node is a rest node: no interval can be crossed";
    return out;
  }
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(nv), hi(nv);
  for (int i = 0; i < nv; ++i) hi[i] = d.mvc[var[i]];
  // a feasible crawl to start from
  Eigen::VectorXd z0 = 0.5 * hi;
  int halvings = 0;
  while (!std::isfinite(total_time(speeds(z0))) && halvings++ < 60) z0 *= 0.5;
  if (!std::isfinite(total_time(speeds(z0)))) {
    out.message = no_crawl_message(pb, d, speeds(z0), z0.maxCoeff(), halvings);
    return out;
  }
  const core::opt::ComplexResult r = restarted_complex(
      [&](const Eigen::VectorXd& z) { return total_time(speeds(z)); }, lo, hi, z0, settings, out);
  out.profile.law = SegmentLaw::kPathAcceleration;
  out.profile.s = d.nodes;
  out.profile.sd = speeds(r.x);
  out.duration = r.f;
  out.solved = true;
  if (!r.converged)
    out.message = "the Complex method stopped after " + std::to_string(r.iterations) +
                  " reflections before its spread criterion was met";
  return out;
}

}  // namespace armstudy::studies::time_optimal
