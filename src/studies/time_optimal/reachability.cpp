// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// exact solver: reachability analysis (backward controllable sets, greedy forward pass)
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <sstream>

#include "core/check.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr double kReachInf = std::numeric_limits<double>::infinity();

std::string place(const Problem& pb, double s, int node, int nodes) {
  std::ostringstream os;
  os << pb.where(s) << " (grid point " << node << " of " << nodes << ")";
  return os.str();
}
}  // namespace

SolverOutput solve_exact_reference(const Problem& pb, const std::vector<double>& nodes,
                                   int checks) {
  ARM_THROW_UNLESS(checks >= 1, "checks per interval " << checks << " should be >= 1");
  return solve_exact_reference(pb, nodes, std::vector<int>(nodes.size() - 1, checks));
}

// (over 60 lines, kept whole: the reference solve with tagged rows that words every failure,
// the plain form the fast solve_exact is tested against)
SolverOutput solve_exact_reference(const Problem& pb, const std::vector<double>& nodes,
                                   const std::vector<int>& checks_per) {
  SolverOutput out;
  const int n = static_cast<int>(nodes.size());
  const int N = n - 1;
  const auto pts = interval_points(pb, nodes, checks_per);
  const std::vector<bool> rest = rest_nodes(pb.path, nodes);

  // rows of every interval in (x_i, u), limits at theta = m / checks
  std::vector<std::vector<Row>> rows(N);
  for (int k = 0; k < N; ++k) {
    const int checks = checks_per[k];
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
    rows[k].push_back({1.0, 2.0 * ds, klo[k + 1], khi[k + 1],
                       RowTag{-1, LimitKind::kVelocity, k + 1, nodes[k + 1]}});
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
        os << " (the arm must be at rest there, but the limits need s'^2 >= " << xi.lo << " "
           << pb.path.unit() << "^2/s^2)";
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
      out.message = "the limits hold the arm at rest near " + place(pb, nodes[k], k, n) + ": " +
                    describe(tag, pb.limits, pb.path.unit()) +
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

namespace {
// solve_exact's rows without their tags: lo <= cx x + cu u <= hi
struct Coef {
  double cx, cu, lo, hi;
};
// a bound on u, affine in x (phase.cpp's Line without its tag)
struct Ln {
  double p, r;
};

// The arrays of solve_exact, kept between solves of a thread so that a solve allocates
// nothing once they have grown.
struct ExactWorkspace {
  std::vector<Coef> rows;     // every interval's rows
  std::vector<size_t> start;  // interval k's rows begin at rows[start[k]]
  std::vector<int> count;     // rows used per interval
  std::vector<double> klo, khi, x;
  std::vector<unsigned char> rest;
  std::vector<Ln> lower, upper;
  JointPoint buf[2], cur;
};

// append_rows without tags (the same values in the same order)
inline int add_rows(const JointPoint& jp, const Limits& lim, double shift, Coef* out) {
  int n = 0;
  const auto add = [&](double cx, double cu, double lo, double hi) {
    out[n++] = Coef{cx, cu + shift * cx, lo, hi};
  };
  const int nj = static_cast<int>(jp.dq.size());
  for (int j = 0; j < nj; ++j) {
    add(jp.dq[j] * jp.dq[j], 0.0, -kReachInf, lim.velocity[j] * lim.velocity[j]);
    add(jp.b[j], jp.a[j], -lim.torque[j] - jp.c[j], lim.torque[j] - jp.c[j]);
    if (lim.acceleration) add(jp.ddq[j], jp.dq[j], -(*lim.acceleration)[j], (*lim.acceleration)[j]);
  }
  return n;
}

// add_rows from a point's numbers as ExactPointCache keeps them (q', q'', a, b, c)
inline int add_rows(const double* p, int nj, const Limits& lim, double shift, Coef* out) {
  int n = 0;
  const auto add = [&](double cx, double cu, double lo, double hi) {
    out[n++] = Coef{cx, cu + shift * cx, lo, hi};
  };
  const std::ptrdiff_t m = nj;  // (the offsets in the pointers' type)
  const double *dq = p, *ddq = p + m, *a = p + 2 * m, *b = p + 3 * m, *c = p + 4 * m;
  for (int j = 0; j < nj; ++j) {
    add(dq[j] * dq[j], 0.0, -kReachInf, lim.velocity[j] * lim.velocity[j]);
    add(b[j], a[j], -lim.torque[j] - c[j], lim.torque[j] - c[j]);
    if (lim.acceleration) add(ddq[j], dq[j], -(*lim.acceleration)[j], (*lim.acceleration)[j]);
  }
  return n;
}

// feasible_x of rows[0..n) and the extra row `last`, without tags: the same bounds (every
// candidate is the same quotient; min and max do not depend on the order)
struct XRange {
  double lo = 0, hi = kReachInf;
};
// true when g - bound d > 0 in exact arithmetic, shown without the division g / d: then the
// quotient g / d lies beyond `bound` (above it for d > 0, below it for d < 0), and so does its
// rounding, which can tighten neither bound. fl(g - fl(bound d)) over 2^-50 of |fl(bound d)|
// (plus a floor for underflow) exceeds the rounding of both operations (2^-53 each), so the
// exact difference is positive; otherwise (near ties, an infinite bound, NaN) it is false and
// the quotient is computed as before: the bounds are the same numbers.
inline bool beyond(double g, double d, double bound) {
  const double p = bound * d;
  return g - p > 0x1p-50 * std::abs(p) + 1e-300;
}

// the bounds on x where each lower bound on u meets each upper one (into out); false when
// two parallel ones leave no u
bool pair_bounds(const Ln* L, int nl, const Ln* U, int nu, XRange& out) {
  for (int a = 0; a < nl; ++a) {
    for (int b = 0; b < nu; ++b) {
      const double d = L[a].r - U[b].r, g = U[b].p - L[a].p;
      if (d > 0) {
        if (beyond(g, d, out.hi)) continue;  // (g / d > out.hi: no new bound)
        const double v = g / d;
        if (v < out.hi) out.hi = v;
      } else if (d < 0) {
        if (beyond(g, d, out.lo)) continue;  // (g / d < out.lo: no new bound)
        const double v = g / d;
        if (v > out.lo) out.lo = v;
      } else if (g < -1e-12 * std::max({1.0, std::abs(L[a].p), std::abs(U[b].p)})) {
        return false;
      }
    }
  }
  return true;
}

// (the exact solver's innermost loop over the rows of one interval, per grid point of every
// solve)
XRange feasible_x_fast(const Coef* rows, int n, const Coef& last, ExactWorkspace& ws) {
  XRange out;
  const size_t most = 2 * static_cast<size_t>(n + 1);
  if (ws.lower.size() < most) {
    ws.lower.resize(most);
    ws.upper.resize(most);
  }
  Ln* L = ws.lower.data();
  Ln* U = ws.upper.data();
  int nl = 0, nu = 0;
  const auto take = [&](const Coef& r) {
    if (r.cu == 0.0) {
      if (r.cx > 0) {
        if (std::isfinite(r.hi)) {
          const double v = r.hi / r.cx;
          if (v < out.hi) out.hi = v;
        }
        if (std::isfinite(r.lo)) {
          const double v = r.lo / r.cx;
          if (v > out.lo) out.lo = v;
        }
      } else if (r.cx < 0) {
        if (std::isfinite(r.hi)) {
          const double v = r.hi / r.cx;
          if (v > out.lo) out.lo = v;
        }
        if (std::isfinite(r.lo)) {
          const double v = r.lo / r.cx;
          if (v < out.hi) out.hi = v;
        }
      } else if (r.lo > 1e-12 * std::max(1.0, std::abs(r.lo)) || r.hi < -1e-12) {
        return false;
      }
      return true;
    }
    const double inv = 1.0 / r.cu;
    const double slope = -r.cx * inv;
    if (r.cu > 0) {
      if (std::isfinite(r.hi)) U[nu++] = Ln{r.hi * inv, slope};
      if (std::isfinite(r.lo)) L[nl++] = Ln{r.lo * inv, slope};
    } else {
      if (std::isfinite(r.hi)) L[nl++] = Ln{r.hi * inv, slope};
      if (std::isfinite(r.lo)) U[nu++] = Ln{r.lo * inv, slope};
    }
    return true;
  };
  for (int i = 0; i < n; ++i)
    if (!take(rows[i])) return XRange{1, 0};
  if (!take(last)) return XRange{1, 0};
  if (!pair_bounds(L, nl, U, nu, out)) return XRange{1, 0};
  return out;
}

// u_range(rows, x).hi without tags
double u_hi_fast(const Coef* rows, int n, double x) {
  double hi = kReachInf;
  for (int i = 0; i < n; ++i) {
    const Coef& r = rows[i];
    if (r.cu == 0.0) continue;
    const double inv = 1.0 / r.cu;
    const double b = (r.cu < 0 ? r.lo - r.cx * x : r.hi - r.cx * x) * inv;
    if (b < hi) hi = b;
  }
  return hi;
}
}  // namespace

void max_velocity_curve(const Problem& pb, const std::vector<double>& nodes,
                        std::vector<double>* sd_all, std::vector<double>* sd_velocity,
                        const ExactPointCache* cache) {
  sd_all->assign(nodes.size(), 0.0);
  sd_velocity->assign(nodes.size(), 0.0);
  thread_local ExactWorkspace ws;
  const PointSource source(pb);
  const Coef none{0.0, 0.0, -kReachInf, kReachInf};  // no extra row
  ws.rows.resize(static_cast<size_t>(pb.limits.joints()) * 3);
  for (size_t k = 0; k < nodes.size(); ++k) {
    const int nj = pb.limits.joints();
    const double* known = cache ? cache->find(nodes[k], k + 1 == nodes.size()) : nullptr;
    int c;
    if (known) {
      c = add_rows(known, nj, pb.limits, 0.0, ws.rows.data());
    } else {
      source.at(nodes[k], k + 1 == nodes.size(), &ws.cur);
      c = add_rows(ws.cur, pb.limits, 0.0, ws.rows.data());
    }
    const double* dq = known ? known : ws.cur.dq.data();
    const XRange xi = feasible_x_fast(ws.rows.data(), c, none, ws);
    (*sd_all)[k] = xi.lo > xi.hi ? 0.0 : std::sqrt(std::max(0.0, xi.hi));
    double v = kReachInf;
    for (int j = 0; j < nj; ++j)
      if (dq[j] != 0) v = std::min(v, pb.limits.velocity[j] / std::abs(dq[j]));
    (*sd_velocity)[k] = v;
  }
}

SolverOutput solve_exact(const Problem& pb, const std::vector<double>& nodes, int checks) {
  ARM_THROW_UNLESS(checks >= 1, "checks per interval " << checks << " should be >= 1");
  return solve_exact(pb, nodes, std::vector<int>(nodes.size() - 1, checks));
}

ExactPointCache::ExactPointCache(const Problem& problem) : joints_(problem.limits.joints()) {
  if (!problem.path.joint_space()) path_ = &problem.path.tip();
}

const double* ExactPointCache::find(double s, bool from_left) const {
  if (!path_) return nullptr;
  // a solve asks in increasing s: start after the last answer's place when it lies below s
  // (every entry up to it does), a few steps on, then the binary search
  size_t i = hint_ < index_.size() && index_[hint_].s < s ? hint_ + 1 : 0;
  for (int step = 0; step < 4 && i < index_.size() && index_[i].s < s; ++step) ++i;
  if (i < index_.size() && index_[i].s < s)
    i = static_cast<size_t>(std::lower_bound(index_.begin() + i, index_.end(), s,
                                             [](const Entry& e, double v) { return e.s < v; }) -
                            index_.begin());
  hint_ = i;
  auto it = index_.begin() + static_cast<std::ptrdiff_t>(i);
  for (; it != index_.end() && it->s == s; ++it)
    if (same_point(s, from_left, it->s, it->from_left)) return coef_.data() + it->at;
  return nullptr;
}

void ExactPointCache::reserve(size_t points) {
  if (!path_) return;
  fresh_.reserve(fresh_.size() + points);
  coef_.reserve(coef_.size() + points * static_cast<size_t>(stride()));
}

void ExactPointCache::add(const JointPoint& p, bool from_left) {
  if (!path_) return;
  const size_t at = coef_.size();
  fresh_.push_back({p.s, from_left, at});
  coef_.resize(at + static_cast<size_t>(stride()));
  double* out = coef_.data() + at;
  for (const core::JointVector* v : {&p.dq, &p.ddq, &p.a, &p.b, &p.c}) {
    const double* in = v->data();
    for (int j = 0; j < joints_; ++j) *out++ = in[j];
  }
}

void ExactPointCache::merge() {
  std::vector<Entry> all(index_.size() + fresh_.size());
  std::merge(index_.begin(), index_.end(), fresh_.begin(), fresh_.end(), all.begin(),
             [](const Entry& a, const Entry& b) { return a.s < b.s; });
  index_.swap(all);
  fresh_.clear();
}

void ExactPointCache::absorb(const ExactPointCache& other) {
  if (!path_) return;
  fresh_.reserve(fresh_.size() + other.index_.size());
  coef_.reserve(coef_.size() + other.coef_.size());
  for (const Entry& e : other.index_) {
    const size_t at = coef_.size();
    fresh_.push_back({e.s, e.from_left, at});
    coef_.insert(coef_.end(), other.coef_.begin() + static_cast<std::ptrdiff_t>(e.at),
                 other.coef_.begin() + static_cast<std::ptrdiff_t>(e.at + stride()));
  }
}

bool ExactPointCache::same_point(double s, bool from_left, double s2, bool from_left2) const {
  return s == s2 && (from_left == from_left2 || !path_->joins_pieces(s));
}

namespace {
// Where solve_exact evaluates the points of `nodes` with checks[k] check points in interval k,
// in its order (increasing s): at m = checks the interval's end, from the left; at m = 0 of
// an interval after the first the end of the one before, taken again, except at a stop.
struct SolverPointAt {
  double s;
  bool from_left;
};
inline double check_point_s(const std::vector<double>& nodes, int k, int m, int checks) {
  const double ds = nodes[k + 1] - nodes[k];
  return m == checks ? nodes[k + 1] : nodes[k] + ds * m / checks;
}
inline bool is_stop(const std::vector<double>& stops, double s) {
  return std::find(stops.begin(), stops.end(), s) != stops.end();
}
std::vector<SolverPointAt> solver_points(const std::vector<double>& nodes,
                                         const std::vector<int>& checks,
                                         const std::vector<double>& stops) {
  std::vector<SolverPointAt> out;
  for (size_t k = 0; k + 1 < nodes.size(); ++k)
    for (int m = 0; m <= checks[k]; ++m) {
      if (m == 0 && k > 0 && !is_stop(stops, nodes[k])) continue;
      out.push_back({check_point_s(nodes, static_cast<int>(k), m, checks[k]), m == checks[k]});
    }
  return out;
}
}  // namespace

void prefetch_points(const Problem& pb, const std::vector<double>& nodes,
                     const std::vector<int>& checks, const std::vector<double>& known_nodes,
                     const std::vector<int>& known_checks, ExactPointCache* cache) {
  if (!cache->active()) return;
  const auto& stops = pb.path.stops();
  const std::vector<SolverPointAt> want = solver_points(nodes, checks, stops);
  const std::vector<SolverPointAt> known = solver_points(known_nodes, known_checks, stops);
  const PointSource source(pb);
  cache->reserve(want.size());
  JointPoint jp;
  size_t i = 0;  // known[i] is the first with s >= the wanted point's (both in increasing s)
  for (const SolverPointAt& w : want) {
    while (i < known.size() && known[i].s < w.s) ++i;
    bool have = false;
    for (size_t j = i; j < known.size() && known[j].s == w.s && !have; ++j)
      have = cache->same_point(w.s, w.from_left, known[j].s, known[j].from_left);
    if (have) continue;
    try {
      source.solver_at(w.s, w.from_left, &jp);
    } catch (const std::exception&) {
      continue;  // (the solve meets it again and says why)
    }
    cache->add(jp, w.from_left);
  }
  cache->merge();
}

namespace {
// the workspace's row offsets (checks_per[k] + 1 points of nj kinds of limits per interval),
// its arrays and the rest nodes (the ends and the path's stops)
void size_workspace(const Problem& pb, const std::vector<double>& nodes,
                    const std::vector<int>& checks_per, ExactWorkspace& ws) {
  const int n = static_cast<int>(nodes.size());
  const int N = n - 1;
  const int nj = pb.limits.joints();
  const int kinds = pb.limits.acceleration ? 3 : 2;
  ws.start.resize(N + 1);
  ws.start[0] = 0;
  for (int k = 0; k < N; ++k) {
    ARM_THROW_UNLESS(checks_per[k] >= 1,
                     "checks per interval " << checks_per[k] << " should be >= 1");
    ws.start[k + 1] = ws.start[k] + static_cast<size_t>(checks_per[k] + 1) * nj * kinds;
  }
  ws.rows.resize(ws.start[N]);
  ws.count.assign(N, 0);
  ws.klo.assign(n, 0.0);
  ws.khi.assign(n, 0.0);
  ws.x.assign(n, 0.0);
  ws.rest.assign(n, 0);
  ws.rest.front() = ws.rest.back() = 1;
  const auto& stops = pb.path.stops();
  for (double st : stops)
    for (int k = 0; k < n; ++k)
      if (nodes[k] == st) ws.rest[k] = 1;
}

// rows of every interval in (x_i, u), limits at theta = m / checks (interval_points'
// points: the first point of an interval is the last of the one before, except at a stop)
void fill_rows(const Problem& pb, const std::vector<double>& nodes,
               const std::vector<int>& checks_per, ExactPointCache* cache, ExactWorkspace& ws) {
  const int N = static_cast<int>(nodes.size()) - 1;
  const int nj = pb.limits.joints();
  const int kinds = pb.limits.acceleration ? 3 : 2;
  const auto& stops = pb.path.stops();
  const PointSource source(pb);
  if (cache) cache->reserve(ws.start[N] / (static_cast<size_t>(nj) * kinds));  // (every point)
  const JointPoint* prev = nullptr;    // the last point of the interval before, or its
  const double* prev_known = nullptr;  // numbers from the cache
  int next = 0;                        // the buffer of the next new point
  for (int k = 0; k < N; ++k) {
    const int checks = checks_per[k];
    const double ds = nodes[k + 1] - nodes[k];
    Coef* rows = ws.rows.data() + ws.start[k];
    int c = 0;
    for (int m = 0; m <= checks; ++m) {
      if (m == 0 && k > 0 && !is_stop(stops, nodes[k])) {
        c += prev ? add_rows(*prev, pb.limits, 0.0, rows + c)
                  : add_rows(prev_known, nj, pb.limits, 0.0, rows + c);
        continue;
      }
      const double s = check_point_s(nodes, k, m, checks);
      const double shift = 2.0 * ds * m / checks;
      const double* known = cache ? cache->find(s, m == checks) : nullptr;
      if (known) {
        c += add_rows(known, nj, pb.limits, shift, rows + c);
        if (m == checks) {
          prev = nullptr;
          prev_known = known;
        }
        continue;
      }
      // (after m = 0, the point of the interval before is no longer needed)
      JointPoint& fresh = ws.buf[next];
      next ^= 1;
      source.solver_at(s, m == checks, &fresh);
      if (cache) cache->add(fresh, m == checks);
      c += add_rows(fresh, pb.limits, shift, rows + c);
      if (m == checks) prev = &fresh;
    }
    ws.count[k] = c;
  }
  if (cache) cache->merge();
}

// Whether interval k of `nodes` is interval j - 1 of `prev`'s grid (the same ends and check
// points) with the same set at its end, found in the walk down prev's nodes (j, the index of
// the prev node at or below nodes[k + 1], decreases with k)
bool same_as_before(const std::vector<double>& nodes, const std::vector<int>& checks_per, int k,
                    const SolverOutput& prev, size_t& j, const ExactWorkspace& ws) {
  const std::vector<double>& ps = prev.profile.s;
  while (j > 0 && ps[j] > nodes[k + 1]) --j;
  return j > 0 && ps[j] == nodes[k + 1] && ps[j - 1] == nodes[k] &&
         prev.reach_checks[j - 1] == checks_per[k] && prev.reach_lo[j] == ws.klo[k + 1] &&
         prev.reach_hi[j] == ws.khi[k + 1];
}

// backward pass: controllable sets, K_N = {0}; false on an empty set. An interval that
// `prev` solved with the same set at its end takes its set from it.
bool backward_pass(const std::vector<double>& nodes, const std::vector<int>& checks_per,
                   const SolverOutput* prev, ExactWorkspace& ws) {
  const int N = static_cast<int>(nodes.size()) - 1;
  const bool memo = prev && prev->solved && prev->reach_hi.size() == prev->profile.s.size() &&
                    prev->profile.s.size() >= 2;
  size_t j = memo ? prev->profile.s.size() - 1 : 0;
  for (int k = N - 1; k >= 0; --k) {
    if (memo && same_as_before(nodes, checks_per, k, *prev, j, ws)) {
      ws.klo[k] = prev->reach_lo[j - 1];
      ws.khi[k] = prev->reach_hi[j - 1];
      continue;
    }
    const double ds = nodes[k + 1] - nodes[k];
    const Coef reach{1.0, 2.0 * ds, ws.klo[k + 1], ws.khi[k + 1]};
    const XRange xi = feasible_x_fast(ws.rows.data() + ws.start[k], ws.count[k], reach, ws);
    const double tol = 1e-12 * std::max(1.0, std::abs(xi.hi));
    if (xi.lo > xi.hi + tol || (ws.rest[k] && xi.lo > tol)) return false;
    ws.klo[k] = ws.rest[k] ? 0.0 : std::max(0.0, xi.lo);
    ws.khi[k] = ws.rest[k] ? 0.0 : std::max(ws.klo[k], xi.hi);
  }
  return true;
}

// forward pass: greedy largest u, x_0 = 0; false where the motion would stall
bool forward_pass(const std::vector<double>& nodes, ExactWorkspace& ws) {
  const int N = static_cast<int>(nodes.size()) - 1;
  for (int k = 0; k < N; ++k) {
    const double ds = nodes[k + 1] - nodes[k];
    const double uhi = u_hi_fast(ws.rows.data() + ws.start[k], ws.count[k], ws.x[k]);
    const double u = std::min(uhi, (ws.khi[k + 1] - ws.x[k]) / (2 * ds));
    const double x_next = std::clamp(ws.x[k] + 2 * ds * u, ws.klo[k + 1], ws.khi[k + 1]);
    ws.x[k + 1] = std::max(0.0, x_next);
    if (ws.x[k] <= 0 && ws.x[k + 1] <= 0) return false;
  }
  return true;
}
}  // namespace

SolverOutput solve_exact(const Problem& pb, const std::vector<double>& nodes,
                         const std::vector<int>& checks_per, ExactPointCache* cache,
                         const SolverOutput* previous) {
  thread_local ExactWorkspace ws;
  const int n = static_cast<int>(nodes.size());
  const int N = n - 1;
  ARM_THROW_UNLESS(static_cast<int>(checks_per.size()) == N, "solve_exact: " << checks_per.size()
                                                                             << " check counts for "
                                                                             << N << " intervals");
  size_workspace(pb, nodes, checks_per, ws);
  fill_rows(pb, nodes, checks_per, cache, ws);
  // on any failure of the passes the reference solver (the same numbers, with the rows'
  // tags) words the message
  if (!backward_pass(nodes, checks_per, previous, ws) || !forward_pass(nodes, ws))
    return solve_exact_reference(pb, nodes, checks_per);
  SolverOutput out;
  out.reach_lo.assign(ws.klo.begin(), ws.klo.begin() + n);
  out.reach_hi.assign(ws.khi.begin(), ws.khi.begin() + n);
  out.reach_checks = checks_per;
  out.profile.law = SegmentLaw::kPathAcceleration;
  out.profile.s = nodes;
  out.profile.sd.resize(n);
  for (int k = 0; k < n; ++k) out.profile.sd[k] = std::sqrt(ws.x[k]);
  out.duration = profile_duration(pb, out.profile);
  out.solved = std::isfinite(out.duration);
  if (!out.solved) out.message = "the exact profile has an infinite duration";
  return out;
}

}  // namespace armstudy::studies::time_optimal
