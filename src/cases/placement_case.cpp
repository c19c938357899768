// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/placement_case.hpp"

#include <cmath>
#include <cstdio>

#include "cases/arm_loader.hpp"
#include "studies/placement/geometry.hpp"

namespace armstudy::cases {
namespace {
using core::kDeg;
}  // namespace

core::PlanarChain placement_default_arm() {
  core::PlanarChain c;
  c.links = {{0.4, 4.0, 0.2, 0.0, core::uniform_rod_inertia(4.0, 0.4), true},
             {0.2, 2.0, 0.1, 0.0, core::uniform_rod_inertia(2.0, 0.2), true}};
  c.point_masses = {{1, 0.2, 0.0, 1.0}};
  c.gravity = 0.0;
  return core::make_chain(c);
}

Demand placement_demand(const studies::placement::Spec& spec, const YAML::Mark& mark) {
  // the solver's candidates: (nx_s + 1) start points x the directions in [0, 180] deg for
  // the full sweep, (thesis_divisions + 1)^2 for the thesis's own grid, plus the map's
  // nx x ny nodes; each is one trajectory of `samples` samples per (program,
  // configuration) pair
  const double starts = spec.nx_s + 1.0;
  const double directions = std::ceil(core::kPi / spec.phi_step) + 1.0;
  const double thesis = (spec.thesis_divisions + 1.0) * (spec.thesis_divisions + 1.0);
  const double candidates = starts * directions + thesis + double(spec.map_nx) * spec.map_ny;
  const double pairs = double(spec.programs.size()) * double(spec.configurations.size());
  Demand d;
  d.what = "the placement sweep";
  d.keys =
      "placement.nx_s, placement.phi_step_deg, placement.thesis_divisions, placement.map, "
      "placement.samples, "
      "placement.programs and placement.configurations";
  d.unit = "trajectory samples";
  d.work = candidates * pairs * spec.samples;
  d.work_budget = 1e10;
  d.work_per_second = 9e7;           // the bundled cases: 6.2e7 estimated samples in 0.7 s
  d.frames_rendered = pairs * 45.0;  // each optimum's animation (31 frames) and two strips
  // per candidate: its line and checks (~64 B) and one metrics record (56 B) and a status
  // byte per pair; the program tables hold ~100 B per sample. Measured (nx_s 500,
  // phi_step_deg 0.1, samples 21): 525 MB estimated, 422 MB peak resident; the work counts
  // unreachable candidates too (4.4 times the 3.4e7 samples evaluated)
  d.memory_bytes =
      candidates * (64.0 + pairs * 58.0) + double(spec.programs.size()) * spec.samples * 100.0;
  char detail[200];
  std::snprintf(detail, sizeof detail,
                "%.3g candidates (2 x %.0f start points x %.0f directions + %d x %d map "
                "nodes) x %.0f program/configuration pairs x %d samples",
                candidates, starts, directions, spec.map_nx, spec.map_ny, pairs, spec.samples);
  d.detail = detail;
  d.mark = mark;
  return d;
}

namespace {
namespace pl = studies::placement;

// the arm: a horizontal 2-link arm with both joints active
void check_placement_arm(Map& root, const core::PlanarChain& chain, bool from_model) {
  if (chain.gravity != 0.0 && from_model) {
    root.error("arm", "'arm.model' is an arm in a plane with gravity " +
                          format_number(chain.gravity) +
                          " m/s^2 (the model's gravity projected into the plane normal to its "
                          "joints' axes); expected 0: the placement study is a horizontal plane "
                          "(joint axes along the model's gravity)");
  } else if (chain.gravity != 0.0) {
    root.error("gravity", "'gravity' is " + format_number(chain.gravity) +
                              " m/s^2; expected 0: the placement study is a horizontal plane");
  }
  for (int i = 0; i < chain.num_links(); ++i) {
    if (!chain.links[i].active) {
      root.error("arm",
                 "'arm.links[" + std::to_string(i + 1) +
                     "]' has a passive joint; expected both joints active for a placement study");
    }
  }
}

// an imported arm's torque limits (the model's, both joints) where the case sets none
void model_torque_limit(Map& p, const model_import::ImportedArm& model, pl::Spec& spec) {
  std::vector<std::string>& origin = spec.arm_origin.limits;
  if (p.has("torque_limits_Nm")) {
    origin.push_back("placement.torque_limits_Nm: the case");
    return;
  }
  if (model.torque.size() != 2 || !model.torque[0] || !model.torque[1]) {
    origin.push_back("placement.torque_limits_Nm: none (the model states none for both joints)");
    return;
  }
  spec.torque_limit = std::array<double, 2>{model.torque[0]->value, model.torque[1]->value};
  origin.push_back("placement.torque_limits_Nm [" + format_number(model.torque[0]->value) + ", " +
                   format_number(model.torque[1]->value) + "] N m: the model's " +
                   model.torque[0]->from + "; " + model.torque[1]->from);
}

// the task: exactly one of length_fraction and length_m
void load_line_length(Map& p, const pl::Annulus& an, pl::Spec& spec) {
  const bool has_fraction = p.has("length_fraction"), has_length = p.has("length_m");
  if (has_fraction && has_length) {
    p.error("length_m",
            "'placement.length_m' and 'placement.length_fraction' are both given; "
            "expected exactly one of them");
  } else if (!has_fraction && !has_length) {
    p.error_here(
        "missing required key 'placement.length_fraction' (or 'placement.length_m'); "
        "expected the line length");
  }
  if (has_fraction) {
    if (const auto f = p.number("length_fraction", NumberRule::range(0.0, 1.0, ""))) {
      if (*f <= 0) {
        p.error("length_fraction", "'placement.length_fraction' is " + format_number(*f) +
                                       "; expected a fraction in (0, 1] of Lmax");
      }
      spec.length = *f * an.lmax;
    }
  }
  if (has_length) {
    if (const auto L = p.number("length_m", NumberRule::positive("m"))) {
      spec.length = *L;
      if (*L > an.lmax * (1 + 1e-12)) {
        p.error("length_m",
                "'placement.length_m' is " + format_number(*L) +
                    " m, longer than Lmax = 4 sqrt(L1 L2) = " + format_number(an.lmax) +
                    " m of this arm; expected 0 < length_m <= " + format_number(an.lmax));
      }
    }
  }
}

// placement.programs (by name) and placement.configurations (1 or 2)
void load_programs(Map& p, pl::Spec& spec) {
  std::vector<std::string> default_programs;
  for (const auto prog : spec.programs) default_programs.emplace_back(core::program_name(prog));
  if (auto progs = p.seq("programs", default_programs)) {
    spec.programs.clear();
    const auto names = core::program_names();
    for (size_t i = 0; i < progs->size(); ++i) {
      const YAML::Node n = progs->at(i);
      const std::string name = n.IsScalar() ? n.Scalar() : "";
      const auto prog = core::parse_program(name);
      if (!prog) {
        std::string list;
        for (const auto& s : names) list += (list.empty() ? "" : ", ") + s;
        std::string msg =
            "'" + progs->path_at(i) + "' is '" + brief(name) + "'; expected one of: " + list;
        if (const auto c = closest(name, names)) msg += " (did you mean '" + *c + "'?)";
        progs->diag().error(n.Mark(), msg);
        continue;
      }
      spec.programs.push_back(*prog);
    }
    if (progs->size() == 0)
      p.error("programs", "'placement.programs' is empty; expected at least one program");
  }
  const std::vector<double> default_configurations(spec.configurations.begin(),
                                                   spec.configurations.end());
  if (auto cfgs =
          p.numbers("configurations", NumberRule::range(1, 2, ""), 0, default_configurations)) {
    spec.configurations.clear();
    for (size_t i = 0; i < cfgs->size(); ++i) {
      const double c = (*cfgs)[i];
      if (c != 1.0 && c != 2.0) {
        p.error("configurations", "'placement.configurations[" + std::to_string(i + 1) + "]' is " +
                                      format_number(c) + "; expected 1 or 2");
        continue;
      }
      spec.configurations.push_back(int(c));
    }
  }
}

// the sweep's grid, samples, margin, limits, refinement and map
void load_sweep_settings(Map& p, const pl::Annulus& an, pl::Spec& spec) {
  spec.nx_s = p.integer_or("nx_s", spec.nx_s, 1, 10000);
  spec.thesis_divisions = p.integer_or("thesis_divisions", spec.thesis_divisions, 1, 1000);
  spec.phi_step =
      p.number_or("phi_step_deg", spec.phi_step / kDeg, NumberRule::range(1e-3, 45.0, "deg")) *
      kDeg;
  if (!(spec.phi_step > 0)) spec.phi_step = kDeg;  // an error was recorded
  spec.samples = p.integer_or("samples", spec.samples, 21, 100001);
  spec.singularity_margin =
      p.number_or("singularity_margin_m", spec.singularity_margin, NumberRule::positive("m"));
  if (std::isfinite(spec.singularity_margin) &&
      spec.singularity_margin >= (an.outer - an.inner) / 2) {
    p.error("singularity_margin_m", "'placement.singularity_margin_m' is " +
                                        format_number(spec.singularity_margin) +
                                        " m; expected less than half the annulus width, " +
                                        format_number((an.outer - an.inner) / 2) + " m");
  }
  if (const auto t = p.numbers("torque_limits_Nm", NumberRule::positive("N m"), 2))
    spec.torque_limit = std::array<double, 2>{(*t)[0], (*t)[1]};
  if (const auto w = p.numbers("power_limits_W", NumberRule::positive("W"), 2))
    spec.power_limit = std::array<double, 2>{(*w)[0], (*w)[1]};
  spec.refine = p.boolean_or("refine", spec.refine);
  if (auto m = p.map("map")) {
    spec.map_nx = m->integer_or("nx", spec.map_nx, 2, 1000);
    spec.map_ny = m->integer_or("ny", spec.map_ny, 2, 1000);
    m->finish();
  }
}

// placement.cycle_time: the cycle-time objective's limits and grids (both limits required)
void load_cycle_time(Map& p, pl::Spec& spec) {
  auto m = p.map("cycle_time");
  if (!m) return;
  pl::CycleTimeSpec ct;
  const auto pair = [](const std::vector<double>& v) {
    return (core::JointVector(2) << v[0], v[1]).finished();
  };
  for (const char* key : {"velocity_limit_rad_s", "torque_limit_Nm"})
    if (!m->has(key))
      m->error_here("missing required key '" + m->path_of(key) +
                    "'; expected the limits of joints 1 and 2");
  if (const auto v = m->numbers("velocity_limit_rad_s", NumberRule::positive("rad/s"), 2))
    ct.velocity_limit = pair(*v);
  if (const auto v = m->numbers("torque_limit_Nm", NumberRule::positive("N m"), 2))
    ct.torque_limit = pair(*v);
  if (const auto v = m->numbers("acceleration_limit_rad_s2", NumberRule::positive("rad/s^2"), 2))
    ct.acceleration_limit = pair(*v);
  ct.map_grid_points = m->integer_or("map_grid_points", ct.map_grid_points, 3, 100000);
  ct.grid_points = m->integer_or("grid_points", ct.grid_points, 3, 100000);
  ct.checks_per_interval = m->integer_or("checks_per_interval", ct.checks_per_interval, 1, 100);
  ct.tolerance_rel = m->number_or("tolerance_rel", ct.tolerance_rel, NumberRule::positive(""));
  m->finish();
  spec.cycle_time = ct;
}

// placement.evaluate: fixed placements, each by (x_s_m, phi_deg) or root_xy_m
void load_evaluations(Map& p, pl::Spec& spec) {
  auto ev = p.seq("evaluate");
  if (!ev) return;
  for (size_t i = 0; i < ev->size(); ++i) {
    auto e = ev->map_at(i);
    if (!e) continue;
    pl::EvaluationSpec es;
    es.label = e->string_or("label", "placement " + std::to_string(i + 1));
    const bool line = e->has("x_s_m") || e->has("phi_deg"), rootxy = e->has("root_xy_m");
    if (line && rootxy) {
      e->error("root_xy_m", "'" + e->path_of("root_xy_m") +
                                "' and 'x_s_m'/'phi_deg' are both given; expected one placement");
    } else if (rootxy) {
      if (const auto r = e->numbers("root_xy_m", NumberRule::any("m"), 2)) {
        const Eigen::Vector2d lp = pl::line_of_root({(*r)[0], (*r)[1]});
        es.x_s = lp[0];
        es.phi = lp[1];
      }
    } else if (line) {
      es.x_s = e->required_number("x_s_m", NumberRule::positive("m"));
      es.phi = e->required_number("phi_deg", NumberRule::range(-360.0, 360.0, "deg")) * kDeg;
    } else {
      e->error_here("'" + ev->path_at(i) +
                    "' gives no placement; expected x_s_m and phi_deg, or root_xy_m");
    }
    e->finish();
    spec.evaluations.push_back(es);
  }
}
}  // namespace

studies::placement::Spec load_placement(Map& root) {
  pl::Spec spec;  // its defaults are the defaults of the keys below (written once, in spec.hpp)
  std::optional<model_import::ImportedArm> model;
  spec.chain = load_arm(root, placement_default_arm(), 2, &model);
  check_placement_arm(root, spec.chain, model.has_value());
  if (model) spec.arm_origin = arm_origin(*model);
  const pl::Annulus an = pl::annulus(spec.chain.links[0].length, spec.chain.links[1].length);

  auto p = root.map("placement");
  if (!p) {
    if (!root.has("placement"))
      root.error_here(
          "missing required key 'placement'; expected the placement task (length_fraction "
          "or length_m, ...)");
    return spec;
  }
  load_line_length(*p, an, spec);
  spec.duration = p->number_or("duration_s", spec.duration, NumberRule::positive("s"));
  load_programs(*p, spec);
  load_sweep_settings(*p, an, spec);
  load_evaluations(*p, spec);
  load_cycle_time(*p, spec);
  spec.threads = p->integer_or("threads", spec.threads, 0, 256);
  if (model) model_torque_limit(*p, *model, spec);
  p->finish();
  if (p->diag().empty()) p->diag().demand(placement_demand(spec, p->node().Mark()));
  return spec;
}

}  // namespace armstudy::cases
