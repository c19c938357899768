// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include <cmath>
#include <locale>
#include <sstream>

#include "model_import/imported_arm.hpp"
#include "model_import/mujoco_load.hpp"
#include "model_import/urdf_text.hpp"

namespace armstudy::model_import {
namespace {
using Vec3 = Eigen::Vector3d;

constexpr double kAxisTol = 1e-9;  // parallel axes, links in one line (|sin| of the angle)

Vec3 v3(const mjtNum* p) { return {p[0], p[1], p[2]}; }

std::string name_of(const mjModel* m, mjtObj type, int id) {
  const char* n = mj_id2name(m, type, id);
  return n && *n ? n : "#" + std::to_string(id);
}
std::string body(const mjModel* m, int b) { return "body '" + name_of(m, mjOBJ_BODY, b) + "'"; }
std::string joint(const mjModel* m, int j) { return "joint '" + name_of(m, mjOBJ_JOINT, j) + "'"; }

std::string num(double v) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s.precision(6);
  s << v;
  return s.str();
}

// what one model has to be read as a chain: the moving bodies in order and, per body, its link
struct Chain {
  std::vector<int> moving;  // body ids, base to tip
  std::vector<int> joints;  // joint id of each
  std::vector<int> link;    // per body: its link (-1: fixed to the world)
};

const char* joint_kind(int type) {
  switch (type) {
    case mjJNT_FREE: return "a free joint (a floating base)";
    case mjJNT_BALL: return "a ball joint";
    case mjJNT_SLIDE: return "a slide (prismatic) joint";
    default: return "a hinge";
  }
}

// the hinges of one chain from the world, one per body; every other body is fixed to one
Chain find_chain(const mjModel* m, const std::string& file) {
  Chain c;
  c.link.assign(m->nbody, -1);
  for (int j = 0; j < m->njnt; ++j)
    if (m->jnt_type[j] != mjJNT_HINGE)
      throw ImportError(file + ": " + joint(m, j) + " of " + body(m, m->jnt_bodyid[j]) + " is " +
                        joint_kind(m->jnt_type[j]) +
                        "; expected hinge (revolute) joints only, on a base fixed to the world");
  for (int b = 1; b < m->nbody; ++b) {  // bodies come after their parents
    const int parent_link = c.link[m->body_parentid[b]];
    if (m->body_jntnum[b] == 0) {
      c.link[b] = parent_link;
      continue;
    }
    if (m->body_jntnum[b] > 1)
      throw ImportError(file + ": " + body(m, b) + " has " + std::to_string(m->body_jntnum[b]) +
                        " joints; expected one hinge per body (a planar chain)");
    const int last = c.moving.empty() ? -1 : static_cast<int>(c.moving.size()) - 1;
    if (parent_link != last)
      throw ImportError(
          file + ": " + body(m, b) + " (" + joint(m, m->body_jntadr[b]) + ") branches off " +
          (parent_link < 0 ? std::string("the base") : body(m, c.moving[parent_link])) + ", but " +
          body(m, c.moving[last]) + " moves already; expected one chain of hinges (no branches)");
    c.link[b] = static_cast<int>(c.moving.size());
    c.moving.push_back(b);
    c.joints.push_back(m->body_jntadr[b]);
  }
  if (c.moving.empty())
    throw ImportError(file + ": the model has no joint; expected a chain of 1 to " +
                      std::to_string(core::kMaxLinks) + " hinges");
  if (c.moving.size() > static_cast<size_t>(core::kMaxLinks))
    throw ImportError(file + ": the model has " + std::to_string(c.moving.size()) +
                      " hinges; expected at most " + std::to_string(core::kMaxLinks));
  if (m->neq > 0)
    throw ImportError(file + ": the model has " + std::to_string(m->neq) +
                      " equality constraint(s); expected none (a free planar chain)");
  return c;
}

// each joint: parallel to the first (same direction), reference 0, no damping or spring
Vec3 check_joints(const mjModel* m, const mjData* d, const Chain& c, const std::string& file) {
  const Vec3 n = v3(d->xaxis + 3 * c.joints[0]).normalized();
  for (size_t i = 0; i < c.joints.size(); ++i) {
    const int j = c.joints[i];
    const Vec3 a = v3(d->xaxis + 3 * j).normalized();
    if (a.cross(n).norm() > kAxisTol || a.dot(n) < 0)
      throw ImportError(file + ": " + joint(m, j) + " turns about (" + num(a.x()) + ", " +
                        num(a.y()) + ", " + num(a.z()) + ") in the world; expected an axis " +
                        "parallel to " + joint(m, c.joints[0]) + "'s (" + num(n.x()) + ", " +
                        num(n.y()) + ", " + num(n.z()) + "), pointing the same way");
    if (m->qpos0[m->jnt_qposadr[j]] != 0.0)
      throw ImportError(file + ": " + joint(m, j) + " has reference position " +
                        num(m->qpos0[m->jnt_qposadr[j]]) +
                        " rad; expected 0 (armstudy's joint angles are the model's own)");
    const int dof = m->jnt_dofadr[j];
    if (m->dof_damping[dof] != 0 || m->dof_frictionloss[dof] != 0 || m->jnt_stiffness[j] != 0)
      throw ImportError(file + ": " + joint(m, j) + " has damping, friction loss or stiffness;" +
                        " expected none (armstudy's arm has no joint friction or spring)");
  }
  return n;
}

// the chain's x and y axes in the model: y against gravity in the plane, else x along the
// model's x (or y) axis projected into the plane
void plane_axes(const Vec3& n, const Vec3& g, ImportedArm* arm) {
  const Vec3 gp = g - g.dot(n) * n;
  arm->normal = n;
  arm->gravity = g;
  if (gp.norm() > 1e-12 * std::max(1.0, g.norm())) {
    arm->y_axis = -gp.normalized();
    arm->x_axis = arm->y_axis.cross(n);
    arm->chain.gravity = gp.norm();
  } else {
    Vec3 x = Vec3::UnitX() - n.x() * n;
    if (x.norm() < 1e-6) x = Vec3::UnitY() - n.y() * n;
    arm->x_axis = x.normalized();
    arm->y_axis = n.cross(arm->x_axis);
    arm->chain.gravity = 0.0;
  }
}

// the tip: a site named `tip` on the last link, else the last link's one fixed leaf body
Vec3 find_tip(const mjModel* m, const mjData* d, const Chain& c, const std::string& file,
              std::string* what) {
  const int last = static_cast<int>(c.moving.size()) - 1;
  const int site = mj_name2id(m, mjOBJ_SITE, "tip");
  if (site >= 0 && c.link[m->site_bodyid[site]] == last) {
    *what = "site 'tip' of " + body(m, m->site_bodyid[site]);
    return v3(d->site_xpos + 3 * site);
  }
  std::vector<int> leaves;
  for (int b = 1; b < m->nbody; ++b) {
    if (c.link[b] != last || m->body_jntnum[b] > 0) continue;
    bool leaf = true;
    for (int k = b + 1; k < m->nbody; ++k) leaf &= m->body_parentid[k] != b;
    if (leaf) leaves.push_back(b);
  }
  if (leaves.size() != 1)
    throw ImportError(
        file + ": the tip of the last link (" + body(m, c.moving[last]) + ") is " +
        (leaves.empty() ? std::string("not marked")
                        : "ambiguous: " + std::to_string(leaves.size()) + " fixed bodies end it") +
        "; expected a site named 'tip' on it, or one body fixed after the last joint (a URDF "
        "link on a fixed joint, e.g. the tool)");
  *what = "the origin of " + body(m, leaves[0]) + ", fixed after the last joint";
  return v3(d->xpos + 3 * leaves[0]);
}

// per link: length, direction (in the plane) and the mass properties of its bodies
void read_links(const mjModel* m, const mjData* d, const Chain& c, const Vec3& tip,
                const std::string& file, ImportedArm* arm) {
  const auto plane = [&](const Vec3& p) {
    return Eigen::Vector2d(p.dot(arm->x_axis), p.dot(arm->y_axis));
  };
  const Vec3& n = arm->normal;
  const int nl = static_cast<int>(c.moving.size());
  Eigen::Vector2d prev_u;
  for (int i = 0; i < nl; ++i) {
    const int j = c.joints[i];
    const Eigen::Vector2d a = plane(v3(d->xanchor + 3 * j));
    const Eigen::Vector2d b = plane(i + 1 < nl ? v3(d->xanchor + 3 * c.joints[i + 1]) : tip);
    const double length = (b - a).norm();
    const std::string to = i + 1 < nl ? joint(m, c.joints[i + 1]) : std::string("the tip");
    if (!(length > 1e-9))
      throw ImportError(file + ": " + to + " lies on the axis of " + joint(m, j) +
                        " in the plane; expected a link of length > 0 between them");
    const Eigen::Vector2d u = (b - a) / length;
    if (i == 0) {
      arm->chain.base = a;
      arm->chain.base_angle = std::atan2(u.y(), u.x());
    } else if (std::abs(prev_u.x() * u.y() - prev_u.y() * u.x()) > kAxisTol || prev_u.dot(u) < 0) {
      const double deg =
          std::atan2(prev_u.x() * u.y() - prev_u.y() * u.x(), prev_u.dot(u)) * 180.0 / M_PI;
      throw ImportError(file + ": at the model's reference pose (qpos0) link " +
                        std::to_string(i + 1) + " (" + joint(m, j) + " to " + to + ") turns " +
                        num(deg) + " deg from link " + std::to_string(i) +
                        "; expected the links in one line at qpos0 (armstudy's joint angles are "
                        "the model's own, 0 along the previous link)");
    }
    prev_u = u;
    // the bodies of link i: mass, centre of mass, inertia about the normal at that centre
    double mass = 0;
    Vec3 com = Vec3::Zero();
    for (int bd = 1; bd < m->nbody; ++bd)
      if (c.link[bd] == i) {
        mass += m->body_mass[bd];
        com += m->body_mass[bd] * v3(d->xipos + 3 * bd);
      }
    if (!(mass > 0))
      throw ImportError(file + ": " + body(m, c.moving[i]) + " (link " + std::to_string(i + 1) +
                        ", with the bodies fixed to it) has no mass; expected mass > 0");
    com /= mass;
    double inertia = 0;
    for (int bd = 1; bd < m->nbody; ++bd) {
      if (c.link[bd] != i) continue;
      const mjtNum* R = d->ximat + 9 * bd;  // columns: the principal axes in the world
      for (int k = 0; k < 3; ++k) {
        const double nk = n.x() * R[k] + n.y() * R[3 + k] + n.z() * R[6 + k];
        inertia += m->body_inertia[3 * bd + k] * nk * nk;
      }
      const Vec3 r = v3(d->xipos + 3 * bd) - com;
      inertia += m->body_mass[bd] * (r - r.dot(n) * n).squaredNorm();
    }
    const Eigen::Vector2d rc = plane(com) - a;
    core::Link l;
    l.length = length;
    l.mass = mass;
    l.com = rc.dot(u);
    l.com_lateral = u.x() * rc.y() - u.y() * rc.x();
    l.inertia = inertia;
    arm->chain.links.push_back(l);
    const double armature = m->dof_armature[m->jnt_dofadr[j]];
    if (armature > 0) {
      core::SpinningInertia s;
      s.inertia = armature;
      s.coeffs = core::JointVector::Zero(nl);
      s.coeffs[i] = 1.0;
      arm->chain.spinners.push_back(s);
    }
  }
}

// the smaller side of a range [lo, hi] as a symmetric bound, and a note when they differ
double symmetric(double lo, double hi, std::string* note) {
  if (lo != -hi) *note = " (the smaller side of [" + num(lo) + ", " + num(hi) + "])";
  return std::min(std::abs(lo), std::abs(hi));
}

// joint ranges and the actuators' torque bounds (motor, gear) of an MJCF; URDF effort and
// velocity from the file's own <limit>
void read_limits(const mjModel* m, const Chain& c, const UrdfText* urdf, const std::string& file,
                 ImportedArm* arm) {
  const size_t nl = c.joints.size();
  arm->torque.assign(nl, std::nullopt);
  arm->velocity.assign(nl, std::nullopt);
  arm->range.assign(nl, std::nullopt);
  for (size_t i = 0; i < nl; ++i) {
    const int j = c.joints[i];
    const std::string jn = name_of(m, mjOBJ_JOINT, j);
    arm->joint_names.push_back(jn);
    if (m->jnt_limited[j])
      arm->range[i] = ModelRange{
          m->jnt_range[2 * j], m->jnt_range[2 * j + 1],
          urdf ? "<limit lower upper> of joint '" + jn + "'" : "range of joint '" + jn + "'"};
    if (!urdf) continue;
    const auto it = urdf->limits.find(jn);
    if (it == urdf->limits.end()) continue;
    if (it->second.effort && *it->second.effort > 0)
      arm->torque[i] = ModelLimit{*it->second.effort, "<limit effort> of joint '" + jn + "'"};
    if (it->second.velocity && *it->second.velocity > 0)
      arm->velocity[i] = ModelLimit{*it->second.velocity, "<limit velocity> of joint '" + jn + "'"};
  }
  for (int a = 0; a < m->nu; ++a) {
    const std::string an = "actuator '" + name_of(m, mjOBJ_ACTUATOR, a) + "'";
    const int j = m->actuator_trnid[2 * a];
    size_t i = 0;
    while (i < nl && c.joints[i] != j) ++i;
    if (m->actuator_trntype[a] != mjTRN_JOINT || i == nl)
      throw ImportError(file + ": " + an + " drives no joint of the chain; expected actuators " +
                        "on the chain's hinges only");
    if (arm->torque[i])
      throw ImportError(file + ": " + an + " is the second actuator of " + joint(m, j) +
                        "; expected at most one per joint");
    const double gear = std::abs(m->actuator_gear[6 * a]);
    const bool motor = m->actuator_gaintype[a] == mjGAIN_FIXED &&
                       m->actuator_biastype[a] == mjBIAS_NONE &&
                       m->actuator_dyntype[a] == mjDYN_NONE;
    std::optional<ModelLimit> best;
    std::string note;
    if (m->actuator_forcelimited[a]) {
      const double f =
          symmetric(m->actuator_forcerange[2 * a], m->actuator_forcerange[2 * a + 1], &note);
      best = ModelLimit{gear * f, "forcerange" + note + " x gear " + num(gear) + " of " + an};
    }
    if (motor && m->actuator_ctrllimited[a]) {
      note.clear();
      const double u =
          symmetric(m->actuator_ctrlrange[2 * a], m->actuator_ctrlrange[2 * a + 1], &note);
      const double t = gear * std::abs(m->actuator_gainprm[mjNGAIN * a]) * u;
      if (!best || t < best->value)
        best =
            ModelLimit{t, "ctrlrange" + note + " x gain " + num(m->actuator_gainprm[mjNGAIN * a]) +
                              " x gear " + num(gear) + " of " + an + " (a motor)"};
    }
    if (best) arm->torque[i] = best;
  }
}
}  // namespace

