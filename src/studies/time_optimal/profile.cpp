// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "core/check.hpp"
#include "core/dynamics.hpp"
#include "core/kinematics.hpp"
#include "studies/time_optimal/two_link_dynamics.hpp"

namespace armstudy::studies::time_optimal {

const PathGeometry& SolverPath::tip() const {
  if (!tip_)
    throw std::logic_error("time-optimal path: a joint-space path has no tip path geometry");
  return *tip_;
}

const JointPathGeometry& SolverPath::joint() const {
  if (!joint_) throw std::logic_error("time-optimal path: a tip path has no joint-space geometry");
  return *joint_;
}

JointPoint Problem::at(double s, bool from_left) const {
  if (path.joint_space()) return joint_space_point(chain, path.joint(), s, from_left);
  PathTrouble trouble;
  const auto jp = joint_point(chain, path.tip(), configuration, s, from_left, &trouble);
  if (!jp) throw std::logic_error("time-optimal path point used unchecked: " + trouble.message);
  return *jp;
}

Eigen::Vector2d Problem::tip(double s, bool from_left) const {
  if (path.joint_space()) return core::end_effector(chain, path.joint().at(s, from_left).q);
  return path.tip().at(s, from_left).p;
}

std::string Problem::where(double s, bool from_left) const {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(3);
  os << "s = " << s << " " << path.unit() << ", ";
  if (path.joint_space()) {
    const core::JointVector q = path.joint().at(s, from_left).q;
    os << "q = (";
    for (int j = 0; j < q.size(); ++j) os << (j ? ", " : "") << q[j];
    os << ") rad";
  } else {
    const Eigen::Vector2d p = path.tip().at(s, from_left).p;
    os << "(x, y) = (" << p.x() << ", " << p.y() << ") m";
  }
  return os.str();
}

PointSource::PointSource(const Problem& problem) : problem_(&problem) {
  if (!problem.path.joint_space()) {
    tip_.emplace(problem.chain, problem.path.tip(), problem.configuration);
    rates_.emplace(problem.chain, problem.path.tip(), problem.configuration);
    dyn_ = make_two_link_dynamics(problem.chain);
  }
}

void PointSource::solver_at(double s, bool from_left, JointPoint* jp) const {
  if (rates_) {
    const PathPoint pp = problem_->path.tip().at(s, from_left);
    TipRates r;
    if (rates_->at_point(pp, &r)) {
      jp->s = s;
      jp->p = pp.p;
      jp->q.setConstant(2, std::numeric_limits<double>::quiet_NaN());
      jp->dq.resize(2);
      jp->ddq.resize(2);
      jp->dq << r.dq[0], r.dq[1];
      jp->ddq << r.ddq[0], r.ddq[1];
      jp->sin_q2 = r.s2;
      const double ct12 = r.c1 * r.c2 - r.s1 * r.s2, st12 = r.s1 * r.c2 + r.c1 * r.s2;
      path_dynamics_abs(dyn_, r.c2, r.s2, r.c1, r.s1, ct12, st12, r.dq, r.ddq, &jp->a, &jp->b,
                        &jp->c);
      return;
    }
  }
  at(s, from_left, jp);
}

void PointSource::at(double s, bool from_left, JointPoint* jp) const {
  if (!tip_ || !tip_->at(s, from_left, jp)) *jp = problem_->at(s, from_left);
}

Problem make_problem(const Spec& spec, const Limits& limits) {
  if (spec.space == PathSpace::kJoint)
    return Problem{spec.chain, JointPathGeometry(spec.joint_path), spec.configuration, limits};
  return Problem{spec.chain, PathGeometry(spec.path), spec.configuration, limits};
}

std::vector<double> make_nodes(const SolverPath& path, int intervals) {
  std::vector<double> cuts{0.0};
  for (double s : path.stops()) cuts.push_back(s);
  cuts.push_back(path.length());
  const int pieces = static_cast<int>(cuts.size()) - 1;
  ARM_THROW_UNLESS(intervals >= pieces, "path needs >= " << pieces
                                                         << " intervals (one per "
                                                            "piece between stops); got "
                                                         << intervals);
  // intervals per piece in proportion to length, at least one each (largest remainder)
  std::vector<int> count(pieces, 1);
  int left = intervals - pieces;
  std::vector<double> share(pieces);
  for (int p = 0; p < pieces; ++p) share[p] = (cuts[p + 1] - cuts[p]) / path.length() * intervals;
  while (left > 0) {
    int best = 0;
    for (int p = 1; p < pieces; ++p)
      if (share[p] - count[p] > share[best] - count[best]) best = p;
    ++count[best];
    --left;
  }
  std::vector<double> nodes{0.0};
  for (int p = 0; p < pieces; ++p) {
    for (int k = 1; k <= count[p]; ++k)
      nodes.push_back(k == count[p] ? cuts[p + 1]
                                    : cuts[p] + (cuts[p + 1] - cuts[p]) * k / count[p]);
  }
  return nodes;
}

std::vector<bool> rest_nodes(const SolverPath& path, const std::vector<double>& nodes) {
  std::vector<bool> rest(nodes.size(), false);
  rest.front() = rest.back() = true;
  for (double st : path.stops()) {
    for (size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k] == st) rest[k] = true;
  }
  return rest;
}

