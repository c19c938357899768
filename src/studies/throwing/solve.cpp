#include "studies/throwing/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "core/kinematics.hpp"

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

ThrowingResult solve_throwing(const ThrowingSpec& spec, const ProgressFn& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  ThrowingResult r;
  ThrowSetup setup;
  VelocityProfile initial;
  const Eigen::Vector2d delta = spec.release - spec.start;
  try {
    setup = make_throw_setup(spec);
    initial = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate,
                          spec.tf, spec.stages);
  } catch (const std::invalid_argument& e) {
    r.message = std::string("invalid throwing set-up: ") + e.what();
    return r;
  }
  if (progress) progress(0.0, "eq. 8 trajectory");
  r.initial = record_motion(setup, spec, initial);
  if (!r.initial.evaluation.finite) {
    r.message = "the eq. 8 trajectory's simulation diverged; check the arm parameters";
    return r;
  }

  r.initial_feasible = r.initial.evaluation.feasible;

  // the feasible reference: eq. 8 itself, or the feasible profile nearest to it
  NloptSettings ns = spec.nlopt;
  ns.threads = spec.threads;
  ns.backoff = spec.backoff;
  VelocityProfile start = initial;
  if (r.initial_feasible) {
    r.reference_kind = "eq8";
    r.reference = r.initial;
  } else {
    if (progress) progress(0.02, "repair of eq. 8 (nearest feasible)");
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

  // iterative dynamic programming from the reference, several seeds
  IdpSettings is = spec.idp;
  is.threads = spec.threads;
  is.backoff = spec.backoff;
  {
    const auto t0 = std::chrono::steady_clock::now();
    r.idp_seeds = run_idp_seeds(setup, start, delta, is, [&](double f, std::string_view s) {
      if (progress) progress(0.05 + 0.55 * f, s);
    });
    r.idp_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  r.idp_converged = true;
  for (size_t k = 0; k < r.idp_seeds.size(); ++k) {
    r.idp_converged &= r.idp_seeds[k].converged;
    if (better_profile(r.idp_seeds[k].evaluation, r.idp_seeds[r.idp_best_seed].evaluation))
      r.idp_best_seed = static_cast<int>(k);
  }
  r.idp_run = r.idp_seeds[r.idp_best_seed];
  r.idp = record_motion(setup, spec, r.idp_run.best);
  r.idp_check = verify_profile(setup, r.idp_run.best, spec.check_refinement);
  r.saving_percent = 100.0 * (r.reference.evaluation.energy - r.idp.evaluation.energy) /
                     std::abs(r.reference.evaluation.energy);

  // the same constrained problem by SLSQP on the same parameterisation, same start
  if (spec.run_nlopt) {
    if (progress) progress(0.6, "SLSQP (NLopt)");
    r.nlopt_run = run_nlopt(setup, start, delta, ns);
    r.nlopt = record_motion(setup, spec, r.nlopt_run.best);
    r.nlopt_check = verify_profile(setup, r.nlopt_run.best, spec.check_refinement);
    r.nlopt_ran = true;
  }
  if (progress) progress(0.95, "open-loop replay");

  // integration accuracy: the optimum with 16 times the rk4 steps
  ThrowSetup fine = setup;
  fine.steps_per_stage = 16 * setup.steps_per_stage;
  std::vector<ThrowSample> fine_samples;
  {
    const ProfileEvaluation ef = simulate_profile(fine, r.idp.profile, &fine_samples);
    r.rk4_energy_error = std::abs(ef.energy - r.idp.evaluation.energy) / std::abs(ef.energy);
    r.rk4_theta3_error = std::abs(ef.theta3_final - r.idp.evaluation.theta3_final);
  }
  // the optimum's voltages (sampled densely, from the 16x simulation) applied open loop to
  // the model with all four joints free, compared with the planned angles of that same
  // simulation (the rk4 error of the coarse plan is checked apart, above)
  {
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
      for (double t : r.idp.series.t) {
        while (j + 1 < rr.t.size() && rr.t[j] < t - 1e-12) ++j;
        if (!r.replay_t.empty() && r.replay_t.back() == rr.t[j]) continue;
        r.replay_t.push_back(rr.t[j]);
        r.replay_q.push_back(rr.q[j]);
      }
    } catch (const std::runtime_error& e) {
      r.replay_error = INFINITY;
    }
  }

  // ballistic flight of the ball after release
  const core::JointVector& qf = r.idp.series.q.back();
  const core::JointVector& qdf = r.idp.series.qd.back();
  r.flight = ballistic_flight(ball_position(setup.chain, qf), ball_velocity(setup.chain, qf, qdf),
                              spec.arm.gravity, spec.landing_height);
  if (r.nlopt_ran && r.nlopt.series.t.size() >= 2) {
    const core::JointVector& qn = r.nlopt.series.q.back();
    const core::JointVector& qdn = r.nlopt.series.qd.back();
    r.nlopt_flight =
        ballistic_flight(ball_position(setup.chain, qn), ball_velocity(setup.chain, qn, qdn),
                         spec.arm.gravity, spec.landing_height);
  }
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (!r.flight.reaches) {
    r.message = "the ball never reaches the landing height " + fixed(spec.landing_height, 3) +
                " m: its apex is " + fixed(r.flight.apex, 3) + " m";
    return r;
  }
  r.status = Status::kSolved;
  const std::string ref = r.reference_kind == "eq8"        ? "eq. 8"
                          : r.reference_kind == "repaired" ? "repaired eq. 8"
                                                           : "infeasible eq. 8";
  // the sentence leads with the lowest energy of a converged answer that the independent
  // re-check found feasible; the other optimiser follows as the comparison
  const std::string idp_words = std::string("IDP") + (r.idp_converged ? "" : " (NOT converged)") +
                                (r.idp_check.feasible ? "" : " (infeasible in the re-check)") +
                                " " + fixed(r.idp.evaluation.energy, 3) + " J";
  const std::string ref_words = ref + ": " + fixed(r.reference.evaluation.energy, 3) + " J";
  const bool slsqp_answer = r.nlopt_ran && r.nlopt_run.converged && r.nlopt_run.feasible &&
                            r.nlopt_check.feasible && r.nlopt_flight.reaches &&
                            r.nlopt.evaluation.energy < r.idp.evaluation.energy &&
                            !(r.idp_converged && r.idp_check.feasible &&
                              r.idp.evaluation.energy <= r.nlopt.evaluation.energy);
  if (slsqp_answer) {
    r.answer = "slsqp";
    const double saving = 100.0 * (r.reference.evaluation.energy - r.nlopt.evaluation.energy) /
                          r.reference.evaluation.energy;
    r.message =
        "lowest-energy throw found: SLSQP's, " + fixed(r.nlopt.evaluation.energy, 3) +
        " J, converged and feasible in the re-check (" + ref_words + ", saving " +
        fixed(saving, 1) + " %); " + idp_words + " (saving " + fixed(r.saving_percent, 1) +
        " %), a stall above it; the ball lands at x = " + fixed(r.nlopt_flight.landing.x(), 3) +
        " m";
  } else {
    r.message = idp_words + " (" + ref_words + ", saving " + fixed(r.saving_percent, 1) +
                " %); ball lands at x = " + fixed(r.flight.landing.x(), 3) + " m";
    if (r.nlopt_ran)
      r.message += "; SLSQP" + std::string(r.nlopt_run.converged ? "" : " (NOT converged)") + ": " +
                   fixed(r.nlopt.evaluation.energy, 3) + " J" +
                   (r.nlopt_run.feasible && r.nlopt_check.feasible ? "" : " (infeasible)");
  }
  return r;
}

}  // namespace armstudy::studies
