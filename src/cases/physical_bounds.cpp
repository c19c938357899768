// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/physical_bounds.hpp"

namespace armstudy::cases {

std::vector<std::string> chain_size_problems(const core::PlanarChain& chain,
                                             const std::vector<std::string>& joint_names) {
  std::vector<std::string> out;
  const auto check = [&](int link, const std::string& what, double v, const NumberRule& rule) {
    const std::string bad = violation(v, rule);
    if (bad.empty()) return;
    std::string name = "link " + std::to_string(link + 1);
    if (link < static_cast<int>(joint_names.size()) && !joint_names[link].empty())
      name += " (joint '" + brief(joint_names[link]) + "')";
    out.push_back(name + ": the " + what + " is " + exact_number(v) + " " + rule.unit + "; " + bad);
  };
  for (int i = 0; i < chain.num_links(); ++i) {
    const core::Link& l = chain.links[i];
    check(i, "length", l.length, link_length_rule());
    check(i, "mass", l.mass, mass_or_zero_rule());
    check(i, "inertia about the centre of mass", l.inertia, inertia_rule());
    check(i, "centre of mass along the link", l.com, offset_rule());
    check(i, "centre of mass across the link", l.com_lateral, offset_rule());
  }
  for (const core::PointMass& p : chain.point_masses) {
    check(p.link, "point mass", p.mass, mass_or_zero_rule());
    check(p.link, "point mass's place along the link", p.x, offset_rule());
    check(p.link, "point mass's place across the link", p.y, offset_rule());
  }
  return out;
}

}  // namespace armstudy::cases