std::vector<std::vector<JointPoint>> interval_points(const Problem& problem,
                                                     const std::vector<double>& nodes, int checks) {
  ARM_THROW_UNLESS(checks >= 1, "checks per interval " << checks << " should be >= 1");
  return interval_points(problem, nodes, std::vector<int>(nodes.size() - 1, checks));
}

std::vector<std::vector<JointPoint>> interval_points(const Problem& problem,
                                                     const std::vector<double>& nodes,
                                                     const std::vector<int>& checks_per) {
  ARM_THROW_UNLESS(checks_per.size() + 1 == nodes.size(),
                   "interval_points: " << checks_per.size() << " check counts for "
                                       << nodes.size() - 1 << " intervals");
  const auto& stops = problem.path.stops();
  const PointSource source(problem);
  std::vector<std::vector<JointPoint>> out(nodes.size() - 1);
  for (size_t k = 0; k + 1 < nodes.size(); ++k) {
    const int checks = checks_per[k];
    ARM_THROW_UNLESS(checks >= 1, "checks per interval " << checks << " should be >= 1");
    const double ds = nodes[k + 1] - nodes[k];
    out[k].reserve(checks + 1);
    for (int m = 0; m <= checks; ++m) {
      if (m == 0 && k > 0 && std::find(stops.begin(), stops.end(), nodes[k]) == stops.end()) {
        out[k].push_back(out[k - 1].back());  // the same point, already computed
        continue;
      }
      const double s = m == checks ? nodes[k + 1] : nodes[k] + ds * m / checks;
      out[k].emplace_back();
      source.at(s, m == checks, &out[k].back());
    }
  }
  return out;
}

namespace {
// x = s'^2, u = s'' and the time since the interval's start, at theta of interval k
struct LocalState {
  double x, u, dt;
};

LocalState path_acceleration_state(const Profile& pr, int k, double theta) {
  const double ds = pr.s[k + 1] - pr.s[k];
  const double x0 = pr.sd[k] * pr.sd[k], x1 = pr.sd[k + 1] * pr.sd[k + 1];
  const double x = std::max(0.0, x0 + theta * (x1 - x0));
  const double v = pr.sd[k] + std::sqrt(x);
  // constant acceleration: elapsed time = distance / mean speed
  return {x, (x1 - x0) / (2 * ds), v > 0 ? 2 * theta * ds / v : 0.0};
}
}  // namespace

double profile_duration(const Problem& problem, const Profile& pr) {
  double t = 0;
  for (size_t k = 0; k + 1 < pr.s.size(); ++k) {
    if (pr.law == SegmentLaw::kPathAcceleration) {
      const double v = pr.sd[k] + pr.sd[k + 1];
      if (v <= 0) return std::numeric_limits<double>::infinity();
      t += 2 * (pr.s[k + 1] - pr.s[k]) / v;
    } else {
      const double v = pr.qd1[k] + pr.qd1[k + 1];
      const double dq = problem.at(pr.s[k + 1], true).q[0] - problem.at(pr.s[k]).q[0];
      if (v == 0 || dq / v <= 0) return std::numeric_limits<double>::infinity();
      t += 2 * dq / v;
    }
  }
  return t;
}

