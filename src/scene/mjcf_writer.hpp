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
/// joint's armature (I c^2); other spinners need extra bodies (see the scene of the study).

#include <string>

#include "core/planar_chain.hpp"

namespace armstudy::scene {

struct MjcfOptions {
  std::string model_name = "armstudy_chain";
  double timestep = 1e-3;         ///< s
  std::string integrator = "RK4"; ///< "Euler" or "RK4"
  int offwidth = 640;             ///< px, off-screen buffer
  int offheight = 480;
  /// Extra XML inserted in <worldbody> before the chain (table, task line, markers).
  std::string world_extra;
  /// Extra XML inserted inside the tip body (e.g. a payload geom).
  std::string tip_extra;
  /// Visual link thickness, m (0: 4% of the longest link).
  double link_radius = 0.0;
};

/// Combined inertial of one link body: link plus point masses on it.
struct LinkInertial {
  double mass = 0;     ///< kg
  double com_x = 0;    ///< m, link frame
  double com_y = 0;
  double izz = 0;      ///< kg m^2 about the combined centre of mass
};

/// The inertial MuJoCo gets for link i.
LinkInertial combined_inertial(const core::PlanarChain& chain, int link);

/// Smallest inertia written to MJCF (MuJoCo rejects zero inertia on a moving body).
inline constexpr double kMinMjcfInertia = 1e-12;
inline constexpr double kMinMjcfMass = 1e-12;

/// The MJCF text of `chain`. @throws std::invalid_argument for a spinner that couples
/// several joints.
std::string write_mjcf(const core::PlanarChain& chain, const MjcfOptions& options = {});

}  // namespace armstudy::scene
