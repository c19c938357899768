// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/arm_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "scene/mjcf_writer.hpp"
#include "scene/polyline.hpp"

namespace armstudy::scene {
namespace {
constexpr double kPi = 3.14159265358979323846;

std::ostringstream xml() {
  std::ostringstream x;
  x.imbue(std::locale::classic());
  x.precision(9);
  return x;
}

double reach(const core::PlanarChain& chain) {
  double r = 0;
  for (const auto& l : chain.links) r += l.length;
  return r;
}

double link_radius(const core::PlanarChain& chain) {
  double longest = 0;
  for (const auto& l : chain.links) longest = std::max(longest, l.length);
  return 0.04 * longest;
}

// a slanted light: its shadows (render.shadows) fall beside the arm on the table or wall
std::string shadow_light(double height) {
  auto x = xml();
  x << "    <light name=\"sun\" directional=\"true\" pos=\"0 0 " << height
    << "\" dir=\"0.25 -0.35 -1\" castshadow=\"true\" diffuse=\"0.22 0.22 0.22\" "
       "specular=\"0 0 0\" ambient=\"0 0 0\"/>\n";
  return x.str();
}

// the spacing of a plane's rendering grid (its third size): MuJoCo draws a plane as a grid
// of quads, lit per vertex; the lights here are directional (the headlight and the sun), so a
// plane is lit alike at every vertex and a 4 x 4 grid draws what 0.01 m quads did (up to
// 200 x 200 of them, each drawn again for every shadow pass)
double plane_grid(double half) { return 0.5 * half; }

// The fewest sides that draw the scene's round geoms (largest radius `radius` m, the view
// `span_y` m high on `height` px) as the circles they are: each polygon within a quarter of a
// pixel of its circle, r (1 - cos(pi / n)) <= 0.25 px, at least 12 and at most MuJoCo's
// default 28 (a joint disc 6 px across needs 12, a close-up of the ball all 28); stacks
// (the meridians of a capsule's end seen from the side) at the same angular step.
void set_quality(MjcfOptions* o, double radius, double span_y, int height) {
  const double r_px = radius * height / std::max(span_y, 1e-9);
  int n = 28;
  if (r_px > 0.25) n = static_cast<int>(std::ceil(kPi / std::acos(1 - 0.25 / r_px)));
  n = std::clamp(n + (n % 2), 12, 28);
  if (n == 28) return;  // MuJoCo's defaults
  o->numslices = n;
  o->numstacks = std::max(8, static_cast<int>(std::ceil(n * 16.0 / 28.0)) + 1) & ~1;
}

// The background grid's texture and material: square cells of `cell_m` m (MuJoCo maps a
// plane's texture over 2 / texrepeat m with texuniform), each cell drawn in fewer texels than it
// covers on screen (one per ~1.5 px, 16 to 200), so that llvmpipe magnifies it (one bilinear lookup
// a pixel) instead of filtering between two mipmap levels of a minified texture, which cost ~20 %
// of a frame with 200 texels a cell (tests/bench/scene_bench.cpp). The one-texel lines then cover
// ~1.5 px instead of under one, so `mark` is taken a third of the way from the background `rgb`
// (that is about as dark as the minified lines looked). `view` and `height` px as the renderer
// frames them at its default margin.
std::string grid_asset(const char* material, double cell_m, const ViewBox& v, int width, int height,
                       const double rgb[3], const double mark[3]) {
  const double margin = 1 + 2 * 0.06;  // RenderSettings::margin's default
  const double aspect = static_cast<double>(width) / std::max(1, height);
  const double span = std::max(v.y_max - v.y_min, (v.x_max - v.x_min) / aspect) * margin;
  const double cell_px = cell_m * height / std::max(span, 1e-9);
  const int texels = std::clamp(static_cast<int>(cell_px / 1.5), 16, 200);
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(3);
  os << std::fixed;
  os << "    <texture name=\"grid\" type=\"2d\" builtin=\"checker\" rgb1=\"" << rgb[0] << " "
     << rgb[1] << " " << rgb[2] << "\" rgb2=\"" << rgb[0] << " " << rgb[1] << " " << rgb[2]
     << "\" width=\"" << texels << "\" height=\"" << texels << "\" mark=\"edge\" markrgb=\"";
  for (int c = 0; c < 3; ++c) os << (c ? " " : "") << rgb[c] + (mark[c] - rgb[c]) / 3;
  os << "\"/>\n    <material name=\"" << material << "\" texture=\"grid\" texrepeat=\""
     << 2 / cell_m << " " << 2 / cell_m << "\" texuniform=\"true\"/>\n";
  return os.str();
}

// a narrow field of view: nearly orthographic, little parallax between drawing heights
constexpr double kFovy = 20;

// The centre of the frames' view as the model's <statistic center>: where MuJoCo's viewer
// (`simulate model.xml`) points its free camera when it opens the model. Without it the
// viewer looks at the centre of all geoms' boxes (the wall's) and, at this narrow fovy, shows
// the pedestal without the arm (tests/e2e/simulate_viewer_test.sh). armstudy's own renderer
// places its camera itself and reads neither.
std::string viewer_centre(double cx, double cy) {
  std::ostringstream x;
  x.imbue(std::locale::classic());
  x.precision(6);
  x << "  <statistic center=\"" << cx << " " << cy << " 0\"/>\n";
  return x.str();
}

// a light headlight-lit look without specular glare
const char* kVisual =
    "    <headlight ambient=\"0.45 0.45 0.45\" diffuse=\"0.35 0.35 0.35\" "
    "specular=\"0.05 0.05 0.05\"/>\n"
    "    <map znear=\"0.01\" zfar=\"60\"/>\n";

}  // namespace

std::string grid_caption(double spacing_m) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << "grid " << spacing_m << " m";
  return os.str();
}