TimedState state_at_time(const Problem& problem, const Profile& pr,
                         const std::vector<double>& node_t, double t) {
  ARM_THROW_UNLESS(pr.law == SegmentLaw::kPathAcceleration,
                   "state_at_time needs a profile of constant path acceleration");
  ARM_THROW_UNLESS(pr.s.size() >= 2 && pr.sd.size() == pr.s.size() && node_t.size() == pr.s.size(),
                   "state_at_time: profile sizes differ");
  t = std::clamp(t, node_t.front(), node_t.back());
  // interval k with node_t[k] <= t <= node_t[k + 1]
  size_t k =
      static_cast<size_t>(std::upper_bound(node_t.begin(), node_t.end(), t) - node_t.begin());
  k = std::clamp<size_t>(k, 1, node_t.size() - 1) - 1;
  const double ds = pr.s[k + 1] - pr.s[k];
  const double x0 = pr.sd[k] * pr.sd[k], x1 = pr.sd[k + 1] * pr.sd[k + 1];
  const double u = (x1 - x0) / (2 * ds);
  const double tau = std::clamp(t - node_t[k], 0.0, node_t[k + 1] - node_t[k]);
  TimedState out;
  out.t = t;
  out.s = std::clamp(pr.s[k] + pr.sd[k] * tau + 0.5 * u * tau * tau, pr.s[k], pr.s[k + 1]);
  out.sd = std::max(0.0, pr.sd[k] + u * tau);
  out.sdd = u;
  const JointPoint jp = problem.at(out.s, out.s >= pr.s[k + 1]);
  out.q = jp.q;
  out.qd = jp.dq * out.sd;
  out.qdd = jp.dq * u + jp.ddq * out.sd * out.sd;
  out.tau = core::inverse_dynamics(problem.chain, jp.q, out.qd, out.qdd);
  return out;
}

namespace {
Eigen::MatrixXd pack(int nj, const std::vector<core::JointVector>& v) {
  Eigen::MatrixXd m(nj, v.size());
  for (size_t i = 0; i < v.size(); ++i) m.col(i) = v[i];
  return m;
}

// the sentence: grid point, binding limit, margin
std::string violation_text(const Problem& problem, const Violation& v) {
  std::ostringstream os;
  os.precision(4);
  const double lim = problem.limits.of(v.kind, v.joint);
  const double used = (v.worst + 1) * lim;
  os << "largest limit use: joint " << v.joint + 1 << " " << limit_name(v.kind) << " " << used
     << " of " << lim << " " << limit_unit(v.kind) << " at s = " << v.s << " "
     << problem.path.unit() << ", t = " << v.t << " s (interval " << v.interval
     << ", from grid point " << v.interval << "); ";
  if (v.worst <= 0)
    os << "met with a margin of " << lim - used << " " << limit_unit(v.kind) << " ("
       << 0.0 - v.worst << " relative)";
  else
    os << "over it by " << used - lim << " " << limit_unit(v.kind) << " (" << v.worst
       << " relative, between the solver's check points)";
  return os.str();
}

// |value| / limit (infinite for any use of a zero limit)
inline double use_ratio(double value, double lim) {
  const double v = std::abs(value);
  return lim > 0 ? v / lim : (v > 1e-12 ? std::numeric_limits<double>::infinity() : 0.0);
}

// the largest |v[i]|, i < n, and 0 when there is none (NaN is never the largest)
inline double largest_abs(const double* v, size_t n) {
  size_t i = 0;
  double m = 0;
#ifdef __SSE2__
  // maxpd(x, m) is x > m ? x : m lane by lane, as below; four chains for its latency
  const __m128d sign = _mm_set1_pd(-0.0);
  __m128d m0 = _mm_setzero_pd(), m1 = _mm_setzero_pd();
  for (; i + 4 <= n; i += 4) {
    m0 = _mm_max_pd(_mm_andnot_pd(sign, _mm_loadu_pd(v + i)), m0);
    m1 = _mm_max_pd(_mm_andnot_pd(sign, _mm_loadu_pd(v + i + 2)), m1);
  }
  double lanes[2];
  _mm_storeu_pd(lanes, _mm_max_pd(m1, m0));
  m = lanes[0] > lanes[1] ? lanes[0] : lanes[1];
#endif
  for (; i < n; ++i) {
    const double x = std::abs(v[i]);
    m = x > m ? x : m;
  }
  return m;
}

// the joint velocities (v), torques (t) and accelerations (a) at n points of the dense
// re-check from their rates and local states, the torques by the closed form; an AVX build
// beside the baseline one, picked at load time (no FMA: the same roundings)
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx", "default")))
#endif
void scan_block(const TwoLinkDynamics& dyn, const TipRateArrays& ra, const double* __restrict sds,
                const double* __restrict xs, const double* __restrict us, size_t n,
                double* __restrict v0, double* __restrict v1, double* __restrict t0,
                double* __restrict t1, double* __restrict a0, double* __restrict a1) {
  const double* __restrict dq0 = ra.dq0.data();
  const double* __restrict dq1 = ra.dq1.data();
  const double* __restrict ddq0 = ra.ddq0.data();
  const double* __restrict ddq1 = ra.ddq1.data();
  const double* __restrict c1 = ra.c1.data();
  const double* __restrict s1 = ra.s1.data();
  const double* __restrict c2 = ra.c2.data();
  const double* __restrict s2 = ra.s2.data();
  const auto scan = [&](auto gravity) {
#pragma GCC ivdep
    for (size_t i = 0; i < n; ++i) {
      const double sd = sds[i], x = xs[i], u = us[i];
      const double vq[2] = {dq0[i] * sd, dq1[i] * sd};
      const double aq[2] = {dq0[i] * u + ddq0[i] * x, dq1[i] * u + ddq1[i] * x};
      double tq[2];
      inverse_dynamics_cs_fixed<decltype(gravity)::value>(dyn, c1[i], s1[i], c2[i], s2[i], vq, aq,
                                                          tq);
      v0[i] = vq[0];
      v1[i] = vq[1];
      t0[i] = tq[0];
      t1[i] = tq[1];
      a0[i] = aq[0];
      a1[i] = aq[1];
    }
  };
  if (dyn.gravity == 0.0)
    scan(std::false_type{});
  else
    scan(std::true_type{});
}
}  // namespace

