// exact solver: reachability analysis (backward controllable sets, greedy forward pass)
#include <algorithm>
#include <cmath>
#include <sstream>

#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string place(const Problem& pb, double s, int node, int nodes) {
  std::ostringstream os;
  os << pb.where(s) << " (grid point " << node << " of " << nodes << ")";
  return os.str();
}
}  // namespace

void max_velocity_curve(const Problem& pb, const std::vector<double>& nodes,
                        std::vector<double>* sd_all, std::vector<double>* sd_velocity) {
  sd_all->assign(nodes.size(), 0.0);
  sd_velocity->assign(nodes.size(), 0.0);
  std::vector<Row> rows;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const JointPoint jp = pb.at(nodes[k], k + 1 == nodes.size());
    rows.clear();
    append_rows(jp, pb.limits, 0.0, static_cast<int>(k), &rows);
    const XInterval xi = feasible_x(rows);
    (*sd_all)[k] = xi.empty() ? 0.0 : std::sqrt(std::max(0.0, xi.hi));
    double v = kInf;
    for (int j = 0; j < pb.limits.joints(); ++j)
      if (jp.dq[j] != 0) v = std::min(v, pb.limits.velocity[j] / std::abs(jp.dq[j]));
    (*sd_velocity)[k] = v;
  }
}

SolverOutput solve_exact(const Problem& pb, const std::vector<double>& nodes, int checks) {
  SolverOutput out;
  const int n = static_cast<int>(nodes.size());
  const int N = n - 1;
  const auto pts = interval_points(pb, nodes, checks);
  const std::vector<bool> rest = rest_nodes(pb.path, nodes);

  // rows of every interval in (x_i, u), limits at theta = m / checks
  std::vector<std::vector<Row>> rows(N);
  for (int k = 0; k < N; ++k) {
    const double ds = nodes[k + 1] - nodes[k];
    rows[k].reserve((checks + 1) * 6 + 1);
    for (int m = 0; m <= checks; ++m)
      append_rows(pts[k][m], pb.limits, 2.0 * ds * m / checks, k, &rows[k]);
  }

  // backward pass: controllable sets, K_N = {0}
  std::vector<double> klo(n, 0.0), khi(n, 0.0);
  std::vector<RowTag> khi_tag(n);
  for (int k = N - 1; k >= 0; --k) {
    const double ds = nodes[k + 1] - nodes[k];
    // x_i + 2 ds u in K_i+1
    rows[k].push_back({1.0, 2.0 * ds, klo[k + 1], khi[k + 1], RowTag{-1, LimitKind::kVelocity, k + 1, nodes[k + 1]}});
    const XInterval xi = feasible_x(rows[k]);
    rows[k].pop_back();
    const double tol = 1e-12 * std::max(1.0, std::abs(xi.hi));
    if (xi.lo > xi.hi + tol || (rest[k] && xi.lo > tol)) {
      std::ostringstream os;
      // the upper and the lower bound that cross (or, at a rest node, the lower bound)
      const bool crossed = xi.lo > xi.hi + tol;
      const RowTag& a = crossed ? xi.hi_tag : xi.lo_tag;
      const RowTag& b = crossed ? xi.lo_tag : xi.lo_tag2;
      os << "no speed meets the limits near " << place(pb, nodes[k], k, n) << ": "
         << describe(a, pb.limits, pb.path.unit());
      if (b.joint != a.joint || b.kind != a.kind || b.s != a.s)
        os << " conflicts with " << describe(b, pb.limits, pb.path.unit());
      if (rest[k] && xi.lo <= xi.hi + tol)
        os << " (the arm must be at rest there, but the limits need s'^2 >= " << xi.lo << " m^2/s^2)";
      out.message = os.str();
      return out;
    }
    klo[k] = rest[k] ? 0.0 : std::max(0.0, xi.lo);
    khi[k] = rest[k] ? 0.0 : std::max(klo[k], xi.hi);
    khi_tag[k] = xi.hi_tag;
  }

  // forward pass: greedy largest u, x_0 = 0
  std::vector<double> x(n, 0.0);
  for (int k = 0; k < N; ++k) {
    const double ds = nodes[k + 1] - nodes[k];
    const URange ur = u_range(rows[k], x[k]);
    double u = std::min(ur.hi, (khi[k + 1] - x[k]) / (2 * ds));
    double next = std::clamp(x[k] + 2 * ds * u, klo[k + 1], khi[k + 1]);
    x[k + 1] = std::max(0.0, next);
    if (x[k] <= 0 && x[k + 1] <= 0) {
      // two consecutive rests: the limits hold the arm still; name the one that binds
      RowTag tag = ur.hi_tag;
      if (!(ur.hi <= (khi[k + 1] - x[k]) / (2 * ds))) tag = khi_tag[k + 1];
      out.message = "the limits hold the arm at rest near " + place(pb, nodes[k], k, n) +
                    ": " + describe(tag, pb.limits, pb.path.unit()) +
                    " allows no motion there, so the path cannot be traversed in finite time";
      return out;
    }
  }
  out.profile.law = SegmentLaw::kPathAcceleration;
  out.profile.s = nodes;
  out.profile.sd.resize(n);
  for (int k = 0; k < n; ++k) out.profile.sd[k] = std::sqrt(x[k]);
  out.duration = profile_duration(pb, out.profile);
  out.solved = std::isfinite(out.duration);
  if (!out.solved) out.message = "the exact profile has an infinite duration";
  return out;
}

}  // namespace armstudy::studies::time_optimal