namespace {
// the task as a polyline from start (green) to end (red)
std::vector<Eigen::Vector2d> task_polyline(const TableDecor& decor) {
  std::vector<Eigen::Vector2d> task = decor.task_path;
  if (decor.task_start && decor.task_end) task = {*decor.task_start, *decor.task_end};
  return task;
}

// what to frame: the reach circle about the base and the task
ViewBox table_view(const Eigen::Vector2d& b, double R, double r,
                   const std::vector<Eigen::Vector2d>& task) {
  ViewBox v{b.x() - R, b.x() + R, b.y() - R, b.y() + R};
  for (const Eigen::Vector2d& p : task) {
    v.x_min = std::min(v.x_min, p.x() - 2 * r);
    v.x_max = std::max(v.x_max, p.x() + 2 * r);
    v.y_min = std::min(v.y_min, p.y() - 2 * r);
    v.y_max = std::max(v.y_max, p.y() + 2 * r);
  }
  return v;
}

// a model name from the model file's own (letters, digits and _ kept)
std::string model_name_of(const studies::ArmOrigin& origin, double gravity) {
  if (origin.name.empty()) return gravity == 0 ? "horizontal_arm" : "vertical_arm";
  std::string n = origin.name;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  return n + "_in_plane";
}

std::string joint_list(const std::vector<double>& v, const char* unit) {
  auto x = xml();
  for (size_t i = 0; i < v.size(); ++i) x << (i ? ", " : "") << "joint" << i + 1 << " " << v[i];
  x << " " << unit;
  return x.str();
}

// the model's comment: the case's own arm (its links, its plane and gravity), where it came
// from, the limits the study used, and the scene
std::string table_comment(const core::PlanarChain& chain, const TableDecor& d) {
  std::ostringstream what;
  what.imbue(std::locale::classic());
  what << "    A " << chain.num_links() << "-link planar arm in the x-y plane, "
       << (chain.gravity == 0 ? "horizontal (gravity 0)" : "vertical: gravity ");
  if (chain.gravity != 0) what << chain.gravity << " m/s^2 along -y";
  what << ".\n";
  const studies::ArmOrigin& o = d.origin;
  if (o.from_model()) {
    what << "    Read from " << o.model << " (" << o.format << ", model '" << o.name
         << "') through MuJoCo's parser and solved in\n    " << o.plane << ".\n    The tip is "
         << o.tip << ". Joints joint1, joint2, ... are the model's";
    for (size_t i = 0; i < o.joint_names.size(); ++i)
      what << (i ? ", " : " ") << "'" << o.joint_names[i] << "'";
    what << " (the model's own angles).\n";
  }
  if (!d.joint_range.empty() || !d.torque_limit.empty() || !d.velocity_limit.empty() ||
      !o.limits.empty()) {
    what << "    The limits the study used: joint ranges (range) and torque bounds (the motors'\n"
         << "    forcerange, gear 1) below; MJCF has no velocity limit";
    if (!d.velocity_limit.empty()) what << ": " << joint_list(d.velocity_limit, "rad/s");
    what << ".\n";
    for (const std::string& l : o.limits) what << "      " << l << "\n";
  }
  if (chain.gravity == 0)
    what << "    The table is the x-y plane seen from above (camera looking down -z), the root is\n"
            "    the dark pedestal, the task is drawn in red from S (green) to F (red); a 0.2 m "
            "grid.\n";
  else
    what << "    The x-y plane is seen from +z (x right, y up: gravity points down the image), "
            "the\n    root is the dark pedestal, the task is drawn in red from S (green) to F "
            "(red); a 0.2 m grid.\n";
  return what.str() +
         "    Each link body has one combined <inertial> (link + payload), so MuJoCo's masses,\n"
         "    centres of mass and inertias are the case's; geoms are visual only.\n";
}

// the world's geoms: the table plane, the root's pedestal and cross, the task line and its
// start and end marks
std::string table_world(const Eigen::Vector2d& b, double r, double cx, double cy, double half,
                        const std::vector<Eigen::Vector2d>& task) {
  auto w = xml();
  w << shadow_light(0.5 * half);
  w << "    <geom name=\"table\" type=\"plane\" pos=\"" << cx << " " << cy << " " << -3 * r
    << "\" size=\"" << half << " " << half << " " << plane_grid(half)
    << "\" material=\"table\"/>\n";
  // root: pedestal and a cross on the table
  w << "    <geom name=\"root\" type=\"cylinder\" pos=\"" << b.x() << " " << b.y() << " "
    << -1.5 * r << "\" size=\"" << 2.2 * r << " " << 1.4 * r << "\" rgba=\"0.20 0.20 0.22 1\"/>\n";
  for (int k = 0; k < 2; ++k) {
    const double dx = k == 0 ? 4 * r : 0, dy = k == 0 ? 0 : 4 * r;
    w << "    <geom name=\"root_cross" << k << "\" type=\"capsule\" fromto=\"" << b.x() - dx << " "
      << b.y() - dy << " " << -2.9 * r << " " << b.x() + dx << " " << b.y() + dy << " " << -2.9 * r
      << "\" size=\"" << 0.25 * r << "\" rgba=\"0.20 0.20 0.22 1\"/>\n";
  }
  for (size_t k = 1; k < task.size(); ++k) {
    if ((task[k] - task[k - 1]).norm() < 1e-9) continue;
    w << "    <geom name=\"task" << k << "\" type=\"capsule\" fromto=\"" << task[k - 1].x() << " "
      << task[k - 1].y() << " " << -2.6 * r << " " << task[k].x() << " " << task[k].y() << " "
      << -2.6 * r << "\" size=\"" << 0.35 * r << "\" rgba=\"0.85 0.12 0.12 1\"/>\n";
  }
  if (task.size() >= 2) {
    const Eigen::Vector2d& S = task.front();
    const Eigen::Vector2d& F = task.back();
    w << "    <geom name=\"task_start\" type=\"cylinder\" pos=\"" << S.x() << " " << S.y() << " "
      << -2.6 * r << "\" size=\"" << 0.9 * r << " " << 0.3 * r << "\" rgba=\"0.10 0.60 0.20 1\"/>\n"
      << "    <geom name=\"task_end\" type=\"cylinder\" pos=\"" << F.x() << " " << F.y() << " "
      << -2.6 * r << "\" size=\"" << 0.9 * r << " " << 0.3 * r
      << "\" rgba=\"0.85 0.12 0.12 1\"/>\n";
  }
  return w.str();
}
}  // namespace