// (over 60 lines, kept whole: the plain reference the fast two-link resample is tested
// against, one loop over the points as the solvers' limits read)
void resample_reference(const Problem& problem, const Profile& pr, int per_interval, int keep,
                        MotionSamples* out, Violation* viol, std::vector<double>* node_t,
                        std::vector<double>* interval_worst) {
  ARM_THROW_UNLESS(per_interval >= 1, "resampling points " << per_interval << " should be >= 1");
  const int K = static_cast<int>(pr.s.size()) - 1;
  const int total = K * per_interval + 1;
  const int stride = std::max(1, total / std::max(1, keep));
  *out = MotionSamples{};
  const int nj = problem.chain.num_links();
  std::vector<core::JointVector> q, qd, qdd, tau;
  *viol = Violation{};
  viol->worst = -1;
  if (node_t) node_t->assign(pr.s.size(), 0.0);
  if (interval_worst) interval_worst->assign(K, -1.0);
  double t_node = 0;
  int index = 0;
  for (int k = 0; k < K; ++k) {
    const JointPoint j0 = problem.at(pr.s[k], false);
    const JointPoint j1 = problem.at(pr.s[k + 1], true);
    const double ds = pr.s[k + 1] - pr.s[k];
    const double dq1 = j1.q[0] - j0.q[0];
    double t_end = t_node;
    for (int m = (k == 0 ? 0 : 1); m <= per_interval; ++m) {
      const double theta = static_cast<double>(m) / per_interval;
      const JointPoint jp =
          m == 0 ? j0 : (m == per_interval ? j1 : problem.at(pr.s[k] + theta * ds));
      double x, u, dt;
      if (pr.law == SegmentLaw::kPathAcceleration) {
        const LocalState ls = path_acceleration_state(pr, k, theta);
        x = ls.x;
        u = ls.u;
        dt = ls.dt;
      } else {
        // constant q1'': q1'^2 grows linearly with the joint-1 travel; s' = q1' / (dq1/ds)
        const double v0 = pr.qd1[k], v1 = pr.qd1[k + 1];
        const double a1 = (v1 * v1 - v0 * v0) / (2 * dq1);
        const double travel = jp.q[0] - j0.q[0];
        const double w2 = std::max(0.0, v0 * v0 + 2 * a1 * travel);
        const double w = std::copysign(std::sqrt(w2), dq1);
        const double sd = w / jp.dq[0];
        x = sd * sd;
        u = (a1 - jp.ddq[0] * x) / jp.dq[0];
        dt = (v0 + w) != 0 ? 2 * travel / (v0 + w) : 0.0;
      }
      const double sd = std::sqrt(std::max(0.0, x));
      const core::JointVector qdv = jp.dq * sd;
      const core::JointVector qddv = jp.dq * u + jp.ddq * x;
      const core::JointVector tv = core::inverse_dynamics(problem.chain, jp.q, qdv, qddv);
      const double t = t_node + dt;
      t_end = t;
      // limit use
      const core::JointVector* vals[3] = {&qdv, &tv, &qddv};
      for (int kind = 0; kind < 3; ++kind) {
        if (kind == 2 && !problem.limits.acceleration) continue;
        for (int j = 0; j < nj; ++j) {
          const double lim = problem.limits.of(static_cast<LimitKind>(kind), j);
          const double r = use_ratio((*vals[kind])[j], lim);
          if (r > viol->ratio[kind][j]) viol->ratio[kind][j] = r;
          if (interval_worst && r - 1 > (*interval_worst)[k]) (*interval_worst)[k] = r - 1;
          if (r - 1 > viol->worst) {
            viol->worst = r - 1;
            viol->joint = j;
            viol->kind = static_cast<LimitKind>(kind);
            viol->s = jp.s;
            viol->t = t;
            viol->interval = k;
          }
        }
      }
      if (index % stride == 0 || (k == K - 1 && m == per_interval)) {
        out->s.push_back(jp.s);
        out->t.push_back(t);
        out->sd.push_back(sd);
        out->sdd.push_back(u);
        q.push_back(jp.q);
        qd.push_back(qdv);
        qdd.push_back(qddv);
        tau.push_back(tv);
      }
      ++index;
    }
    t_node = t_end;
    if (node_t) (*node_t)[k + 1] = t_node;
  }
  out->q = pack(nj, q);
  out->qd = pack(nj, qd);
  out->qdd = pack(nj, qdd);
  out->tau = pack(nj, tau);
  viol->text = violation_text(problem, *viol);
}

