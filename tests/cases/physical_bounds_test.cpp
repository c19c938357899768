// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// An arm's physical sizes are judged when the case is read (cases/physical_bounds.hpp): a
// link of 1e-100 m validated and then `run` ended with MuJoCo's raw "fromto points too
// close ...\nObject name = ...". Refused now at the key, in armstudy's words, by
// validate as by run; the bounds' own edges are accepted.
#include <gtest/gtest.h>

#include <string>

#include "app/pipeline.hpp"
#include "cases/case_error.hpp"
#include "cases/physical_bounds.hpp"
#include "model_import/mujoco_message.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::cases {
namespace {

// the errors of loading `arm` (the `arm:` section) into a small time-optimal case
std::string arm_errors(const std::string& arm) {
  const std::string yaml = "study: time_optimal\nname: a\n" + arm +
                           "time_optimal:\n  path: {points_m: [[0.3, 0.1], [-0.1, 0.5]]}\n";
  try {
    app::load_case_text(yaml, "c.yaml");
  } catch (const CaseErrors& e) {
    std::string out;
    for (const auto& err : e.errors()) out += err.format() + "\n";
    return out;
  }
  return "";
}

TEST(PhysicalBounds, ALinkOfAbsurdLengthIsRefusedAtItsKeyBeforeMujocoSeesIt) {
  EXPECT_EQ(arm_errors("arm:\n  links:\n    - {length: 1.0e-100, mass: 3.0}\n"
                       "    - {length: 0.35, mass: 2.0}\n"),
            "c.yaml:5:16: 'arm.links[1].length' is 1e-100; should be in [0.001, 1000] m\n");
  EXPECT_NE(arm_errors("arm:\n  links:\n    - {length: 0.4, mass: 3.0}\n"
                       "    - {length: 1.0e+4, mass: 2.0}\n")
                .find("'arm.links[2].length' is 10000; should be in [0.001, 1000] m"),
            std::string::npos);
}

TEST(PhysicalBounds, MassesInertiasAndOffsetsBeyondTheirBoundsAreEachNamed) {
  const std::string e = arm_errors(
      "arm:\n  links:\n    - {length: 0.4, mass: 1.0e-100, com: 2000}\n"
      "    - {length: 0.35, mass: 2.0, inertia: 1.0e+7, com_lateral: -1.0e+4}\n"
      "  payload: 1.0e+7\n  point_masses:\n    - {link: 1, at: 0.1, mass: 1.0e-9}\n");
  for (const char* want :
       {"'arm.links[1].mass' is 1e-100; should be 0 or in [1e-06, 1000000] kg",
        "'arm.links[1].com' is 2000; should be in [-1000, 1000] m",
        "'arm.links[2].inertia' (or 'rod') is 10000000; should be in [0, 1000000] kg m^2",
        "'arm.links[2].com_lateral' is -10000; should be in [-1000, 1000] m",
        "'arm.payload' is 10000000; should be 0 or in [1e-06, 1000000] kg",
        "'arm.point_masses[1].mass' is 1e-09; should be in [1e-06, 1000000] kg"})
    EXPECT_NE(e.find(want), std::string::npos) << want << "\n" << e;
}

TEST(PhysicalBounds, TheBoundsOwnEdgesAndAMasslessLinkWithAPointMassAreAccepted) {
  EXPECT_EQ(arm_errors("arm:\n  links:\n    - {length: 0.001, mass: 1.0e-6, inertia: 0}\n"
                       "    - {length: 1000, mass: 1.0e+6, inertia: 1.0e+6, com: -1000}\n"),
            "");
  EXPECT_EQ(arm_errors("arm:\n  links:\n    - {length: 0.4, mass: 0}\n"
                       "    - {length: 0.35, mass: 2.0}\n"
                       "  point_masses:\n    - {link: 1, at: 0.4, mass: 1.0}\n"),
            "");
}

TEST(PhysicalBounds, AModelsArmIsHeldToTheSameBoundsNamingLinkAndJoint) {
  core::PlanarChain chain;
  chain.links = {core::Link{}, core::Link{}};
  chain.links[0].length = 1e-100;
  chain.links[0].mass = 2.0;
  chain.links[1].length = 0.3;
  chain.links[1].mass = 1e7;
  const std::vector<std::string> p = chain_size_problems(chain, {"shoulder", "elbow"});
  ASSERT_EQ(p.size(), 2u) << ::testing::PrintToString(p);
  EXPECT_EQ(p[0],
            "link 1 (joint 'shoulder'): the length is 1e-100 m; should be in [0.001, 1000] m");
  EXPECT_EQ(p[1],
            "link 2 (joint 'elbow'): the mass is 10000000 kg; should be 0 or in [1e-06, 1000000] "
            "kg");
}

// MuJoCo's message spans lines; a terminal showed its line break as a literal "\n"
TEST(PhysicalBounds, MujocosMessageIsSaidInOneLine) {
  EXPECT_EQ(
      model_import::mujoco_message("Error: fromto points too close in geom 'link1_geom' (id = 0)\n"
                                   "  Object name = link1_geom, id = 0, line = 19, column = -1\n"),
      "fromto points too close in geom 'link1_geom' (id = 0); Object name = link1_geom, "
      "id = 0, line = 19, column = -1");
  EXPECT_EQ(model_import::mujoco_message("XML Error: bad\r\n\r\nElement 'x'  "),
            "XML Error: bad; Element 'x'");
  EXPECT_EQ(model_import::mujoco_message(""), "");
  // and so the scene's model says it: the generated model of a run, in one line
  try {
    scene::MujocoModel m(
        "<mujoco><worldbody><body><joint/><geom type=\"capsule\" fromto=\"0 0 0 1e-100 0 0\" "
        "size=\"0.01\"/></body></worldbody></mujoco>",
        "the generated model");
    ADD_FAILURE() << "MuJoCo loaded a 1e-100 m capsule";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the generated model: MuJoCo could not load the model: fromto points "
                        "too close"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace armstudy::cases
