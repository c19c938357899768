// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/phase.hpp"

#include <cmath>
#include <sstream>

namespace armstudy::studies::time_optimal {
namespace {
constexpr double kPhaseInf = std::numeric_limits<double>::infinity();

// one bound on u, affine in x: u >= p + r x (lower) or u <= p + r x (upper)
struct Line {
  double p, r;
  const RowTag* tag;
};
}  // namespace

const char* limit_name(LimitKind kind) {
  switch (kind) {
    case LimitKind::kVelocity: return "velocity";
    case LimitKind::kTorque: return "torque";
    case LimitKind::kAcceleration: return "acceleration";
  }
  return "?";
}

const char* limit_unit(LimitKind kind) {
  switch (kind) {
    case LimitKind::kVelocity: return "rad/s";
    case LimitKind::kTorque: return "N m";
    case LimitKind::kAcceleration: return "rad/s^2";
  }
  return "?";
}

double Limits::of(LimitKind kind, int joint) const {
  switch (kind) {
    case LimitKind::kVelocity: return velocity[joint];
    case LimitKind::kTorque: return torque[joint];
    case LimitKind::kAcceleration: return acceleration ? (*acceleration)[joint] : kPhaseInf;
  }
  return kPhaseInf;
}

void append_rows(const JointPoint& jp, const Limits& lim, double shift, int point,
                 std::vector<Row>* rows) {
  // a quantity cx x(jp) + cu u with x(jp) = x_i + shift u reads cx x_i + (cu + shift cx) u
  const auto add = [&](double cx, double cu, double lo, double hi, int j, LimitKind k) {
    rows->push_back({cx, cu + shift * cx, lo, hi, RowTag{j, k, point, jp.s}});
  };
  const int n = static_cast<int>(jp.dq.size());
  for (int j = 0; j < n; ++j) {
    add(jp.dq[j] * jp.dq[j], 0.0, -kPhaseInf, lim.velocity[j] * lim.velocity[j], j,
        LimitKind::kVelocity);
    add(jp.b[j], jp.a[j], -lim.torque[j] - jp.c[j], lim.torque[j] - jp.c[j], j, LimitKind::kTorque);
    if (lim.acceleration)
      add(jp.ddq[j], jp.dq[j], -(*lim.acceleration)[j], (*lim.acceleration)[j], j,
          LimitKind::kAcceleration);
  }
}

// (over 60 lines, kept whole: one pass over the rows of a two-variable LP, each case of a
// row's signs beside the others)
XInterval feasible_x(const std::vector<Row>& rows) {
  XInterval out;
  Line lower[64], upper[64];
  int nl = 0, nu = 0;
  std::vector<Line> lower_big, upper_big;
  const bool big = rows.size() > 64;
  const auto push = [&](bool is_upper, Line l) {
    if (big) {
      (is_upper ? upper_big : lower_big).push_back(l);
    } else if (is_upper) {
      upper[nu++] = l;
    } else {
      lower[nl++] = l;
    }
  };
  const auto bound_x = [&](double v, bool is_upper, const RowTag& t, const RowTag& t2) {
    if (is_upper && v < out.hi) {
      out.hi = v;
      out.hi_tag = t;
      out.hi_tag2 = t2;
    } else if (!is_upper && v > out.lo) {
      out.lo = v;
      out.lo_tag = t;
      out.lo_tag2 = t2;
    }
  };
  for (const Row& r : rows) {
    if (r.cu == 0.0) {
      // a bound on x alone
      if (r.cx > 0) {
        if (std::isfinite(r.hi)) bound_x(r.hi / r.cx, true, r.tag, r.tag);
        if (std::isfinite(r.lo)) bound_x(r.lo / r.cx, false, r.tag, r.tag);
      } else if (r.cx < 0) {
        if (std::isfinite(r.hi)) bound_x(r.hi / r.cx, false, r.tag, r.tag);
        if (std::isfinite(r.lo)) bound_x(r.lo / r.cx, true, r.tag, r.tag);
      } else if (r.lo > 1e-12 * std::max(1.0, std::abs(r.lo)) || r.hi < -1e-12) {
        out.lo = 1;
        out.hi = 0;
        out.lo_tag = out.hi_tag = out.lo_tag2 = out.hi_tag2 = r.tag;
        return out;
      }
      continue;
    }
    // cu u in [lo - cx x, hi - cx x]
    const double inv = 1.0 / r.cu;
    const bool pos = r.cu > 0;
    if (std::isfinite(r.hi)) push(pos, Line{r.hi * inv, -r.cx * inv, &r.tag});
    if (std::isfinite(r.lo)) push(!pos, Line{r.lo * inv, -r.cx * inv, &r.tag});
  }
  const Line* L = big ? lower_big.data() : lower;
  const Line* U = big ? upper_big.data() : upper;
  if (big) {
    nl = static_cast<int>(lower_big.size());
    nu = static_cast<int>(upper_big.size());
  }
  // every pair: p_L + r_L x <= p_U + r_U x
  for (int a = 0; a < nl; ++a) {
    for (int b = 0; b < nu; ++b) {
      const double d = L[a].r - U[b].r, g = U[b].p - L[a].p;
      if (d > 0) {
        bound_x(g / d, true, *L[a].tag, *U[b].tag);
      } else if (d < 0) {
        bound_x(g / d, false, *L[a].tag, *U[b].tag);
      } else if (g < -1e-12 * std::max({1.0, std::abs(L[a].p), std::abs(U[b].p)})) {
        out.lo = 1;
        out.hi = 0;
        out.lo_tag = out.hi_tag = *L[a].tag;
        out.lo_tag2 = out.hi_tag2 = *U[b].tag;
        return out;
      }
    }
  }
  return out;
}

URange u_range(const std::vector<Row>& rows, double x) {
  URange out;
  for (const Row& r : rows) {
    if (r.cu == 0.0) continue;
    const double inv = 1.0 / r.cu;
    double a = (r.lo - r.cx * x) * inv, b = (r.hi - r.cx * x) * inv;
    if (r.cu < 0) std::swap(a, b);
    if (b < out.hi) {
      out.hi = b;
      out.hi_tag = r.tag;
    }
    if (a > out.lo) {
      out.lo = a;
      out.lo_tag = r.tag;
    }
  }
  return out;
}

std::string describe(const RowTag& tag, const Limits& limits, const char* unit) {
  std::ostringstream os;
  if (tag.joint < 0) {
    os << "the need to stop at the end of the path (from s = ";
    os.setf(std::ios::fixed);
    os.precision(3);
    os << tag.s << " " << unit << ")";
    return os.str();
  }
  os << "the joint " << tag.joint + 1 << " " << limit_name(tag.kind) << " limit ";
  os << limits.of(tag.kind, tag.joint) << " " << limit_unit(tag.kind);
  os.setf(std::ios::fixed);
  os.precision(3);
  os << " at s = " << tag.s << " " << unit;
  return os.str();
}

}  // namespace armstudy::studies::time_optimal