namespace {
// the thread's scratch arrays of resample_two_link, kept from call to call
struct TwoLinkBuffers {
  TipRateArrays ra;
  std::vector<double> arrays[3 + 3 * 2];  // xs, us, sds, then the values of each limit
  std::vector<double> s_at;               // (one interval's arc lengths and path points)
  std::vector<PathPoint> pp_at;
  std::vector<double> peaks;
};
TwoLinkBuffers& two_link_buffers() {
  thread_local TwoLinkBuffers b;
  return b;
}

// resample of a constant-s'' profile on a 2-link tip path: the same samples and the same
// largest uses as resample_reference. The scan over every point takes the joint rates
// without trigonometric functions (TipRateEvaluator) and the closed-form inverse dynamics
// (two_link_dynamics.hpp), both equal to the reference to rounding; every point within
// 1e-12 of a limit's largest use is a candidate, and the candidates and the kept samples
// are evaluated again as resample_reference does (joint_point, core's inverse dynamics).
// Stages: per block of intervals, the path points and local states, the rates, the scan,
// the peaks and the kept samples; then the candidates and their re-check.
struct TwoLinkResample {
  static constexpr int nj = 2;
  static constexpr double kRounding = 1e-12;
  // the scan in structure-of-arrays form: point i = k per_interval + m (m = 1..per_interval,
  // and m = 0 in the first interval), in blocks of intervals whose arrays stay in cache
  static constexpr int kBlock = 32;
  struct Candidate {
    int k, m;
    double r;
  };
  // the reference state at point m of interval k, as resample_reference computes it
  struct Reference {
    JointPoint jp;
    double sd, u, dt;
    core::JointVector qd, qdd;
  };

  const Problem& problem;
  const Profile& pr;
  const int per_interval;
  const int K;
  const int total;
  const int stride;
  MotionSamples* out;
  Violation* viol;
  std::vector<double>* interval_worst;
  std::vector<core::JointVector> q, qd, qdd, tau;
  std::vector<double> nt;
  const PointSource source;
  const TipRateEvaluator rates;
  const TwoLinkDynamics dyn;
  const int kinds;
  double lim[3][nj];
  std::vector<Candidate> cand[3][nj];
  // (plain references: one thread-local address computation per call)
  TwoLinkBuffers& buf;
  TipRateArrays& ra;
  std::vector<double>& xs;
  std::vector<double>& us;
  std::vector<double>& sds;
  // the values of the limits at every point of the profile, and their largest use in each
  // interval (peak[(kind nj + j) K + k])
  std::vector<double>* val[3];
  std::vector<double>& peaks;
  double t_node = 0;

  TwoLinkResample(const Problem& problem_, const Profile& pr_, int per_interval_, int keep,
                  MotionSamples* out_, Violation* viol_, std::vector<double>* interval_worst_)
      : problem(problem_),
        pr(pr_),
        per_interval(per_interval_),
        K(static_cast<int>(pr_.s.size()) - 1),
        total(K * per_interval_ + 1),
        stride(std::max(1, total / std::max(1, keep))),
        out(out_),
        viol(viol_),
        interval_worst(interval_worst_),
        nt(pr_.s.size(), 0.0),
        source(problem_),
        rates(problem_.chain, problem_.path.tip(), problem_.configuration),
        dyn(make_two_link_dynamics(problem_.chain)),
        kinds(problem_.limits.acceleration ? 3 : 2),
        buf(two_link_buffers()),
        ra(buf.ra),
        xs(buf.arrays[0]),
        us(buf.arrays[1]),
        sds(buf.arrays[2]),
        val{buf.arrays + 3, buf.arrays + 3 + nj,
            buf.arrays + 3 + 2 * static_cast<std::ptrdiff_t>(nj)},
        peaks(buf.peaks) {
    *out = MotionSamples{};
    *viol = Violation{};
    viol->worst = -1;
    if (interval_worst) interval_worst->assign(K, -1.0);
    for (int kind = 0; kind < kinds; ++kind)
      for (int j = 0; j < nj; ++j)
        lim[kind][j] = problem.limits.of(static_cast<LimitKind>(kind), j);
    for (int kind = 0; kind < 3; ++kind)
      for (int j = 0; j < nj; ++j) val[kind][j].resize(static_cast<size_t>(total));
    peaks.assign(static_cast<size_t>(kinds) * nj * K, 0.0);
  }

