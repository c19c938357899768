// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// models/*.xml: in sync with the generator, loadable by MuJoCo from disk, and carrying
// exactly the case's masses, centres of mass and inertias (computed here independently of
// the writer, from the chain's links and point masses).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/mjcf_writer.hpp"
#include "scene/model_files.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "studies/throwing/solve.hpp"
#include "testing/arms.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = fs::path(ARMSTUDY_SOURCE_DIR) / "models";

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

struct Named {
  const char* file;
  ArmScene scene;
};

std::vector<Named> models() {
  return {{kHorizontalModelFile, default_horizontal_scene()},
          {kTrayModelFile, default_tray_scene()}};
}

TEST(Models, CommittedFilesEqualTheGeneratedOnes) {
  const bool update = std::getenv("ARMSTUDY_UPDATE_MODELS") != nullptr;
  for (const Named& m : models()) {
    const fs::path p = kModels / m.file;
    if (update) std::ofstream(p, std::ios::binary) << m.scene.mjcf;
    EXPECT_EQ(read(p), m.scene.mjcf)
        << p << " is out of date: run scene_tests with ARMSTUDY_UPDATE_MODELS=1";
  }
}

// expected inertial of link i: the link and every point mass on it
struct Expected {
  double mass = 0, cx = 0, cy = 0, izz = 0;
};
Expected expected(const core::PlanarChain& c, int i) {
  Expected e;
  const core::Link& l = c.links[i];
  double mx = l.mass * l.com, my = l.mass * l.com_lateral;
  e.mass = l.mass;
  for (const auto& p : c.point_masses)
    if (p.link == i) {
      e.mass += p.mass;
      mx += p.mass * p.x;
      my += p.mass * p.y;
    }
  e.cx = mx / e.mass;
  e.cy = my / e.mass;
  e.izz = l.inertia + l.mass * (std::pow(l.com - e.cx, 2) + std::pow(l.com_lateral - e.cy, 2));
  for (const auto& p : c.point_masses)
    if (p.link == i) e.izz += p.mass * (std::pow(p.x - e.cx, 2) + std::pow(p.y - e.cy, 2));
  return e;
}

TEST(Models, LoadedFromDiskTheyCarryTheCasesMassesCentresAndInertias) {
  for (const Named& m : models()) {
    SCOPED_TRACE(m.file);
    const MujocoModel mm = MujocoModel::from_file((kModels / m.file).string());
    const mjModel* mj = mm.model();
    const core::PlanarChain& c = m.scene.chain;
    double total = 0;
    for (int i = 0; i < c.num_links(); ++i) {
      const std::string name = "link" + std::to_string(i + 1);
      const int b = mj_name2id(mj, mjOBJ_BODY, name.c_str());
      ASSERT_GE(b, 0) << name;
      const Expected e = expected(c, i);
      if (e.mass == 0) {
        EXPECT_LE(mj->body_mass[b], kMinMjcfMass) << name;
        continue;
      }
      EXPECT_NEAR(mj->body_mass[b], e.mass, 1e-15 * e.mass) << name;
      EXPECT_NEAR(mj->body_ipos[3 * b], e.cx, 1e-15) << name;
      EXPECT_NEAR(mj->body_ipos[3 * b + 1], e.cy, 1e-15) << name;
      // the hinge's axis z is a principal axis; MuJoCo stores the diagonal
      EXPECT_NEAR(mj->body_inertia[3 * b + 2], std::max(e.izz, kMinMjcfInertia),
                  1e-14 * std::max(e.izz, 1e-12))
          << name;
      total += e.mass;
    }
    // and the stand-in masses of the bodies with none (the ball's spin body: 2e-12 kg)
    for (int b = 1; b < mj->nbody; ++b)
      if (mj->body_mass[b] == kMinMjcfMass) total += kMinMjcfMass;
    EXPECT_NEAR(mj->body_subtreemass[0], total, 1e-12 * total);
    // gravity and the actuated joints
    EXPECT_DOUBLE_EQ(mj->opt.gravity[1], -c.gravity);
    int active = 0;
    for (const auto& l : c.links) active += l.active;
    EXPECT_EQ(mj->nu, active);
  }
}

TEST(Models, TrayModelCarriesTheBallsSpinInertiaOnItsOwnHinge) {
  const studies::ThrowingSpec spec;
  const MujocoModel mm = MujocoModel::from_file((kModels / kTrayModelFile).string());
  const int b = mj_name2id(mm.model(), mjOBJ_BODY, "spin1");
  ASSERT_GE(b, 0);
  EXPECT_DOUBLE_EQ(mm.model()->body_inertia[3 * b + 2], spec.arm.Ib);
  ASSERT_EQ(mm.model()->neq, 1);
  // psi = -(1 + r4/r_b) theta4
  EXPECT_DOUBLE_EQ(mm.model()->eq_data[1], -(1 + spec.arm.r4 / spec.arm.rb));
}

TEST(Models, BadModelFileGivesMujocosMessageWithTheFile) {
  const fs::path p = testing::temp_path("bad_model.xml");
  std::ofstream(p) << "<mujoco><worldbody><body><joint type=\"hinge\"/><geom type=\"sphere\"/>"
                      "</body></worldbody></mujoco_broken>";
  try {
    MujocoModel::from_file(p.string());
    FAIL() << "no exception";
  } catch (const ModelError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find(p.string()), std::string::npos) << w;
    EXPECT_NE(w.find("XML"), std::string::npos) << "MuJoCo's own message: " << w;
  }
}

}  // namespace
}  // namespace armstudy::scene
