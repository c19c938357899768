// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The MuJoCo scenes of the two arms, generated from the case's chain (so that masses,
/// centres of mass and inertias are the case's): the horizontal 2-link arm on a table seen
/// from above, with the straight-line task and the root marked; the tray arm in a vertical
/// plane seen from the side, with the rolling ball.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/planar_chain.hpp"
#include "scene/renderer.hpp"
#include "studies/arm_origin.hpp"

namespace armstudy::scene {

/// A model to load and the rectangle its camera frames.
struct ArmScene {
  core::PlanarChain chain;
  std::string mjcf;
  ViewBox view;
};

/// The spacing of the grid drawn on the horizontal arm's table and behind the tray arm, m
/// (the frames' captions say it from here).
inline constexpr double kTableGridM = 0.2;
inline constexpr double kWallGridM = 0.1;
/// "grid 0.2 m"
std::string grid_caption(double spacing_m);

/// What the horizontal arm's table shows besides the arm (world frame, m).
struct TableDecor {
  std::optional<Eigen::Vector2d> task_start;  ///< the straight-line task S -> F
  std::optional<Eigen::Vector2d> task_end;
  /// A task path as a polyline (used when task_start/task_end are not set), m.
  std::vector<Eigen::Vector2d> task_path;
  cases::FrameSize offscreen;  ///< the model's off-screen buffer, px: at least the frame
  /// The limits the study used, for model.xml (empty: none): per joint a range [lo, hi]
  /// (rad), a torque bound (N m, the motors' force range) and a velocity bound (rad/s,
  /// written as a comment: MJCF has no joint velocity limit).
  std::vector<Eigen::Vector2d> joint_range;
  std::vector<double> torque_limit, velocity_limit;
  /// Where the arm came from (its model file, plane and limits' sources).
  studies::ArmOrigin origin;
};

/// The arm in its plane seen from +z (x right, y up): a horizontal arm (gravity 0, model
/// `horizontal_arm`) on a table seen from above, or an arm in a vertical plane (model
/// `vertical_arm`, gravity along -y, down the image) before a wall; an arm read from a
/// model file is named after it. The horizontal arm on a table (top view): links in blue and teal,
/// the payload as an orange sphere at the tip, the task line in red with its start and end, the
/// root as a dark pedestal with a cross; a kTableGridM grid on the table.
ArmScene horizontal_arm_scene(const core::PlanarChain& chain, const TableDecor& decor);

/// What the tray arm's scene needs besides the chain.
struct TrayDecor {
  double ball_radius = 0.010;   ///< m (r_b)
  double cup_width = 2.0;       ///< rad, the tray's angular width (lambda of eq. 9)
  cases::FrameSize offscreen;   ///< the model's off-screen buffer, px
  std::optional<ViewBox> view;  ///< default: everything the arm can reach
};

/// The tray arm in a vertical plane (side view, gravity down the image): links 1 and 2
/// driven, the tray (link N-1) a cup of radius r4 + r_b about the end of its axis, the ball
/// (tip of link N) a red sphere with a white stripe that shows its spin. The ball's spin
/// is an extra body with its own hinge coupled to the ball joint by a joint equality
/// (mjcf_writer.hpp); the model's comment says so.
/// @throws std::invalid_argument if the chain has fewer than 2 links.
ArmScene tray_arm_scene(const core::PlanarChain& chain, const TrayDecor& decor);

}  // namespace armstudy::scene