ArmScene horizontal_arm_scene(const core::PlanarChain& chain, const TableDecor& decor) {
  ArmScene s;
  s.chain = chain;
  const double r = link_radius(chain);
  const double R = reach(chain);
  const Eigen::Vector2d b = chain.base;
  std::vector<Eigen::Vector2d> task = task_polyline(decor);
  const ViewBox v = table_view(b, R, r, task);
  s.view = v;
  const double cx = 0.5 * (v.x_min + v.x_max), cy = 0.5 * (v.y_min + v.y_max);
  const double half = 2.0 * std::max(v.x_max - v.x_min, v.y_max - v.y_min);
  // a finely sampled task path (a thousand points) as the few segments that draw the same
  // picture: every dropped point within a tenth of a pixel of the line drawn
  {
    std::vector<Eigen::Vector2d> drawn;
    const double tol = subpixel_tolerance(v.x_max - v.x_min, v.y_max - v.y_min,
                                          decor.offscreen.width, decor.offscreen.height);
    for (const size_t k : simplify_polyline(task, tol)) drawn.push_back(task[k]);
    task = std::move(drawn);
  }

  MjcfOptions o;
  o.model_name = model_name_of(decor.origin, chain.gravity);
  o.joint_range = decor.joint_range;
  o.torque_limit = decor.torque_limit;
  o.fovy = kFovy;
  o.top_extra = viewer_centre(cx, cy);
  o.offscreen = decor.offscreen;
  set_quality(&o, 2.2 * r, v.y_max - v.y_min,
              decor.offscreen.height);  // the pedestal is the roundest
  o.link_radius = r;
  o.link_rgba = {"0.18 0.38 0.75 1", "0.10 0.58 0.55 1", "0.45 0.35 0.65 1"};
  o.visual_extra = kVisual;
  {
    const double rgb[3] = {0.96, 0.96, 0.94}, mark[3] = {0.80, 0.80, 0.78};
    o.asset_extra = grid_asset("table", kTableGridM, v, decor.offscreen.width,
                               decor.offscreen.height, rgb, mark);
  }
  o.comment = table_comment(chain, decor);
  o.world_extra = table_world(b, r, cx, cy, half, task);
  // joints as dark discs
  for (int i = 0; i < chain.num_links(); ++i) {
    auto j = xml();
    j << "      <geom name=\"joint" << i + 1 << "_disc\" type=\"cylinder\" pos=\"0 0 0\" size=\""
      << 1.35 * r << " " << 1.1 * r << "\" rgba=\"0.25 0.25 0.28 1\"/>\n";
    o.link_extra.push_back(j.str());
  }
  // payload: an orange sphere at the tip
  auto t = xml();
  t << "      <geom name=\"payload\" type=\"sphere\" pos=\"" << chain.links.back().length
    << " 0 0\" size=\"" << 1.6 * r << "\" rgba=\"0.96 0.55 0.08 1\"/>\n";
  o.tip_extra = t.str();
  s.mjcf = write_mjcf(chain, o);
  return s;
}