  double& peak(int kind, int j, int k) { return peaks[static_cast<size_t>(kind * nj + j) * K + k]; }

  // where point m of interval k lies: s and the side (the interval's end from the left)
  bool where(int k, int m, double* s) const {
    if (m == 0) {
      *s = pr.s[k];
      return false;
    }
    if (m == per_interval) {
      *s = pr.s[k + 1];
      return true;
    }
    *s = pr.s[k] + static_cast<double>(m) / per_interval * (pr.s[k + 1] - pr.s[k]);
    return false;
  }

  Reference reference(int k, int m) const {
    Reference r;
    double s;
    const bool left = where(k, m, &s);
    source.at(s, left, &r.jp);
    const LocalState ls = path_acceleration_state(pr, k, static_cast<double>(m) / per_interval);
    r.sd = std::sqrt(std::max(0.0, ls.x));
    r.u = ls.u;
    r.dt = ls.dt;
    r.qd = r.jp.dq * r.sd;
    r.qdd = r.jp.dq * ls.u + r.jp.ddq * ls.x;
    return r;
  }

  // the path points and local states of intervals [k0, k1) point by point (the path may
  // be a spline), from index i0
  void path_points(int k0, int k1, size_t i0) {
    const PathGeometry& path = problem.path.tip();
    std::vector<double>& s_at = buf.s_at;
    std::vector<PathPoint>& pp_at = buf.pp_at;
    s_at.resize(static_cast<size_t>(per_interval) + 1);
    pp_at.resize(static_cast<size_t>(per_interval) + 1);
    for (int k = k0; k < k1; ++k) {
      const int m0 = k == 0 ? 0 : 1;
      // point m of interval k at index base + m of the block
      const std::ptrdiff_t base =
          static_cast<std::ptrdiff_t>(k) * per_interval - static_cast<std::ptrdiff_t>(i0);
      // the points m < per_interval from the right, in increasing s; the last from the left
      for (int m = m0; m < per_interval; ++m) where(k, m, &s_at[m]);
      path.at_increasing(s_at.data() + m0, static_cast<size_t>(per_interval - m0),
                         pp_at.data() + m0);
      pp_at[per_interval] = path.at(pr.s[k + 1], true);
      for (int m = m0; m <= per_interval; ++m) {
        const size_t i = static_cast<size_t>(base + m);
        const PathPoint& pp = pp_at[m];
        ra.px[i] = pp.p.x();
        ra.py[i] = pp.p.y();
        ra.vx[i] = pp.dp.x();
        ra.vy[i] = pp.dp.y();
        ra.ax[i] = pp.ddp.x();
        ra.ay[i] = pp.ddp.y();
      }
      // path_acceleration_state's operations, and s' = sqrt(max(0, x)) = sqrt(x) with
      // x = max(0, ..), in a loop without branches
      const double ds = pr.s[k + 1] - pr.s[k];
      const double x0 = pr.sd[k] * pr.sd[k], x1 = pr.sd[k + 1] * pr.sd[k + 1];
      const double u = (x1 - x0) / (2 * ds);
      for (int m = m0; m <= per_interval; ++m) {
        const size_t i = static_cast<size_t>(base + m);
        const double theta = static_cast<double>(m) / per_interval;
        const double x = std::max(0.0, x0 + theta * (x1 - x0));
        const double root = std::sqrt(x);
        xs[i] = x;
        us[i] = u;
        sds[i] = root;
      }
    }
  }

