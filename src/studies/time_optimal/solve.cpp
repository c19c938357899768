#include "studies/time_optimal/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <thread>

#include "core/check.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr int kKeepSamples = 600;    // samples per solver kept for plots
constexpr int kDenseTotal = 4000;    // least dense re-check points of a coarse solution
constexpr int kMaxRefinements = 3;   // doublings of the exact solver's check points

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

// re-check a solver's profile densely and fill its result
void finish(const Problem& pb, const SolverOutput& o, int per_interval, SolverResult* r) {
  r->solved = o.solved;
  r->message = o.message;
  r->evaluations = o.evaluations;
  r->iterations = o.iterations;
  if (!o.solved) return;
  r->duration = o.duration;
  r->law = o.profile.law;
  r->node_s = o.profile.s;
  r->node_sd = o.profile.sd;
  resample(pb, o.profile, per_interval, kKeepSamples, &r->samples, &r->violation, &r->node_t);
}

int dense_points(int intervals, int at_least) {
  return std::max(at_least, (kDenseTotal + intervals - 1) / intervals);
}
}  // namespace

core::PlanarChain default_arm(double L1, double L2) {
  core::PlanarChain c;
  // massless links, 1.0 kg at the end of each (Ozkipcak 1994)
  c.links = {{L1, 0.0, L1 / 2, 0.0, 0.0, true}, {L2, 0.0, L2 / 2, 0.0, 0.0, true}};
  c.point_masses = {{0, L1, 0.0, 1.0}, {1, L2, 0.0, 1.0}};
  c.gravity = 0.0;
  return core::make_chain(c);
}

