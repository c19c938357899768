// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/planar_chain.hpp"

#include <cmath>

#include "core/check.hpp"

namespace armstudy::core {

double PlanarChain::total_mass() const {
  double m = 0.0;
  for (const Link& l : links) m += l.mass;
  for (const PointMass& p : point_masses) m += p.mass;
  return m;
}

PlanarChain make_chain(PlanarChain chain) {
  const int n = chain.num_links();
  ARM_THROW_UNLESS(n >= 1 && n <= kMaxLinks,
                   "chain has " << n << " links; should have 1 to " << kMaxLinks);
  for (int i = 0; i < n; ++i) {
    const Link& l = chain.links[i];
    ARM_THROW_UNLESS(std::isfinite(l.length) && l.length > 0,
                     "link " << i + 1 << " length " << l.length << " m should be > 0");
    ARM_THROW_UNLESS(std::isfinite(l.mass) && l.mass >= 0,
                     "link " << i + 1 << " mass " << l.mass << " kg should be >= 0");
    ARM_THROW_UNLESS(std::isfinite(l.inertia) && l.inertia >= 0,
                     "link " << i + 1 << " inertia " << l.inertia << " kg m^2 should be >= 0");
    ARM_THROW_UNLESS(std::isfinite(l.com) && std::isfinite(l.com_lateral),
                     "link " << i + 1 << " centre of mass should be finite");
  }
  for (size_t k = 0; k < chain.point_masses.size(); ++k) {
    const PointMass& p = chain.point_masses[k];
    ARM_THROW_UNLESS(p.link >= 0 && p.link < n, "point mass " << k + 1 << " is on link "
                                                              << p.link + 1 << "; chain has " << n
                                                              << " links");
    ARM_THROW_UNLESS(std::isfinite(p.mass) && p.mass >= 0,
                     "point mass " << k + 1 << " mass " << p.mass << " kg should be >= 0");
  }
  for (size_t k = 0; k < chain.spinners.size(); ++k) {
    const SpinningInertia& s = chain.spinners[k];
    ARM_THROW_UNLESS(s.coeffs.size() == n, "spinning inertia " << k + 1 << " has "
                                                               << s.coeffs.size()
                                                               << " coefficients; expected " << n);
    ARM_THROW_UNLESS(std::isfinite(s.inertia) && s.inertia >= 0,
                     "spinning inertia " << k + 1 << " " << s.inertia << " kg m^2 should be >= 0");
  }
  ARM_THROW_UNLESS(std::isfinite(chain.gravity) && chain.gravity >= 0,
                   "gravity " << chain.gravity << " m/s^2 should be >= 0");
  return chain;
}

}  // namespace armstudy::core