namespace {
const char* kTrayComment =
    "    The arm with a passive tray of Sato et al. in a vertical plane: the\n"
    "    x-y plane seen from +z (x right, y up), gravity along -y; a 0.1 m grid.\n"
    "    Joints 1 and 2 are driven (motor actuators, gear 1), the tray's hinge is passive, and\n"
    "    link N is a massless radius r4 about the cup's centre C carrying the ball's mass at\n"
    "    its tip: the ball's centre moves on the circle of radius r4 about C.\n"
    "    The rolling ball's SPIN is body spin1: the ball rolls without slip inside the cup,\n"
    "    so its absolute rate is (theta1' + theta2' + theta3') - (r4/r_b) theta4' (a\n"
    "    core::SpinningInertia with coefficients (1, 1, 1, -r4/r_b)). It couples several\n"
    "    joints, so it cannot be armature (armature is diagonal) and no tree of rigid bodies\n"
    "    with positive inertias reproduces I c c^T: spin1 hangs on link N with its own hinge\n"
    "    spin1_joint, which must turn by psi = -(1 + r4/r_b) theta4, enforced by the joint\n"
    "    equality spin1_rolls. Kinematic replay sets psi exactly; mj_inverse is exact after\n"
    "    projecting onto the chain (tau_chain = J^T qfrc_inverse, q_mujoco = J q_chain);\n"
    "    mj_step treats the stiff equality as MuJoCo's soft constraint (impedance 0.9999), "
    "which\n"
    "    conserves energy to ~1e-7 relative (tests/scene/pendulum_mujoco_test.cpp).\n";

// the world's geoms: the wall plane, the pedestal under joint 1 and a floor line
std::string tray_world(const Eigen::Vector2d& b, double r, double rb, double cx, double cy,
                       double half) {
  auto w = xml();
  w << shadow_light(0.5 * half);
  w << "    <geom name=\"wall\" type=\"plane\" pos=\"" << cx << " " << cy << " "
    << -6 * std::max(r, rb) << "\" size=\"" << half << " " << half << " " << plane_grid(half)
    << "\" material=\"wall\"/>\n";
  w << "    <geom name=\"pedestal\" type=\"box\" pos=\"" << b.x() << " " << b.y() - 2.5 * r << " "
    << -2 * r << "\" size=\"" << 2.2 * r << " " << 2.5 * r << " " << r
    << "\" rgba=\"0.25 0.25 0.28 1\"/>\n"
    << "    <geom name=\"floor\" type=\"box\" pos=\"" << b.x() << " " << b.y() - 5.2 * r << " "
    << -2 * r << "\" size=\"" << 8 * r << " " << 0.3 * r << " " << r
    << "\" rgba=\"0.25 0.25 0.28 1\"/>\n";
  return w.str();
}

// the tray's cup as an arc of radius rc about C = (d, 0) in the tray's frame, hung from the
// tray's hinge by two struts to its rims
std::string cup_xml(double d, double rc, double r, double cup_width) {
  auto c = xml();
  const int segments = 16;
  for (int k = 0; k < segments; ++k) {
    const double a0 = -cup_width / 2 + cup_width * k / segments;
    const double a1 = -cup_width / 2 + cup_width * (k + 1) / segments;
    c << "      <geom name=\"cup" << k << "\" type=\"capsule\" fromto=\"" << d + rc * std::cos(a0)
      << " " << rc * std::sin(a0) << " 0 " << d + rc * std::cos(a1) << " " << rc * std::sin(a1)
      << " 0\" size=\"" << 0.35 * r << "\" rgba=\"0.40 0.40 0.45 1\"/>\n";
  }
  for (double a : {-cup_width / 2, cup_width / 2})
    c << "      <geom name=\"cup_strut" << (a < 0 ? 0 : 1) << "\" type=\"capsule\" fromto=\"0 0 0 "
      << d + rc * std::cos(a) << " " << rc * std::sin(a) << " 0\" size=\"" << 0.22 * r
      << "\" rgba=\"0.40 0.40 0.45 1\"/>\n";
  return c.str();
}

// the ball: drawn on the spin body of the ball's spinner (the one turning with the ball
// joint), which sits at the ball's centre (tip of link N); else at the tip
void place_ball(const core::PlanarChain& chain, double r4, double rb, MjcfOptions& o) {
  const int n = chain.num_links();
  auto ball = xml();
  ball << "      <geom name=\"ball\" type=\"sphere\" size=\"" << rb
       << "\" rgba=\"0.86 0.14 0.14 1\"/>\n"
       << "      <geom name=\"ball_stripe\" type=\"box\" pos=\"0 0 " << 0.85 * rb << "\" size=\""
       << 0.75 * rb << " " << 0.13 * rb << " " << 0.2 * rb << "\" rgba=\"0.35 0.04 0.04 1\"/>\n";
  bool ball_drawn = false;
  o.spinner_pos.assign(chain.spinners.size(), Eigen::Vector2d::Zero());
  o.spinner_extra.assign(chain.spinners.size(), "");
  for (const SpinnerBody& sb : spinner_bodies(chain)) {
    if (ball_drawn || sb.link != n - 1 || chain.spinners[sb.spinner].coeffs[n - 1] == 0.0) continue;
    o.spinner_pos[sb.spinner] = Eigen::Vector2d(r4, 0);
    o.spinner_extra[sb.spinner] = ball.str();
    ball_drawn = true;
  }
  if (!ball_drawn) {
    auto t = xml();
    t << "      <body name=\"ball_visual\" pos=\"" << r4 << " 0 0\">\n"
      << ball.str() << "      </body>\n";
    o.tip_extra = t.str();
  }
}
}  // namespace

