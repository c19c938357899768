// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/throwing_case.hpp"

#include <cmath>
#include <cstdio>

#include "core/types.hpp"

namespace armstudy::cases {
namespace {

// a number key that keeps `value` when absent or wrong (the error is recorded)
void num(Map& m, std::string_view key, double& value, const NumberRule& rule) {
  // number_or: the default is the loader's, for the key reference (app/case_keys.hpp)
  if (const double v = m.number_or(key, value, rule); !std::isnan(v)) value = v;
}

// throwing.motors: the motors (eq. 5) and their limits
void read_motors(Map& m, studies::ThrowingSpec& s) {
  num(m, "kt_Nm_per_A", s.motor.kt, NumberRule::positive("N m/A"));
  num(m, "kv_V_s_per_rad", s.motor.kv, NumberRule::positive("V s/rad"));
  num(m, "resistance_ohm", s.motor.Ra, NumberRule::positive("ohm"));
  num(m, "viscous_Nm_s_per_rad", s.motor.Dm, NumberRule::non_negative("N m s/rad"));
  num(m, "coulomb_Nm", s.motor.tau_f, NumberRule::non_negative("N m"));
  num(m, "coulomb_band_rad_s", s.motor.coulomb_band, NumberRule::range(0.0, 1.0, "rad/s"));
  num(m, "rotor_inertia_kg_m2", s.arm.rotor_inertia, NumberRule::non_negative("kg m^2"));
  if (const auto mount = m.choice("motor2", {"on_link1", "on_base"}))
    s.arm.motor2 =
        *mount == "on_base" ? studies::Motor2Mount::kOnBase : studies::Motor2Mount::kOnLink1;
  num(m, "voltage_max_V", s.voltage_max, NumberRule::positive("V"));
  num(m, "current_max_A", s.current_max, NumberRule::positive("A"));
  num(m, "power_max_W", s.power_max, NumberRule::positive("W"));
  s.count_regeneration = m.boolean_or("count_regeneration", s.count_regeneration);
  m.finish();
}

// throwing.task: start and release angles, release rates, duration, landing height
void read_task(Map& t, studies::ThrowingSpec& s) {
  if (const auto v = t.numbers("start_deg", NumberRule::range(-360, 360, "deg"), 4,
                               {s.start[0] / core::kDeg, s.start[1] / core::kDeg,
                                s.theta3_start / core::kDeg, s.theta4_start / core::kDeg})) {
    s.start = {(*v)[0] * core::kDeg, (*v)[1] * core::kDeg};
    s.theta3_start = (*v)[2] * core::kDeg;
    s.theta4_start = (*v)[3] * core::kDeg;
  }
  if (const auto v = t.numbers(
          "release_deg", NumberRule::range(-360, 360, "deg"), 3,
          {s.release[0] / core::kDeg, s.release[1] / core::kDeg, s.theta3_release / core::kDeg})) {
    s.release = {(*v)[0] * core::kDeg, (*v)[1] * core::kDeg};
    s.theta3_release = (*v)[2] * core::kDeg;
  }
  if (const auto v = t.numbers("release_rate_rad_s", NumberRule::range(-200, 200, "rad/s"), 2,
                               {s.release_rate[0], s.release_rate[1]}))
    s.release_rate = {(*v)[0], (*v)[1]};
  num(t, "duration_s", s.tf, NumberRule::range(0.01, 60.0, "s"));
  num(t, "landing_height_m", s.landing_height, NumberRule::range(-100.0, 100.0, "m"));
  t.finish();
}

// throwing.constraints: the contact, friction and release constraints
void read_constraints(Map& c, studies::ThrowingSpec& s) {
  num(c, "contact_margin_N", s.contact_margin, NumberRule::non_negative("N"));
  num(c, "friction_coefficient", s.friction_coefficient, NumberRule::range(1e-3, 10.0, ""));
  if (const auto v = c.number("release_tolerance_deg", NumberRule::positive("deg")))
    s.release_tolerance = *v * core::kDeg;
  num(c, "backoff", s.backoff, NumberRule::range(0.0, 0.2, ""));
  c.finish();
}

// throwing.idp: iterative dynamic programming: stages, steps and its search
void read_idp(Map& i, studies::ThrowingSpec& s) {
  s.stages = i.integer_or("stages", s.stages, 2, 64);
  s.steps_per_stage = i.integer_or("steps_per_stage", s.steps_per_stage, 1, 400);
  s.idp.iterations = i.integer_or("iterations", s.idp.iterations, 1, 1000);
  s.idp.max_passes = i.integer_or("max_passes", s.idp.max_passes, 1, 1000);
  num(i, "tolerance", s.idp.tolerance, NumberRule::range(1e-9, 0.5, ""));
  s.idp.quiet_passes = i.integer_or("quiet_passes", s.idp.quiet_passes, 1, 100);
  num(i, "restore", s.idp.restore, NumberRule::range(1e-3, 1.0, ""));
  s.idp.candidates = i.integer_or("candidates", s.idp.candidates, 1, 200);
  num(i, "shrink", s.idp.shrink, NumberRule::range(1e-3, 0.999, ""));
  if (const auto v = i.numbers("region_rad_s", NumberRule::positive("rad/s"), 2,
                               {s.idp.region[0], s.idp.region[1]}))
    s.idp.region = {(*v)[0], (*v)[1]};
  s.idp.seed =
      static_cast<unsigned>(i.integer_or("seed", static_cast<int>(s.idp.seed), 0, 2147483647));
  s.idp.seeds = i.integer_or("seeds", s.idp.seeds, 1, 64);
  i.finish();
}

// throwing.nlopt: SLSQP (NLopt): its stopping rules, restarts and perturbed starts
void read_nlopt(Map& n, studies::ThrowingSpec& s) {
  s.run_nlopt = n.boolean_or("enabled", s.run_nlopt);
  s.nlopt.max_evaluations = n.integer_or("max_evaluations", s.nlopt.max_evaluations, 1, 10000);
  num(n, "max_time_s", s.nlopt.max_time, NumberRule::range(0.1, 3600.0, "s"));
  num(n, "ftol_rel", s.nlopt.ftol_rel, NumberRule::range(1e-12, 0.1, ""));
  num(n, "xtol_rel", s.nlopt.xtol_rel, NumberRule::range(1e-12, 0.1, ""));
  num(n, "fd_step_rad_s", s.nlopt.fd_step, NumberRule::range(1e-9, 1e-1, "rad/s"));
  s.nlopt.exact_gradient = n.boolean_or("exact_gradient", s.nlopt.exact_gradient);
  num(n, "kkt_tolerance", s.nlopt.kkt_tolerance, NumberRule::range(1e-8, 1.0, ""));
  num(n, "restart_gain", s.nlopt.restart_gain, NumberRule::range(1e-12, 0.1, ""));
  s.nlopt.restarts = n.integer_or("restarts", s.nlopt.restarts, 0, 100);
  s.nlopt.perturbed_starts = n.integer_or("perturbed_starts", s.nlopt.perturbed_starts, 0, 64);
  num(n, "perturbation_rad_s", s.nlopt.perturbation, NumberRule::positive("rad/s"));
  s.nlopt.smooth_starts = n.integer_or("smooth_starts", s.nlopt.smooth_starts, 0, 64);
  num(n, "smooth_amplitude_rad_s", s.nlopt.smooth_amplitude, NumberRule::positive("rad/s"));
  s.nlopt.smooth_modes = n.integer_or("smooth_modes", s.nlopt.smooth_modes, 1, 16);
  s.nlopt.hops = n.integer_or("hops", s.nlopt.hops, 0, 64);
  num(n, "hop_size_rad_s", s.nlopt.hop_size, NumberRule::positive("rad/s"));
  n.finish();
}

// throwing.grid: the control grids after the first (studies/throwing/grid_sequence.hpp)
void read_grid(Map& g, studies::ThrowingSpec& s) {
  s.grid.refinements = g.integer_or("refinements", s.grid.refinements, 0, 4);
  num(g, "tolerance", s.grid.tolerance, NumberRule::range(1e-6, 0.5, ""));
  s.grid.refine_best = g.integer_or("refine_best", s.grid.refine_best, 1, 16);
  s.grid.require_converged = g.boolean_or("require_converged", s.grid.require_converged);
  s.grid.exact_gradient = g.boolean_or("exact_gradient", s.grid.exact_gradient);
  g.finish();
}

// throwing.checks: the checks on the answer
void read_checks(Map& c, studies::ThrowingSpec& s) {
  num(c, "replay_tolerance_rad", s.replay_tolerance, NumberRule::positive("rad"));
  s.allow_not_converged = c.boolean_or("allow_not_converged", s.allow_not_converged);
  s.check_refinement = c.integer_or("refinement", s.check_refinement, 2, 16);
  c.finish();
}
}  // namespace

studies::ThrowingSpec load_throwing_spec(Map& root) {
  studies::ThrowingSpec s;
  s.arm.Ib = studies::solid_sphere_inertia(s.arm.m4, s.arm.rb);
  auto sec = root.map("throwing");
  if (!sec) return s;
  read_tray_arm(*sec, s.arm, &s.tray_width);
  if (auto m = sec->map("motors")) read_motors(*m, s);
  if (auto t = sec->map("task")) read_task(*t, s);
  if (auto c = sec->map("constraints")) read_constraints(*c, s);
  if (auto i = sec->map("idp")) read_idp(*i, s);
  if (auto n = sec->map("nlopt")) read_nlopt(*n, s);
  if (auto g = sec->map("grid")) read_grid(*g, s);
  if (auto c = sec->map("checks")) read_checks(*c, s);
  s.threads = sec->integer_or("threads", s.threads, 1, 64);
  sec->finish();
  if (sec->diag().empty()) sec->diag().demand(throwing_demand(s, sec->node().Mark()));
  return s;
}

Demand throwing_demand(const studies::ThrowingSpec& s, const YAML::Mark& mark) {
  // IDP: for each seed, per iteration of each pass (at most max_passes), every free stage
  // node (stages - 1) tries `candidates` profiles, each simulated over stages x
  // steps_per_stage RK4 steps; SLSQP: each
  // iteration a central-difference gradient over 2 (stages - 1) rates
  const double steps = double(s.stages) * s.steps_per_stage;
  const double idp = double(s.idp.seeds) * s.idp.max_passes * s.idp.iterations * (s.stages - 1.0) *
                     s.idp.candidates;
  // SLSQP: every start (the reference, IDP's, eq. 8's, the perturbed and smooth ones, the hops)
  // with its budget of gradient evaluations
  const double starts = 3.0 + s.nlopt.perturbed_starts + s.nlopt.smooth_starts + s.nlopt.hops;
  // then each finer grid (the same RK4 step, 2^l x the stages): refine_best starts on the
  // first, one on the others, each a gradient of 4 (stages - 1) + 1 simulations, or exact
  // (BM_ThrowGradient: about 12 + (stages - 1) / 8 simulations' time)
  auto gradient = [&](double stages, bool exact) {
    return exact ? 12.0 + (stages - 1.0) / 8.0 : 4.0 * (stages - 1.0) + 1.0;
  };
  const bool fine_exact = s.nlopt.exact_gradient || s.grid.exact_gradient;
  double grids = 0.0;
  for (int l = 1; l <= s.grid.refinements; ++l)
    grids += (l == 1 ? s.grid.refine_best + 1.0 : 2.0) * s.nlopt.max_evaluations *
             gradient(s.stages << l, fine_exact);
  const double start = s.nlopt.max_evaluations * gradient(s.stages, s.nlopt.exact_gradient);
  const double nlopt = s.run_nlopt ? starts * start + grids : 0.0;
  Demand d;
  d.what = "the throwing optimisation";
  d.keys =
      "throwing.idp.seeds, throwing.idp.max_passes, throwing.idp.iterations, throwing.idp.stages, "
      "throwing.idp.candidates, "
      "throwing.idp.steps_per_stage, throwing.nlopt.max_evaluations, "
      "throwing.nlopt.smooth_starts, throwing.nlopt.hops, "
      "throwing.nlopt.exact_gradient, throwing.grid.refinements and throwing.grid.exact_gradient";
  d.unit = "RK4 steps";
  d.work = (idp + nlopt) * steps;
  // the sensitivity part's warm re-solves (app/run_order.hpp's fraction, measured before the
  // global phase came) do not repeat its smooth starts
  if (s.run_nlopt) d.resolve_base = (idp + nlopt - s.nlopt.smooth_starts * start) * steps;
  d.work_budget = 1e9;
  d.work_per_second = 7e6;  // the bundled cases: 3.1e7 and 2.3e7 steps in 4.6 and 3.8 s
  d.frames_rendered = (s.run_nlopt ? 2.0 : 1.0) * 45.0;  // each optimiser's throw
  // the recorded iterations and the motions' series
  d.memory_bytes =
      double(s.idp.seeds) * s.idp.max_passes * s.idp.iterations * 1000.0 + steps * 2000.0;
  char detail[200];
  std::snprintf(detail, sizeof detail, "%.3g IDP and %.3g SLSQP simulations of %.0f RK4 steps", idp,
                nlopt, steps);
  d.detail = detail;
  d.mark = mark;
  return d;
}

}  // namespace armstudy::cases