std::string ImportedArm::plane_text() const {
  const auto v = [](const Vec3& p) {
    return "(" + num(p.x()) + ", " + num(p.y()) + ", " + num(p.z()) + ")";
  };
  std::string s = "the plane normal to the joints' axis " + v(normal) + " of the " + format +
                  "'s world frame, with x along " + v(x_axis) + " and y along " + v(y_axis) +
                  "; the model's gravity " + v(gravity) + " m/s^2 ";
  s += chain.gravity == 0 ? "has no part in the plane: a horizontal plane, gravity-free"
                          : "is " + num(chain.gravity) + " m/s^2 along -y in the plane";
  return s;
}

ImportedArm import_arm(const std::string& path, const std::string& bytes) {
  ImportedArm arm;
  std::optional<UrdfText> urdf;
  if (is_urdf(bytes)) urdf = read_urdf(path, bytes);
  arm.format = urdf ? "URDF" : "MJCF";
  const ModelPtr model = load_mujoco_model(path, urdf ? urdf->for_mujoco : bytes);
  const mjModel* m = model.get();
  arm.model_name = m->names;  // MuJoCo keeps the model's name first
  const DataPtr data(mj_makeData(m));
  if (!data) throw ImportError(path + ": MuJoCo could not allocate the model's data");
  mjData* d = data.get();
  mj_kinematics(m, d);  // at qpos0, the reference pose
  const Chain c = find_chain(m, path);
  const Vec3 n = check_joints(m, d, c, path);
  plane_axes(n, v3(m->opt.gravity), &arm);
  const Vec3 tip = find_tip(m, d, c, path, &arm.tip);
  read_links(m, d, c, tip, path, &arm);
  read_limits(m, c, urdf ? &*urdf : nullptr, path, &arm);
  try {
    arm.chain = core::make_chain(arm.chain);
  } catch (const std::invalid_argument& e) {
    throw ImportError(path + ": " + e.what());
  }
  return arm;
}

}  // namespace armstudy::model_import