  // on the edge of the fast path: the reference point's rates
  void edge_rates(size_t i0, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      if (ra.ok[i]) continue;
      const size_t gi = i0 + i;  // (the point's index in the whole profile)
      const int k = gi == 0 ? 0 : static_cast<int>((gi - 1) / per_interval);
      const int m = static_cast<int>(gi - static_cast<size_t>(k) * per_interval);
      double s;
      const bool left = where(k, m, &s);
      JointPoint jp;
      source.at(s, left, &jp);
      const double t1 = problem.chain.base_angle + jp.q[0];
      ra.dq0[i] = jp.dq[0];
      ra.dq1[i] = jp.dq[1];
      ra.ddq0[i] = jp.ddq[0];
      ra.ddq1[i] = jp.ddq[1];
      ra.c1[i] = std::cos(t1);
      ra.s1[i] = std::sin(t1);
      ra.c2[i] = std::cos(jp.q[1]);
      ra.s2[i] = std::sin(jp.q[1]);
    }
  }

  // the largest |value| of each limit in each interval of the block, over its points
  // m = 1..per_interval (and m = 0 in the first); its use is the largest use, division
  // by the limit being monotone (NaN is never the largest)
  void block_peaks(int k0, int k1) {
    for (int kind = 0; kind < kinds; ++kind)
      for (int j = 0; j < nj; ++j) {
        const double* __restrict v = val[kind][j].data();
        for (int k = k0; k < k1; ++k) {
          const size_t a = k == 0 ? 0 : static_cast<size_t>(k) * per_interval + 1;
          const size_t e = static_cast<size_t>(k + 1) * per_interval + 1;
          peak(kind, j, k) = use_ratio(largest_abs(v + a, e - a), lim[kind][j]);
        }
      }
    if (interval_worst) {
      for (int k = k0; k < k1; ++k) {
        double w = -1;
        for (int kind = 0; kind < kinds; ++kind)
          for (int j = 0; j < nj; ++j) w = std::max(w, peak(kind, j, k) - 1);
        if (w > (*interval_worst)[k]) (*interval_worst)[k] = w;
      }
    }
  }

