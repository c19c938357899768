// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include <cmath>

#include "cases/tray_arm_case.hpp"

#include "cases/physical_bounds.hpp"
#include "core/types.hpp"

namespace armstudy::cases {
namespace {

// a number key that keeps `value` when absent or wrong (the error is recorded)
void tray_num(Map& m, std::string_view key, double& value, const NumberRule& rule) {
  // number_or: the default is the loader's, for the key reference (app/case_keys.hpp)
  if (const double v = m.number_or(key, value, rule); !std::isnan(v)) value = v;
}

void read_link(Map& section, std::string_view key, double& length, double& mass, double& com,
               double& inertia) {
  auto m = section.map(key);
  if (!m) return;
  // physical sizes within cases/physical_bounds.hpp, as a case's own arm
  tray_num(*m, "length_m", length, link_length_rule());
  tray_num(*m, "mass_kg", mass, mass_or_zero_rule());
  tray_num(*m, "com_m", com, offset_rule());
  tray_num(*m, "inertia_kg_m2", inertia, inertia_rule());
  m->finish();
}

}  // namespace

void read_tray_arm(Map& section, studies::TrayArmParams& a, double* width) {
  tray_num(section, "gravity_m_s2", a.gravity, NumberRule::range(1e-3, 100.0, "m/s^2"));
  read_link(section, "link1", a.l1, a.m1, a.r1, a.I1);
  read_link(section, "link2", a.l2, a.m2, a.r2, a.I2);
  if (auto t = section.map("tray")) {
    tray_num(*t, "circle_offset_m", a.circle_offset, link_length_rule());
    tray_num(*t, "mass_kg", a.m3, mass_or_zero_rule());
    tray_num(*t, "com_m", a.r3, offset_rule());
    tray_num(*t, "com_lateral_m", a.r3_lateral, offset_rule());
    tray_num(*t, "inertia_kg_m2", a.I3, inertia_rule());
    if (width) {
      if (const auto w = t->number("width_deg", NumberRule::range(1.0, 360.0, "deg")))
        *width = *w * core::kDeg;
    }
    t->finish();
  }
  bool solid_sphere = true;
  if (auto b = section.map("ball")) {
    tray_num(*b, "mass_kg", a.m4, mass_rule());
    tray_num(*b, "circle_radius_m", a.r4, link_length_rule());
    tray_num(*b, "radius_m", a.rb, link_length_rule());
    const YAML::Node in = b->get("inertia");
    if (in.IsDefined() && !(in.IsScalar() && in.Scalar() == "solid_sphere")) {
      const auto v = read_number(
          in, b->diag(), "'" + b->path_of("inertia") + "' (or 'solid_sphere')", inertia_rule());
      if (v) {
        a.Ib = *v;
        solid_sphere = false;
      }
    }
    b->finish();
  }
  if (solid_sphere) a.Ib = studies::solid_sphere_inertia(a.m4, a.rb);
}

}  // namespace armstudy::cases