Result solve(const Spec& spec, const ProgressFn& progress) {
  const auto report = [&](double f, std::string_view stage) {
    if (progress) progress(f, stage);
  };
  ARM_THROW_UNLESS(spec.chain.num_links() == 2,
                   "time-optimal arm has " << spec.chain.num_links() << " links; should have 2");
  ARM_THROW_UNLESS(spec.configuration == 1 || spec.configuration == 2,
                   "configuration " << spec.configuration << " should be 1 or 2");
  ARM_THROW_UNLESS(spec.exact.grid_points >= 2,
                   "exact grid points " << spec.exact.grid_points << " should be >= 2");
  ARM_THROW_UNLESS(spec.exact.checks_per_interval >= 1 && spec.dp.checks_per_segment >= 1,
                   "checks per interval should be >= 1");
  ARM_THROW_UNLESS(spec.dp.levels >= 2, "DP levels " << spec.dp.levels << " should be >= 2");
  for (int j = 0; j < 2; ++j) {
    ARM_THROW_UNLESS(spec.velocity_limit[j] >= 0 && spec.torque_limit[j] >= 0,
                     "joint " << j + 1 << " limits should be >= 0");
  }
  Result res;
  res.limits = Limits{spec.velocity_limit, spec.torque_limit, spec.acceleration_limit};
  const Problem pb{spec.chain, PathGeometry(spec.path), spec.configuration, res.limits};
  res.path_length = pb.path.length();

  // the path must stay in the workspace and off singular poses: check it finely
  report(0.02, "checking the path");
  {
    const std::vector<double> probe = make_nodes(pb.path, std::max(4 * spec.exact.grid_points, 4000));
    for (size_t k = 0; k < probe.size(); ++k) {
      for (bool left : {false, true}) {
        PathTrouble trouble;
        if (!joint_point(pb.chain, pb.path, pb.configuration, probe[k], left, &trouble)) {
          res.status = Status::kUnsolvable;
          res.message = trouble.message;
          return res;
        }
      }
    }
  }

  // exact solver
  report(0.05, "exact solver (reachability)");
  const std::vector<double> grid = make_nodes(pb.path, spec.exact.grid_points - 1);
  {
    // limits hold at the check points of each interval; between them a limit may be
    // overshot by O(h^2). The checks are doubled until the dense resampling meets every
    // limit to kExactTolerance (at most kMaxRefinements times); run time includes it.
    SolverResult r;
    r.name = "exact";
    r.intervals = static_cast<int>(grid.size()) - 1;
    const auto t0 = std::chrono::steady_clock::now();
    int checks = spec.exact.checks_per_interval;
    SolverOutput o = solve_exact(pb, grid, checks);
    finish(pb, o, spec.resample_per_interval, &r);
    for (int k = 0; k < kMaxRefinements && o.solved && r.violation.worst > kExactTolerance; ++k) {
      checks *= 2;
      o = solve_exact(pb, grid, checks);
      finish(pb, o, spec.resample_per_interval, &r);
    }
    r.run_time = seconds_since(t0);
    r.method = "reachability analysis (backward controllable sets, greedy forward pass) on " +
               std::to_string(spec.exact.grid_points) + " grid points, limits enforced at " +
               std::to_string(checks + 1) + " points of every interval";
    res.solvers.push_back(r);
    if (!o.solved) {
      res.status = Status::kUnsolvable;
      res.message = o.message;
      return res;
    }
  }
  // (no reference into res.solvers: it grows below)
  const double exact_duration = res.solvers.front().duration;
  max_velocity_curve(pb, grid, &res.mvc_sd, &res.mvc_velocity_sd);
  res.mvc_s = grid;
  res.path_p.resize(2, grid.size());
  for (size_t k = 0; k < grid.size(); ++k) res.path_p.col(k) = pb.path.at(grid[k]).p;

  // DP and Complex enforce the limits at checks_per_segment + 1 points of each of their
  // long segments; between them a limit can be overshot. Like the exact solver, each is
  // solved again with doubled checks until its dense resampling meets every limit to
  // kCoarseViolationTolerance (at most kMaxRefinements times); run time includes it.
  const auto run_coarse = [&](SolverResult* r, const std::function<SolverOutput(int)>& run) {
    const auto t0 = std::chrono::steady_clock::now();
    int checks = spec.dp.checks_per_segment;
    SolverOutput o = run(checks);
    finish(pb, o, dense_points(spec.dp.segments, spec.resample_per_interval), r);
    for (int k = 0; k < kMaxRefinements && o.solved && r->violation.worst > kCoarseViolationTolerance; ++k) {
      checks *= 2;
      o = run(checks);
      finish(pb, o, dense_points(spec.dp.segments, spec.resample_per_interval), r);
    }
    r->run_time = seconds_since(t0);
    r->method += ", limits enforced at " + std::to_string(checks + 1) + " points of every segment";
    return o;
  };

  // dynamic programming, one run per requested state
  double done = 0.15;
  for (DpState state : spec.dp.states) {
    report(done, state == DpState::kPathSpeed ? "dynamic programming (state s')"
                                              : "dynamic programming (state q1')");
    SolverResult r;
    r.name = state == DpState::kPathSpeed ? "dp" : "dp_joint1";
    r.method = std::string("dynamic programming, ") + std::to_string(spec.dp.segments) +
               " segments of constant " + (state == DpState::kPathSpeed ? "s''" : "q1''") +
               ", " + std::to_string(spec.dp.levels) + " levels of " +
               (state == DpState::kPathSpeed ? "path speed s'" : "joint-1 velocity q1'");
    r.intervals = spec.dp.segments;
    r.levels = spec.dp.levels;
    run_coarse(&r, [&](int checks) { return solve_dp(pb, spec.dp.segments, spec.dp.levels, checks, state); });
    res.solvers.push_back(r);
    done += 0.15;
  }

  // Box's Complex method on the same discretisation
  if (spec.complex.enabled) {
    report(done, "Box's Complex method");
    SolverResult r;
    r.name = "complex";
    r.method = "Box's Complex method, " + std::to_string(spec.dp.segments) +
               " segments of constant s'', node speeds as variables";
    r.intervals = spec.dp.segments;
    const SolverOutput o = run_coarse(
        &r, [&](int checks) { return solve_complex(pb, spec.dp.segments, checks, spec.complex); });
    r.method += ", restarted " + std::to_string(o.restarts) + " time(s) from its best point";
    res.solvers.push_back(r);
  }

  // DP convergence table (path-speed state), rows spread over two threads
  report(0.6, "DP convergence table");
  res.convergence.resize(spec.dp.convergence_segments.size());
  const auto run_row = [&](size_t i) {
    ConvergenceRow& row = res.convergence[i];
    row.segments = spec.dp.convergence_segments[i];
    // the state grid grows with N (levels x N / N_case): a segment's reachable speeds span
    // ~1/N of the range, so fixed levels would leave finer segments few reachable states
    // and the quantisation loss, ~one level per segment, would grow with N
    const double grow = static_cast<double>(row.segments) / std::max(1, spec.dp.segments);
    row.levels = static_cast<int>(std::lround(spec.dp.levels * std::max(1.0, grow)));
    // fewer check points on shorter segments: about 80 over the path, at least 2 per segment
    // (doubled, as for the solvers above, while dense resampling finds a limit overshot by
    // more than the coarse tolerance between them)
    int checks = std::max(2, 80 / row.segments);
    const auto t0 = std::chrono::steady_clock::now();
    SolverOutput o;
    Violation v;
    for (int k = 0; k <= kMaxRefinements; ++k, checks *= 2) {
      o = solve_dp(pb, row.segments, row.levels, checks, DpState::kPathSpeed);
      if (!o.solved) break;
      MotionSamples ms;
      v = Violation{};
      resample(pb, o.profile, dense_points(row.segments, 4), 2, &ms, &v, nullptr);
      if (v.worst <= kCoarseViolationTolerance) break;
    }
    row.run_time = seconds_since(t0);
    row.solved = o.solved;
    if (!o.solved) return;
    row.duration = o.duration;
    row.excess = o.duration / exact_duration - 1;
    row.worst_violation = v.worst;
  };
  {
    std::thread helper([&] {
      for (size_t i = 1; i < res.convergence.size(); i += 2) run_row(i);
    });
    for (size_t i = 0; i < res.convergence.size(); i += 2) run_row(i);
    helper.join();
  }

  // the exact motion at equal time steps: inside interval k, s = s_k + s'_k tau + u tau^2 / 2
  report(0.95, "sampling the motion");
  const SolverResult& exact = res.solvers.front();
  const int steps = std::max(1, spec.motion_steps);
  res.motion_t.resize(steps + 1);
  res.motion_s.resize(steps + 1);
  res.motion_p.resize(2, steps + 1);
  res.motion_q.resize(2, steps + 1);
  size_t k = 0;
  for (int i = 0; i <= steps; ++i) {
    const double t = exact.duration * i / steps;
    while (k + 2 < exact.node_t.size() && exact.node_t[k + 1] < t) ++k;
    const double ds = exact.node_s[k + 1] - exact.node_s[k];
    const double x0 = exact.node_sd[k] * exact.node_sd[k];
    const double x1 = exact.node_sd[k + 1] * exact.node_sd[k + 1];
    const double u = (x1 - x0) / (2 * ds);
    const double tau = std::clamp(t - exact.node_t[k], 0.0, exact.node_t[k + 1] - exact.node_t[k]);
    const double s = std::clamp(exact.node_s[k] + exact.node_sd[k] * tau + 0.5 * u * tau * tau,
                                exact.node_s[k], exact.node_s[k + 1]);
    const JointPoint jp = pb.at(s, i == steps);
    res.motion_t[i] = t;
    res.motion_s[i] = s;
    res.motion_p.col(i) = jp.p;
    res.motion_q.col(i) = jp.q;
  }

  res.status = Status::kSolved;
  std::ostringstream os;
  os << "fastest traversal of the " << fixed(res.path_length, 3) << " m path: "
     << fixed(exact.duration, 4) << " s (exact)";
  for (const SolverResult& r : res.solvers)
    if (r.name != "exact" && r.solved) os << ", " << fixed(r.duration, 4) << " s (" << r.name << ")";
  for (const SolverResult& r : res.solvers)
    if (r.name != "exact" && !r.solved) os << "; " << r.name << " failed: " << r.message;
  res.message = os.str();
  report(1.0, "done");
  return res;
}