  // the times at the interval ends, and the kept samples (index % stride == 0, and the
  // last point) evaluated as resample_reference does
  void keep_samples(int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const size_t first = k == 0 ? 0 : static_cast<size_t>(k) * per_interval + 1;
      const size_t last = static_cast<size_t>(k + 1) * per_interval;
      const auto keep_point = [&](size_t gi) {
        const int m = static_cast<int>(gi - static_cast<size_t>(k) * per_interval);
        const Reference ref = reference(k, m);
        out->s.push_back(ref.jp.s);
        out->t.push_back(t_node + ref.dt);
        out->sd.push_back(ref.sd);
        out->sdd.push_back(ref.u);
        q.push_back(ref.jp.q);
        qd.push_back(ref.qd);
        qdd.push_back(ref.qdd);
        // (the closed form: core's generic chain to 1e-12 relative)
        inverse_dynamics(dyn, ref.jp.q, ref.qd, ref.qdd, &tau.emplace_back());
      };
      const size_t st = static_cast<size_t>(stride);
      for (size_t g = (first + st - 1) / st * st; g <= last; g += st) keep_point(g);
      if (k == K - 1 && last % st != 0) keep_point(last);
      t_node = t_node + path_acceleration_state(pr, k, 1.0).dt;  // (theta = m / m at the end)
      nt[k + 1] = t_node;
    }
  }

  // the scan over every point, block by block: rates, torques and uses in loops without
  // branches
  void scan() {
    for (int k0 = 0; k0 < K; k0 += kBlock) {
      const int k1 = std::min(K, k0 + kBlock);
      const size_t i0 = k0 == 0 ? 0 : static_cast<size_t>(k0) * per_interval + 1;
      const size_t n = static_cast<size_t>(k1) * per_interval + 1 - i0;
      ra.resize(n);
      for (std::vector<double>* v : {&xs, &us, &sds}) v->resize(n);
      path_points(k0, k1, i0);
      rates.at_points(n, &ra);
      edge_rates(i0, n);
      scan_block(dyn, ra, sds.data(), xs.data(), us.data(), n, val[0][0].data() + i0,
                 val[0][1].data() + i0, val[1][0].data() + i0, val[1][1].data() + i0,
                 val[2][0].data() + i0, val[2][1].data() + i0);
      block_peaks(k0, k1);
      keep_samples(k0, k1);
    }
  }

  // the candidates of each limit: the points a stream over them in order keeps, when it
  // keeps every point within kRounding of the largest use so far (and above 0) and drops
  // the ones below the largest use's floor when it rises. With a finite largest use B,
  // those are the points with a use of at least B's floor, in order: their use is at least
  // the floor of the largest use so far when they come, and never below a later floor; any
  // other point is below B's floor and was dropped or never kept. Only the intervals whose
  // largest use reaches B's floor are looked at. (An infinite use, of a zero limit, has no
  // floor: that limit is streamed point by point.)
  void find_candidates(int kind, int j) {
    const double* __restrict v = val[kind][j].data();
    auto& c = cand[kind][j];
    double B = 0;
    for (int k = 0; k < K; ++k) B = std::max(B, peak(kind, j, k));
    if (!(B > 0)) return;
    const auto point = [&](int k, int m) {
      return use_ratio(v[static_cast<size_t>(k) * per_interval + m], lim[kind][j]);
    };
    if (std::isfinite(B)) {
      const double floor = B - kRounding * std::max(1.0, B);
      for (int k = 0; k < K; ++k) {
        if (peak(kind, j, k) < floor) continue;
        for (int m = k == 0 ? 0 : 1; m <= per_interval; ++m) {
          const double r = point(k, m);
          if (r >= floor && r > 0) c.push_back({k, m, r});
        }
      }
      return;
    }
    double b = 0;
    for (int k = 0; k < K; ++k) {
      for (int m = k == 0 ? 0 : 1; m <= per_interval; ++m) {
        const double r = point(k, m);
        if (r < b - kRounding * std::max(1.0, b) || !(r > 0)) continue;
        if (r > b) {
          const double floor = r - kRounding * std::max(1.0, r);
          c.erase(
              std::remove_if(c.begin(), c.end(), [&](const Candidate& e) { return e.r < floor; }),
              c.end());
          b = r;
        }
        c.push_back({k, m, r});
      }
    }
  }

  // every candidate again as resample_reference: the first point of each limit's largest
  // use; the overall worst is the first point (then kind, then joint) of the largest use
  void recheck_candidates() {
    long worst_index = -1;
    for (int kind = 0; kind < kinds; ++kind) {
      for (int j = 0; j < nj; ++j) {
        double r_best = 0;
        int k_best = -1;
        Reference at_best;
        long i_best = -1;
        for (const Candidate& c : cand[kind][j]) {
          const Reference ref = reference(c.k, c.m);
          double v;
          if (kind == 0)
            v = ref.qd[j];
          else if (kind == 2)
            v = ref.qdd[j];
          else
            v = core::inverse_dynamics(problem.chain, ref.jp.q, ref.qd, ref.qdd)[j];
          const double r = use_ratio(v, lim[kind][j]);
          if (r > r_best) {
            r_best = r;
            k_best = c.k;
            at_best = ref;
            i_best = static_cast<long>(c.k) * per_interval + c.m;
          }
        }
        viol->ratio[kind][j] = r_best;
        if (k_best < 0) continue;
        if (r_best - 1 > viol->worst || (r_best - 1 == viol->worst && i_best < worst_index)) {
          viol->worst = r_best - 1;
          viol->joint = j;
          viol->kind = static_cast<LimitKind>(kind);
          viol->s = at_best.jp.s;
          viol->t = nt[k_best] + at_best.dt;
          viol->interval = k_best;
          worst_index = i_best;
        }
      }
    }
  }

  void run(std::vector<double>* node_t) {
    scan();
    for (int kind = 0; kind < kinds; ++kind)
      for (int j = 0; j < nj; ++j) find_candidates(kind, j);
    recheck_candidates();
    if (node_t) *node_t = nt;
    out->q = pack(nj, q);
    out->qd = pack(nj, qd);
    out->qdd = pack(nj, qdd);
    out->tau = pack(nj, tau);
    viol->text = violation_text(problem, *viol);
  }
};

void resample_two_link(const Problem& problem, const Profile& pr, int per_interval, int keep,
                       MotionSamples* out, Violation* viol, std::vector<double>* node_t,
                       std::vector<double>* interval_worst) {
  TwoLinkResample(problem, pr, per_interval, keep, out, viol, interval_worst).run(node_t);
}
}  // namespace

void resample(const Problem& problem, const Profile& pr, int per_interval, int keep,
              MotionSamples* out, Violation* viol, std::vector<double>* node_t,
              std::vector<double>* interval_worst) {
  ARM_THROW_UNLESS(per_interval >= 1, "resampling points " << per_interval << " should be >= 1");
  if (!problem.path.joint_space() && problem.chain.num_links() == 2 &&
      pr.law == SegmentLaw::kPathAcceleration)
    resample_two_link(problem, pr, per_interval, keep, out, viol, node_t, interval_worst);
  else
    resample_reference(problem, pr, per_interval, keep, out, viol, node_t, interval_worst);
}

}  // namespace armstudy::studies::time_optimal
