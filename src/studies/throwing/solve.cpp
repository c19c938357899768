// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "core/kinematics.hpp"
#include "studies/throwing/grid_sequence.hpp"
#include "studies/throwing/slsqp_starts.hpp"

namespace armstudy::studies {
namespace {

// v with `digits` decimals in the C locale
std::string fixed(double v, int digits) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

// "the contact and power limits": the constraint kinds broken by a motion's worst values
std::string broken_limits(const std::array<double, kConstraintKinds>& worst) {
  std::vector<std::string> names;
  for (int k = 0; k < kConstraintKinds; ++k)
    if (worst[k] > 0) names.push_back(constraint_name(static_cast<ConstraintKind>(k)));
  std::string s = "the ";
  for (size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return s + (names.size() == 1 ? " limit" : " limits");
}

// the status and the sentence that leads the report, from the answer and its checks
void decide_answer(const ThrowingSpec& spec, ThrowingResult& r) {
  const bool slsqp = r.answer == "slsqp";
  const ThrowMotion& m = slsqp ? r.nlopt : r.idp;
  const Verification& check = slsqp ? r.nlopt_check : r.idp_check;
  const Flight& flight = slsqp ? r.nlopt_flight : r.idp_flight;
  const bool converged = slsqp ? r.nlopt_run.converged : r.idp_converged;
  const double kkt = slsqp ? r.nlopt_run.kkt_residual : r.idp_optimality.kkt_residual;
  r.flight = flight;
  const bool feasible = m.evaluation.feasible && check.feasible;
  const double e8 = r.initial.evaluation.energy, e = m.evaluation.energy;
  const std::string idp_words =
      "IDP (the paper's method) " + fixed(r.idp.evaluation.energy, 3) + " J" +
      (r.idp_check.feasible ? "" : " (infeasible in the re-check)") +
      (r.idp_converged ? ""
                       : " (a stall: first-order residual " +
                             fixed(r.idp_optimality.kkt_residual, 4) + " /(rad/s))");
  if (!feasible) {
    r.status = Status::kUnsolvable;
    r.saving_percent = r.idp_saving_percent = NAN;
    r.message = "no feasible throw found: the best " + std::string(slsqp ? "SLSQP" : "IDP") +
                " throw" + (converged ? "" : " (NOT converged)") + " (" + fixed(e, 3) +
                " J) breaks " + broken_limits(m.evaluation.feasible ? check.worst : m.worst) +
                (m.evaluation.feasible ? " in the re-check with finer steps" : "") +
                " (the limits may leave no feasible throw; see the margins)";
    return;
  }
  r.saving_percent = 100.0 * (e8 - e) / std::abs(e8);
  r.idp_saving_percent =
      r.idp_check.feasible ? 100.0 * (e8 - r.idp.evaluation.energy) / std::abs(e8) : NAN;
  if (!flight.reaches) {
    r.status = Status::kUnsolvable;
    r.message = "the ball never reaches the landing height " + fixed(spec.landing_height, 3) +
                " m: its apex is " + fixed(flight.apex, 3) + " m";
    return;
  }
  r.status = Status::kSolved;
  std::string eq8_words = "eq. 8 start " + fixed(e8, 3) + " J";
  if (!r.initial_feasible) eq8_words += ", which breaks " + broken_limits(r.initial.worst);
  // the answer's start: the first grid's best, or an offered start its grid took
  std::string who = "IDP";
  if (slsqp) {
    const bool offered = !r.grids.empty() && r.grids.back().from.rfind("offered: ", 0) == 0;
    who = "SLSQP from " + std::to_string(r.slsqp_starts.size()) + " starts (best from " +
          (offered ? r.grids.back().from : r.slsqp_starts[r.slsqp_best_start].name) + ")";
  }
  // the control grids: the answer of the continuous problem, or how far it still falls
  std::string lead = converged ? "lowest-energy throw found: " : "NOT converged: ";
  std::string grid_words;
  if (slsqp && r.grids.size() >= 2) {
    std::string seq;
    for (const auto& g : r.grids)
      seq += (seq.empty() ? "" : ", ") + std::to_string(g.stages) + ": " + fixed(g.energy, 3);
    grid_words =
        " on " + std::to_string(r.grids.back().stages) + " stages (control grids " + seq + " J; ";
    if (r.grid_converged) {
      grid_words += "converged: the last doubling changed it by " +
                    fixed(std::abs(r.grid_change), 4) + " J, estimated error " +
                    fixed(r.grid_error, 4) + " J)";
    } else {
      grid_words += "the energy still falls with the stages)";
      lead = "not converged: still falling by " + fixed(std::abs(r.grid_change), 3) +
             " J per doubling of the stages (the optimum of the continuous problem is at most "
             "this throw's energy; how far below it lies is not estimated): " +
             (converged ? "" : "NOT converged on its grid: ");
    }
  } else if (slsqp && spec.grid.refinements > 0 && r.grids.size() == 1) {
    grid_words = " on " + std::to_string(r.grids.back().stages) +
                 " stages (no finer grid gave a throw feasible in the re-check: the control "
                 "grid's error is not measured)";
  }
  r.message = lead + fixed(e, 3) + " J" + grid_words + " by " + who + ", first-order residual " +
              fixed(kkt, 6) + " /(rad/s), feasible in the re-check (" + eq8_words + "; saving " +
              fixed(r.saving_percent, 1) +
              " %); the ball lands at x = " + fixed(flight.landing.x(), 3) + " m";
  if (slsqp) r.message += "; " + idp_words;
}

}  // namespace

ThrowSetup make_throw_setup(const ThrowingSpec& spec) {
  ThrowSetup s;
  s.chain = make_tray_arm(spec.arm);
  s.mount = spec.arm.motor2;
  // rotor inertia lives in the chain (studies/tray_arm.hpp), so eq. 5 gets Im = 0
  for (auto& m : s.motor) {
    m = spec.motor;
    m.Im = 0.0;
  }
  s.theta3_0 = spec.theta3_start;
  s.theta4_0 = spec.theta4_start;
  s.theta3_release = spec.theta3_release;
  s.release_tolerance = spec.release_tolerance;
  s.half_width = spec.tray_width / 2;
  s.voltage_max = spec.voltage_max;
  s.current_max = spec.current_max;
  s.power_max = spec.power_max;
  s.contact_margin = spec.contact_margin;
  s.friction_coefficient = spec.friction_coefficient;
  s.ball_mass = spec.arm.m4;
  s.count_regeneration = spec.count_regeneration;
  s.steps_per_stage = spec.steps_per_stage;
  return s;
}

ThrowMotion record_motion(const ThrowSetup& setup, const ThrowingSpec& spec,
                          const VelocityProfile& profile) {
  ThrowMotion m;
  m.profile = profile;
  std::vector<ThrowSample> samples;
  m.evaluation = simulate_profile(setup, profile, &samples);
  ThrowSeries& s = m.series;
  for (const ThrowSample& x : samples) {
    s.t.push_back(x.t);
    s.q.push_back(x.q);
    s.qd.push_back(x.qd);
    s.qdd.push_back(x.qdd);
    s.tau_m.push_back(x.tau_m);
    s.voltage.emplace_back(x.motor[0].voltage, x.motor[1].voltage);
    s.current.emplace_back(x.motor[0].current, x.motor[1].current);
    s.power.emplace_back(x.motor[0].power, x.motor[1].power);
    s.energy.push_back(x.energy);
    s.ball.push_back(ball_position(setup.chain, x.q));
    s.normal_force.push_back(x.normal_force);
    s.tangential_force.push_back(x.tangential_force);
  }
  m.worst = worst_constraints(setup, m.evaluation);
  // energy split by the trapezoid rule over the samples (eq. 7 and its parts)
  for (size_t k = 1; k < samples.size(); ++k) {
    const double dt = samples[k].t - samples[k - 1].t;
    for (int j = 0; j < 2; ++j) {
      const core::MotorSample& a = samples[k - 1].motor[j];
      const core::MotorSample& b = samples[k].motor[j];
      const double pa = setup.count_regeneration ? a.power : std::max(0.0, a.power);
      const double pb = setup.count_regeneration ? b.power : std::max(0.0, b.power);
      m.split.electrical += 0.5 * dt * (pa + pb);
      m.split.mechanical += 0.5 * dt * (a.load + b.load);
      m.split.copper += 0.5 * dt * (a.copper + b.copper);
      m.split.friction += 0.5 * dt * (a.friction + b.friction);
    }
  }
  m.split.rest = m.split.electrical - (m.split.mechanical + m.split.copper + m.split.friction);
  if (!samples.empty()) {
    const ThrowSample& f = samples.back();
    m.angle_error << f.q[0] - spec.release[0], f.q[1] - spec.release[1],
        f.q[2] - spec.theta3_release;
    m.rate_error << f.qd[0] - spec.release_rate[0], f.qd[1] - spec.release_rate[1];
  }
  return m;
}

bool keeps_backoff(const ThrowSetup& setup, const ProfileEvaluation& e, double backoff) {
  if (!e.finite) return false;
  for (double g : constraint_values(setup, e, 0.75 * backoff))
    if (!(g <= 0.0)) return false;
  return true;
}

Verification verify_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                            int refinement) {
  Verification v;
  v.refinement = std::max(1, refinement);
  ThrowSetup fine = setup;
  fine.steps_per_stage = setup.steps_per_stage * v.refinement;
  v.evaluation = simulate_profile(fine, profile, nullptr, 0.0);
  v.worst = worst_constraints(fine, v.evaluation);
  v.release_error = std::abs(v.evaluation.theta3_final - setup.theta3_release);
  v.feasible = v.evaluation.feasible;
  return v;
}

Flight ballistic_flight(const Eigen::Vector2d& p, const Eigen::Vector2d& v, double g, double h) {
  Flight f;
  f.release_position = p;
  f.release_velocity = v;
  // y(t) = y0 + vy t - g t^2 / 2; apex at t = vy / g if vy > 0
  f.apex = v.y() > 0 ? p.y() + v.y() * v.y() / (2 * g) : p.y();
  const double disc = v.y() * v.y() + 2 * g * (p.y() - h);
  if (!(g > 0) || disc < 0) return f;
  // the later root: the ball comes down to h (or rises through it first if it starts below)
  f.duration = (v.y() + std::sqrt(disc)) / g;
  if (f.duration < 0) return f;
  f.reaches = true;
  f.landing = {p.x() + v.x() * f.duration, h};
  for (int k = 0; k <= 40; ++k) {
    const double t = f.duration * k / 40.0;
    f.path_t.push_back(t);
    f.path.emplace_back(p.x() + v.x() * t, p.y() + v.y() * t - 0.5 * g * t * t);
  }
  return f;
}

namespace {
// IDP's feasible start (the reference): eq. 8 itself, or the first profile twice the
// back-off inside every limit on the descent of the violation from eq. 8. That point moves
// with the last digit of an input (a first feasible point, not an optimum), so no saving
// is quoted against it: the saving is against eq. 8, the paper's comparison
VelocityProfile feasible_start(const ThrowSetup& setup, const ThrowingSpec& spec,
                               const VelocityProfile& initial, const Eigen::Vector2d& delta,
                               const NloptSettings& ns, const ProgressFn& progress,
                               ThrowingResult& r) {
  VelocityProfile start = initial;
  if (r.initial_feasible) {
    r.reference_kind = "eq8";
    r.reference = r.initial;
  } else {
    if (progress) progress(0.02, "repair of eq. 8 (IDP's feasible start)");
    r.repair_run = run_nlopt(setup, initial, delta, ns, Objective::kViolation);
    if (r.repair_run.feasible) {
      r.reference_kind = "repaired";
      start = r.repair_run.best;
      r.reference = record_motion(setup, spec, start);
    } else {
      r.reference_kind = "none";
      r.reference = r.initial;
    }
  }
  return start;
}

// iterative dynamic programming from the reference, several seeds; the best seed's motion,
// its re-check and its first-order optimality
void solve_by_idp(const ThrowSetup& setup, const ThrowingSpec& spec, const VelocityProfile& start,
                  const Eigen::Vector2d& delta, const NloptSettings& ns, const ProgressFn& progress,
                  ThrowingResult& r) {
  IdpSettings is = spec.idp;
  is.threads = spec.threads;
  is.backoff = spec.backoff;
  {
    const auto t0 = std::chrono::steady_clock::now();
    r.idp_seeds = run_idp_seeds(setup, start, delta, is, [&](double f, std::string_view s) {
      if (progress) progress(0.05 + 0.35 * f, s);
    });
    r.idp_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  for (size_t k = 0; k < r.idp_seeds.size(); ++k)
    if (better_profile(r.idp_seeds[k].evaluation, r.idp_seeds[r.idp_best_seed].evaluation))
      r.idp_best_seed = static_cast<int>(k);
  r.idp_run = r.idp_seeds[r.idp_best_seed];
  r.idp = record_motion(setup, spec, r.idp_run.best);
  r.idp_check = verify_profile(setup, r.idp_run.best, spec.check_refinement);
  r.idp_optimality = first_order_optimality(setup, r.idp_run.best, delta, ns);
  // IDP converged: every seed stopped on its rule, and its answer is first-order stationary
  r.idp_converged = r.idp_optimality.kkt_residual <= ns.kkt_tolerance;
  for (const IdpResult& sd : r.idp_seeds) r.idp_converged &= sd.converged;
}

// the answer's voltages (sampled densely, from the 16x simulation) applied open loop to
// the model with all four joints free, compared with the planned angles of that same
// simulation (the rk4 error of the coarse plan is checked apart)
void open_loop_replay(const ThrowSetup& setup, const ThrowingSpec& spec, const ThrowMotion& answer,
                      const std::vector<ThrowSample>& fine_samples, ThrowingResult& r) {
  const VoltageHistory vh = voltage_history(fine_samples);
  std::vector<double> times;
  for (const ThrowSample& x : fine_samples)
    if (times.empty() || x.t > times.back()) times.push_back(x.t);
  core::JointVector q0(4), qd0 = core::JointVector::Zero(4);
  q0 << spec.start, spec.theta3_start, spec.theta4_start;
  try {
    const ReplayResult rr = replay_voltages(setup, vh, q0, qd0, times, 1e-10, 1e-12, 1e-4);
    size_t j = 0;
    for (const ThrowSample& x : fine_samples) {
      while (j + 1 < rr.t.size() && rr.t[j] < x.t - 1e-12) ++j;
      r.replay_error = std::max(r.replay_error, (rr.q[j] - x.q).cwiseAbs().maxCoeff());
    }
    // keep the replay at the coarse series' times for the report
    j = 0;
    for (double t : answer.series.t) {
      while (j + 1 < rr.t.size() && rr.t[j] < t - 1e-12) ++j;
      if (!r.replay_t.empty() && r.replay_t.back() == rr.t[j]) continue;
      r.replay_t.push_back(rr.t[j]);
      r.replay_q.push_back(rr.q[j]);
    }
  } catch (const std::runtime_error& e) {
    r.replay_error = INFINITY;
  }
}

// integration accuracy: the answer with 16 times the rk4 steps, and its open-loop replay
// (voltages from 64 times the steps)
void check_answer(const ThrowSetup& setup, const ThrowingSpec& spec, const ThrowMotion& answer,
                  ThrowingResult& r) {
  ThrowSetup fine = setup;
  fine.steps_per_stage = 16 * setup.steps_per_stage;
  std::vector<ThrowSample> fine_samples;
  {
    const ProfileEvaluation ef = simulate_profile(fine, answer.profile, &fine_samples);
    r.rk4_energy_error = std::abs(ef.energy - answer.evaluation.energy) / std::abs(ef.energy);
    r.rk4_theta3_error = std::abs(ef.theta3_final - answer.evaluation.theta3_final);
  }
  // the replay's voltages from 64x the steps: linear between samples, their error falls
  // with the square of the spacing (the finer grids' faster voltage swings need it)
  ThrowSetup replay = setup;
  replay.steps_per_stage = 64 * setup.steps_per_stage;
  fine_samples.clear();
  simulate_profile(replay, answer.profile, &fine_samples);
  open_loop_replay(setup, spec, answer, fine_samples, r);
}
}  // namespace

bool prepare_throw(const ThrowingSpec& spec, ThrowSetup& setup, VelocityProfile& initial,
                   ThrowingResult& r) {
  try {
    setup = make_throw_setup(spec);
    initial = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate,
                          spec.tf, spec.stages);
  } catch (const std::invalid_argument& e) {
    r.message = std::string("invalid throwing set-up: ") + e.what();
    return false;
  }
  return true;
}

ThrowingResult solve_throwing(const ThrowingSpec& spec, const ProgressFn& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  ThrowingResult r;
  ThrowSetup setup;
  VelocityProfile initial;
  const Eigen::Vector2d delta = spec.release - spec.start;
  if (!prepare_throw(spec, setup, initial, r)) return r;
  if (progress) progress(0.0, "eq. 8 trajectory");
  r.initial = record_motion(setup, spec, initial);
  if (!r.initial.evaluation.finite) {
    r.message = "the eq. 8 trajectory's simulation diverged; check the arm parameters";
    return r;
  }

  r.initial_feasible = r.initial.evaluation.feasible;
  NloptSettings ns = spec.nlopt;
  ns.threads = spec.threads;
  ns.backoff = spec.backoff;
  const VelocityProfile start = feasible_start(setup, spec, initial, delta, ns, progress, r);
  solve_by_idp(setup, spec, start, delta, ns, progress, r);

  // the same constrained problem by SLSQP from several starts; the answer is the lowest
  // converged local optimum that the re-check finds feasible
  if (spec.run_nlopt) {
    if (progress) progress(0.4, "SLSQP (NLopt) from several starts");
    run_slsqp_starts(setup, spec, start, initial, delta, ns, r);
    r.nlopt_ran = r.slsqp_best_start >= 0;
    const double first_grid_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    if (progress) progress(0.7, "SLSQP on finer control grids");
    refine_grids(setup, spec, delta, ns, r);
    if (!r.grids.empty()) r.grids.front().run_time = first_grid_time;
  }
  if (progress) progress(0.95, "open-loop replay");
  // the answer: SLSQP's best start when it is feasible (also in the re-check); else IDP's
  // throw when that is; else whichever ran last, infeasible (the case is then not solved)
  const bool slsqp_feasible = r.nlopt_ran && r.nlopt_run.feasible && r.nlopt_check.feasible;
  const bool idp_feasible = r.idp.evaluation.feasible && r.idp_check.feasible;
  r.answer = slsqp_feasible || (r.nlopt_ran && !idp_feasible) ? "slsqp" : "idp";
  check_answer(r.answer == "slsqp" && !r.grids.empty()
                   ? grid_setup(setup, spec.stages, r.nlopt.profile.stages())
                   : setup,
               spec, r.answer == "slsqp" ? r.nlopt : r.idp, r);

  // ballistic flight of the ball after release
  auto flight_of = [&](const ThrowMotion& m) {
    if (m.series.t.size() < 2) return Flight{};
    const core::JointVector& qf = m.series.q.back();
    const core::JointVector& qdf = m.series.qd.back();
    return ballistic_flight(ball_position(setup.chain, qf), ball_velocity(setup.chain, qf, qdf),
                            spec.arm.gravity, spec.landing_height);
  };
  r.idp_flight = flight_of(r.idp);
  if (r.nlopt_ran) r.nlopt_flight = flight_of(r.nlopt);
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  decide_answer(spec, r);
  return r;
}

}  // namespace armstudy::studies