std::vector<Check> checks(const Result& res) {
  std::vector<Check> out;
  if (res.status != Status::kSolved || res.solvers.empty()) return out;
  const SolverResult& exact = res.solvers.front();
  for (const SolverResult& r : res.solvers) {
    if (!r.solved) continue;
    if (r.name != "exact") {
      out.push_back(make_check("exact_not_slower_than_" + r.name,
                               "exact duration / " + r.name + " duration - 1 (the reachability "
                               "solution is never slower)",
                               exact.duration / r.duration - 1, 1e-9));
    }
    out.push_back(make_check(
        r.name + "_meets_limits",
        "largest relative limit overshoot of the " + r.name + " solution, densely resampled: " +
            r.violation.text,
        r.violation.worst, r.name == "exact" ? kExactTolerance : kCoarseViolationTolerance));
  }
  double worst = -1;
  bool any = false;
  for (const ConvergenceRow& row : res.convergence) {
    if (!row.solved) continue;
    any = true;
    worst = std::max(worst, -row.excess / (1 + row.excess));
  }
  if (any)
    out.push_back(make_check("exact_not_slower_than_dp_table",
                             "largest exact duration / DP duration - 1 over the convergence table",
                             worst, 1e-9));
  return out;
}

}  // namespace armstudy::studies::time_optimal
