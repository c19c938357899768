// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/dc_motor.hpp"

#include <gtest/gtest.h>

#include "core/planar_chain.hpp"
#include "testing/arms.hpp"

namespace armstudy::core {
namespace {

// eq. 5-7 of 003 with kv = kt: e i = load + friction + rotor + copper, exactly.
TEST(DcMotor, ElectricalPowerSplitsIntoLoadFrictionRotorAndCopper) {
  DcMotor m;
  m.Im = 2e-6;
  for (double qd : {-7.0, -0.2, 0.0, 3.0, 13.9}) {
    for (double qdd : {-40.0, 0.0, 25.0}) {
      for (double tau : {-0.05, 0.0, 0.08}) {
        const MotorSample s = motor_sample(m, qd, qdd, tau);
        const double rotor = m.Im * qdd * qd;
        EXPECT_TRUE(testing::near_rel(s.power, s.load + s.friction + rotor + s.copper, 1e-12));
        // eq. 6 in its mechanical form
        const double sign = qd > 0 ? 1 : (qd < 0 ? -1 : 0);
        EXPECT_TRUE(testing::near_rel(
            s.current, (tau + m.Dm * qd + m.Im * qdd + m.tau_f * sign) / m.kt, 1e-12));
      }
    }
  }
}

TEST(DcMotor, AccelerationInvertsTheVoltageEquation) {
  DcMotor m;
  m.Im = 3e-6;
  const double qd = 4.0, qdd = 12.5, tau = 0.03;
  const MotorSample s = motor_sample(m, qd, qdd, tau);
  EXPECT_TRUE(testing::near_rel(motor_acceleration(m, s.voltage, qd, tau), qdd, 1e-10));
  m.Im = 0;
  EXPECT_THROW(motor_acceleration(m, 1.0, qd, tau), std::invalid_argument);
}

TEST(PlanarChain, MakeChainRejectsBadLinksNamingLinkAndRule) {
  PlanarChain c = testing::thesis_arm();
  c.links[1].length = -0.1;
  try {
    make_chain(c);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "link 2 length -0.1 m should be > 0");
  }
  c = testing::thesis_arm();
  c.point_masses[0].link = 5;
  EXPECT_THROW(make_chain(c), std::invalid_argument);
  c = testing::thesis_arm();
  c.links.clear();
  EXPECT_THROW(make_chain(c), std::invalid_argument);
}

}  // namespace
}  // namespace armstudy::core
