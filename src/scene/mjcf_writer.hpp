// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MJCF generated from a core::PlanarChain, so that MuJoCo's masses, centres of mass and
/// inertias are exactly the case's.
///
/// The chain lies in the model's x-y plane, every joint a hinge about z; gravity acts along
/// -y with the chain's magnitude. Each link body carries ONE explicit <inertial> that
/// combines the link and every point mass on it (mass, centre of mass, inertia about z at
/// that centre, parallel-axis theorem): exact for planar motion. Geoms are visual only
/// (contype=conaffinity=0, no mass). Joint i gets a `motor` actuator with gear 1 if active;
/// damping and armature are zero. A SpinningInertia acting on one joint only becomes that
/// joint's armature (I c^2). A spinner that couples several joints (the rolling ball of
/// Sato et al.: omega = (qd1+qd2+qd3) - (r4/r_b) qd4) becomes an extra body
/// `spin<k>` hung on the deepest link k whose absolute rate leaves ONE joint in the spin:
/// omega = (qd_1 + ... + qd_k) + d_j qd_j, so the extra hinge `spin<k>` turns by
/// psi = d_j q_j, enforced in simulation by a joint equality constraint. MuJoCo's
/// coordinates are then q_mj = J q (see chain_to_mujoco), and every chain quantity follows
/// exactly: tau_chain = J^T qfrc_mj, M_chain = J^T M_mj J.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cases/case_info.hpp"
#include "core/planar_chain.hpp"

namespace armstudy::scene {

struct MjcfOptions {
  std::string model_name = "armstudy_chain";
  double timestep = 1e-3;          ///< s
  std::string integrator = "RK4";  ///< "Euler" or "RK4"
  cases::FrameSize offscreen;      ///< px, off-screen buffer (<global offwidth offheight>)
  double fovy = 45;                ///< deg, the free camera's vertical field of view
  /// Extra XML inserted in <worldbody> before the chain (table, task line, markers).
  std::string world_extra;
  /// Extra XML inserted inside the tip body (e.g. a payload geom).
  std::string tip_extra;
  /// Visual link thickness, m (0: 4% of the longest link).
  double link_radius = 0.0;
  /// Link colour (RGBA), one per link; links beyond the list use the last entry.
  std::vector<std::string> link_rgba = {"0.30 0.45 0.70 1"};
  /// Per spinner (index as in chain.spinners): position of its body in the frame of the link
  /// it hangs on, m, and extra XML inside its body (e.g. the ball's sphere and stripe).
  std::vector<Eigen::Vector2d> spinner_pos;
  std::vector<std::string> spinner_extra;
  /// Extra XML inserted inside link i's body (index = link), e.g. a tray geom.
  std::vector<std::string> link_extra;
  /// Sides of the polygons that draw spheres, capsules and cylinders (<quality numslices
  /// numstacks>); 0: MuJoCo's own (28, 16).
  int numslices = 0;
  int numstacks = 0;
  /// Extra XML appended in <visual> (after global and quality), e.g. headlight settings.
  std::string visual_extra;
  /// Extra XML inserted right after <compiler> (e.g. <statistic>).
  std::string top_extra;
  /// Extra XML inserted in <asset>.
  std::string asset_extra;
  /// solref / solimp of the spinner equality constraints (stiff: the spin of a rolling ball).
  std::string equality_solref = "0.002 1";
  std::string equality_solimp = "0.9999 0.9999 0.001";
  /// XML comment placed after the header (how the model represents the case).
  std::string comment;
  /// Per joint (empty: none): the range [lo, hi] in rad (limited="true") and the motor's
  /// torque bound in N m (forcelimited="true" forcerange="-t t", gear 1).
  std::vector<Eigen::Vector2d> joint_range;
  std::vector<double> torque_limit;
};

/// How one coupling spinner is represented in MuJoCo (see the header comment).
struct SpinnerBody {
  int spinner = 0;         ///< index in chain.spinners
  int link = -1;           ///< link it hangs on (-1: the world)
  int joint = -1;          ///< the one chain joint its hinge follows (-1: none, rigid with `link`)
  double ratio = 0;        ///< psi = ratio * q[joint]
  std::string body_name;   ///< "spin1", ...
  std::string joint_name;  ///< "spin1_joint"
};

/// The spinners that need their own body (those coupling several joints), in order.
/// @throws std::invalid_argument when no link leaves a single joint in the spin.
std::vector<SpinnerBody> spinner_bodies(const core::PlanarChain& chain);

/// Combined inertial of one link body: link plus point masses on it.
struct LinkInertial {
  double mass = 0;   ///< kg
  double com_x = 0;  ///< m, link frame
  double com_y = 0;
  double izz = 0;  ///< kg m^2 about the combined centre of mass
};

/// The inertial MuJoCo gets for link i.
LinkInertial combined_inertial(const core::PlanarChain& chain, int link);

/// Smallest inertia and mass written to MJCF, the stand-in of a body with none of its own
/// (MuJoCo rejects a moving body whose mass or inertia is below mjMINVAL = 1e-15). MuJoCo's
/// XML writer (a saved copy: testxml, simulate's "Save xml") writes any number within 1e-12
/// of an integer as that integer (xml_util.cc, isint), so a stand-in below 1e-12 comes back
/// as 0 and the saved copy no longer loads; 2e-12 is the smallest round value kept with a
/// margin (2x) against rounding. Its dynamic effect is of the order of 2e-12 over the real
/// inertia it sits beside (tests/scene/mujoco_check_test.cpp).
inline constexpr double kMinMjcfInertia = 2e-12;
inline constexpr double kMinMjcfMass = 2e-12;

/// What the stand-in inertias add to the chain's mass matrix, in the chain's coordinates:
/// a link with less than kMinMjcfInertia of its own gets the difference d_i about its axis,
/// whose angle is q_1 + ... + q_i, so entry (a, b) gains the d_i of every link i >= a, b
/// (constant in q; the stand-in masses add another ~kMinMjcfMass x (1 m)^2 at most).
Eigen::MatrixXd stand_in_mass_matrix(const core::PlanarChain& chain);

/// The MJCF text of `chain` (see the header comment for how spinners are represented).
/// @throws std::invalid_argument for a spinner no extra body can express.
std::string write_mjcf(const core::PlanarChain& chain, const MjcfOptions& options = {});

}  // namespace armstudy::scene
