// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/arm_loader.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "cases/input_file.hpp"
#include "cases/physical_bounds.hpp"

namespace armstudy::cases {

namespace {
// one entry of arm.links: length, mass, centre of mass, inertia ('rod' or a number), joint
core::Link read_arm_link(Map& lm) {
  core::Link l;
  // physical sizes within cases/physical_bounds.hpp: what MuJoCo's model of the arm takes
  l.length = lm.required_number("length", link_length_rule());
  // mass 0 is allowed only for a link that carries point masses (checked below)
  l.mass = lm.required_number("mass", mass_or_zero_rule());
  l.com = lm.number_or("com", std::isfinite(l.length) ? l.length / 2 : 0.0, offset_rule());
  l.com_lateral = lm.number_or("com_lateral", 0.0, offset_rule());
  const YAML::Node in = lm.get("inertia");
  if (!in.IsDefined() || (in.IsScalar() && in.Scalar() == "rod")) {
    l.inertia = core::uniform_rod_inertia(l.mass, l.length);
  } else {
    const auto v =
        read_number(in, lm.diag(), "'" + lm.path_of("inertia") + "' (or 'rod')", inertia_rule());
    l.inertia = v ? *v : 0.0;
  }
  const auto joint = lm.choice("joint", {"active", "passive"});
  l.active = !joint || *joint == "active";
  lm.finish();
  return l;
}

// arm.point_masses, each on one of the n links
void read_point_masses(Map& arm, int n, core::PlanarChain& chain) {
  auto pms = arm.seq("point_masses");
  if (!pms) return;
  for (size_t i = 0; i < pms->size(); ++i) {
    auto pm = pms->map_at(i);
    if (!pm) continue;
    core::PointMass p;
    // a whole number >= 1 as a key (the key reference's range), then one of this arm's links
    p.link = pm->integer_or("link", 1, 1, std::numeric_limits<int>::max()) - 1;
    if (p.link >= std::max(1, n)) {
      pm->error("link", "'" + pm->path_of("link") + "' is " + std::to_string(p.link + 1) +
                            "; should be in [1, " + std::to_string(std::max(1, n)) + "]");
      p.link = 0;
    }
    p.x = pm->required_number("at", offset_rule());
    p.y = pm->number_or("lateral", 0.0, offset_rule());
    p.mass = pm->required_number("mass", mass_rule());
    pm->finish();
    chain.point_masses.push_back(p);
  }
}

// a massless link must carry a point mass: otherwise it is a typo, not a model
void check_massless_links(const core::PlanarChain& chain,
                          std::vector<std::optional<Map>>& link_maps) {
  const int n = static_cast<int>(chain.links.size());
  for (int i = 0; i < n; ++i) {
    if (chain.links[i].mass != 0.0) continue;
    bool carries = false;
    for (const auto& p : chain.point_masses) carries |= p.link == i && p.mass > 0;
    if (!carries && link_maps[i]) {
      auto& lm = link_maps[i];
      lm->error("mass", "'" + lm->path_of("mass") +
                            "' is 0 kg for a massless link without a "
                            "point mass; expected mass > 0 kg, or a point mass on this link");
    }
  }
}

// `arm: {model: FILE}`: the file read like every input, then through MuJoCo's parser
core::PlanarChain load_arm_model(Map& root, Map& arm, const core::PlanarChain& fallback,
                                 int links_required,
                                 std::optional<model_import::ImportedArm>* imported) {
  const auto file = arm.string("model");
  for (const char* k : {"links", "payload", "point_masses"})
    if (arm.has(k))
      arm.error(k, "'arm." + std::string(k) +
                       "' is given beside 'arm.model'; expected one of them (the model "
                       "gives the links, masses and payload)");
  arm.finish();
  if (root.has("gravity")) {
    root.get("gravity");
    root.error("gravity",
               "'gravity' is given with 'arm.model'; expected none: gravity is the model's "
               "(<option gravity>, MuJoCo's default for a URDF), projected into its plane");
  }
  if (!file) return fallback;
  const std::filesystem::path case_dir = std::filesystem::path(arm.diag().path()).parent_path();
  const std::string path = (case_dir / *file).lexically_normal().string();
  const std::string where = "'arm.model' (" + path + ")";
  std::string bytes, why;
  bool runtime = false;
  InputFileRules rules;
  rules.max_bytes = kMaxModelBytes;
  rules.kind = "robot description (URDF or MJCF)";
  if (!read_input_file(path, rules, &bytes, &why, &runtime)) {
    arm.error("model", where + ": " + why);
    return fallback;
  }
  try {
    model_import::ImportedArm a = model_import::import_arm(path, bytes);
    const int n = a.chain.num_links();
    if (links_required > 0 && n != links_required) {
      arm.error("model", where + ": the model has " + std::to_string(n) + " hinges; expected " +
                             std::to_string(links_required) + " links for this study");
      return fallback;
    }
    // the model's sizes within the bounds a case's own arm has (cases/physical_bounds.hpp)
    const std::vector<std::string> sizes = chain_size_problems(a.chain, a.joint_names);
    for (const std::string& size : sizes) arm.error("model", where + ": " + size);
    if (!sizes.empty()) return fallback;
    a.path = *file;
    core::PlanarChain chain = a.chain;
    if (imported) *imported = std::move(a);
    return chain;
  } catch (const std::exception& e) {
    arm.error("model", "'arm.model': " + std::string(e.what()));
    return fallback;
  }
}
}  // namespace

core::PlanarChain load_arm(Map& root, const core::PlanarChain& fallback, int links_required,
                           std::optional<model_import::ImportedArm>* imported) {
  auto arm = root.map("arm");
  if (arm && arm->has("model"))
    return load_arm_model(root, *arm, fallback, links_required, imported);
  core::PlanarChain chain = fallback;
  chain.gravity =
      root.number_or("gravity", fallback.gravity, NumberRule::range(0.0, 100.0, "m/s^2"));
  if (std::isnan(chain.gravity)) chain.gravity = fallback.gravity;
  if (!arm) return chain;
  const size_t errors_before = arm->diag().count();

  auto links = arm->seq("links");
  if (!links) {
    if (!arm->has("links"))
      arm->error_here("missing required key 'arm.links'; expected a list of links");
    arm->number("payload", mass_or_zero_rule());
    arm->seq("point_masses");
    arm->finish();
    return chain;
  }
  if (links->size() == 0 || links->size() > static_cast<size_t>(core::kMaxLinks) ||
      (links_required > 0 && links->size() != static_cast<size_t>(links_required))) {
    const std::string want = links_required > 0
                                 ? std::to_string(links_required) + " links for this study"
                                 : "1 to " + std::to_string(core::kMaxLinks) + " links";
    arm->error("links",
               "'arm.links' has " + std::to_string(links->size()) + " links; expected " + want);
  }
  chain.links.clear();
  chain.point_masses.clear();
  chain.spinners.clear();
  std::vector<std::optional<Map>> link_maps;
  for (size_t i = 0; i < links->size(); ++i) {
    auto lm = links->map_at(i);
    link_maps.push_back(lm);
    chain.links.push_back(lm ? read_arm_link(*lm) : core::Link{});
  }
  const int n = static_cast<int>(chain.links.size());
  const double payload = arm->number_or("payload", 0.0, mass_or_zero_rule());
  read_point_masses(*arm, n, chain);
  if (std::isfinite(payload) && payload > 0 && n > 0)
    chain.point_masses.push_back({n - 1, chain.links.back().length, 0.0, payload});
  check_massless_links(chain, link_maps);
  arm->finish();
  if (arm->diag().count() != errors_before) return fallback;
  try {
    return core::make_chain(chain);
  } catch (const std::invalid_argument& e) {
    root.error("arm", std::string("arm: ") + e.what());
    return fallback;
  }
}

studies::ArmOrigin arm_origin(const model_import::ImportedArm& arm) {
  studies::ArmOrigin o;
  o.model = arm.path;
  o.format = arm.format;
  o.name = arm.model_name;
  o.plane = arm.plane_text();
  o.tip = arm.tip;
  o.joint_names = arm.joint_names;
  return o;
}

std::vector<Eigen::Vector2d> model_ranges(const model_import::ImportedArm& arm) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& r : arm.range) {
    if (!r) return {};
    out.emplace_back(r->lower, r->upper);
  }
  return out;
}

double payload_mass(const core::PlanarChain& chain) {
  if (chain.point_masses.empty() || chain.links.empty()) return 0.0;
  const core::PointMass& p = chain.point_masses.back();
  const int last = chain.num_links() - 1;
  if (p.link == last && p.x == chain.links[last].length && p.y == 0.0) return p.mass;
  return 0.0;
}

}  // namespace armstudy::cases