ArmScene tray_arm_scene(const core::PlanarChain& chain, const TrayDecor& decor) {
  const int n = chain.num_links();
  if (n < 2) throw std::invalid_argument("tray_arm_scene: the chain needs a tray and a ball link");
  ArmScene s;
  s.chain = chain;
  const double rb = decor.ball_radius;
  const double r4 = chain.links[n - 1].length;
  const double d = chain.links[n - 2].length;
  const double R = reach(chain) + rb;
  double r = 0;
  for (int i = 0; i < n - 2; ++i) r = std::max(r, 0.04 * chain.links[i].length);
  if (r == 0) r = 0.25 * rb;
  const Eigen::Vector2d b = chain.base;
  s.view = decor.view ? *decor.view : ViewBox{b.x() - R, b.x() + R, b.y() - R, b.y() + R};
  const ViewBox& v = s.view;
  const double cx = 0.5 * (v.x_min + v.x_max), cy = 0.5 * (v.y_min + v.y_max);
  const double half = 2.0 * std::max(v.x_max - v.x_min, v.y_max - v.y_min);

  MjcfOptions o;
  o.model_name = "tray_arm";
  o.fovy = kFovy;
  o.top_extra = viewer_centre(cx, cy);
  o.offscreen = decor.offscreen;
  set_quality(&o, std::max(1.35 * r, rb), v.y_max - v.y_min,
              decor.offscreen.height);  // discs, ball
  o.link_radius = r;
  o.link_rgba = {"0.18 0.38 0.75 1", "0.10 0.58 0.55 1", "0.40 0.40 0.45 1", "0.85 0.15 0.15 0"};
  if (n == 2) o.link_rgba = {"0.40 0.40 0.45 1", "0.85 0.15 0.15 0"};
  o.visual_extra = kVisual;
  {
    const double rgb[3] = {0.97, 0.97, 0.98}, mark[3] = {0.86, 0.86, 0.90};
    o.asset_extra =
        grid_asset("wall", kWallGridM, v, decor.offscreen.width, decor.offscreen.height, rgb, mark);
  }
  o.comment = kTrayComment;
  o.world_extra = tray_world(b, r, rb, cx, cy, half);
  // joints as discs; the tray's cup about C = (d, 0) in the tray's frame
  o.link_extra.assign(n, "");
  for (int i = 0; i < n - 1; ++i) {
    auto j = xml();
    j << "      <geom name=\"joint" << i + 1 << "_disc\" type=\"cylinder\" pos=\"0 0 0\" size=\""
      << 1.35 * r << " " << 1.1 * r << "\" rgba=\"0.25 0.25 0.28 1\"/>\n";
    o.link_extra[i] = j.str();
  }
  o.link_extra[n - 2] += cup_xml(d, r4 + rb + 0.35 * r, r, decor.cup_width);
  place_ball(chain, r4, rb, o);
  s.mjcf = write_mjcf(chain, o);
  return s;
}

}  // namespace armstudy::scene
