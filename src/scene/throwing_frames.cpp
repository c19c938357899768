// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/throwing_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/animation.hpp"
#include "scene/arm_scene.hpp"
#include "scene/study_frames.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::scene {

// the motion of one optimiser, its samples strictly increasing in time
SampledMotion throwing_motion(const studies::ThrowSeries& s) {
  SampledMotion m;
  // the series repeats each interior stage boundary: keep strictly increasing times
  for (size_t k = 0; k < s.t.size(); ++k) {
    if (!m.t.empty() && s.t[k] <= m.t.back()) continue;
    m.t.push_back(s.t[k]);
    m.q.push_back(s.q[k]);
    m.qd.push_back(s.qd[k]);
  }
  return m;
}

namespace {
TrayDecor throwing_decor(const studies::ThrowingSpec& spec, const core::PlanarChain& chain,
                         const SampledMotion& m, const cases::RenderOptions& options) {
  TrayDecor decor;
  decor.ball_radius = spec.arm.rb;
  decor.cup_width = spec.tray_width;
  decor.offscreen = options.frame;
  // frame the motion itself (with room for the cup, the pedestal and the labels)
  const double pad = spec.arm.r4 + 2 * spec.arm.rb + 0.02;
  ViewBox motion_box = fit_view(chain, m.q, {}, pad);
  motion_box.y_max += 0.12 * (motion_box.y_max - motion_box.y_min);
  decor.view = motion_box;
  return decor;
}
}  // namespace

ArmScene throwing_scene(const studies::ThrowingSpec& spec, const studies::ThrowingResult& result,
                        const cases::RenderOptions& options) {
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  return tray_arm_scene(chain,
                        throwing_decor(spec, chain, throwing_motion(result.idp.series), options));
}

namespace {
// one optimiser's throw to draw: IDP (the files keep their names) or SLSQP
struct Thrown {
  const studies::ThrowMotion* motion;
  std::string who, stem, flight_stem;
  studies::Flight flight;
  bool strip;
};

// a close-up of the tray over the last tenth of the throw: the 15 mm ball and the tray's
// angle at release, which the whole-motion view draws a few pixels large
void render_release_closeup(const studies::ThrowingSpec& spec, const core::PlanarChain& chain,
                            const cases::RenderOptions& options, const std::filesystem::path& dir,
                            const Thrown& th, const SampledMotion& m, TrayDecor decor,
                            std::vector<std::string>& files) {
  const studies::ThrowSeries& s = th.motion->series;
  SampledMotion end;
  const double t_from = m.t.back() - 0.1 * (m.t.back() - m.t.front());
  for (size_t k = 0; k < m.t.size(); ++k)
    if (m.t[k] >= t_from) {
      end.t.push_back(m.t[k]);
      end.q.push_back(m.q[k]);
      end.qd.push_back(m.qd[k]);
    }
  if (end.t.size() < 2) return;
  const Eigen::Vector2d b = s.ball.back();
  const double r = spec.arm.r4 + 3 * spec.arm.rb + 0.02;
  const double aspect = double(options.frame.width) / options.frame.height;
  decor.view = {b.x() - r * aspect, b.x() + r * aspect, b.y() - r, b.y() + r};
  SceneRenderer sr(tray_arm_scene(chain, decor), "throwing scene", render_settings(options));
  FrameLabels labels;
  labels.top_left =
      "close-up at release, " + th.who + "\nlast tenth of the throw; ball path traced";
  labels.bottom_left = "side view; ball radius " +
                       std::to_string(static_cast<int>(std::lround(spec.arm.rb * 1000))) + " mm";
  files.push_back(write_locus(sr, end, 5, s.ball, {}, labels, dir, th.stem + "_release"));
}

// the motion and the whole flight of the ball after release, framed together
void render_flight(const studies::ThrowingSpec& spec, const core::PlanarChain& chain,
                   const cases::RenderOptions& options, const std::filesystem::path& dir,
                   const Thrown& th, const SampledMotion& m, const std::string& title,
                   TrayDecor decor, std::vector<std::string>& files) {
  const std::vector<Eigen::Vector2d>& flight = th.flight.path;
  if (flight.size() < 2) return;
  const double pad = spec.arm.r4 + 2 * spec.arm.rb + 0.02;
  ViewBox v = fit_view(chain, m.q, flight, pad);
  v.y_max += 0.15 * (v.y_max - v.y_min);  // room for the labels
  decor.view = v;
  SceneRenderer sr(tray_arm_scene(chain, decor), "throwing scene", render_settings(options));
  FrameLabels labels;
  char t2[200];
  std::snprintf(t2, sizeof t2, "flight %.2f s, lands at x = %.3f m", th.flight.duration,
                th.flight.landing.x());
  labels.top_left = title + "\n" + t2;
  labels.bottom_left = "side view; red dots: the ball after release";
  std::vector<Eigen::Vector2d> dots;
  for (size_t k = 0; k < flight.size(); ++k) dots.push_back(flight[k]);
  files.push_back(
      write_locus(sr, m, 11, th.motion->series.ball, dots, labels, dir, th.flight_stem));
}
}  // namespace

Rendered render_throwing_frames(const studies::ThrowingSpec& spec,
                                const studies::ThrowingResult& result,
                                const cases::RenderOptions& options,
                                const std::filesystem::path& dir) {
  if (result.idp.series.t.size() < 2) return {};
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  // both optimisers: IDP (the files keep their names) and SLSQP when it ran
  std::vector<Thrown> thrown = {
      {&result.idp, "IDP optimum", "throwing_idp", "throwing_flight", result.idp_flight, true}};
  if (result.nlopt_ran && result.nlopt.series.t.size() >= 2)
    thrown.push_back({&result.nlopt, "SLSQP optimum", "throwing_slsqp", "throwing_slsqp_flight",
                      result.nlopt_flight, false});
  Rendered out;
  std::vector<std::string>& files = out.frames;
  for (const Thrown& th : thrown) {
    const studies::ThrowSeries& s = th.motion->series;
    const SampledMotion m = throwing_motion(s);
    char title[200];
    std::snprintf(title, sizeof title, "%s: %.3f J (eq. 7), %.2f s", th.who.c_str(),
                  th.motion->evaluation.energy, spec.tf);
    const TrayDecor decor = throwing_decor(spec, chain, m, options);
    {
      SceneRenderer sr(tray_arm_scene(chain, decor), "throwing scene", render_settings(options));
      if (th.strip) files.push_back(write_strip(sr, m, options.frames, title, dir, th.stem));
      FrameLabels labels;
      labels.top_left = std::string(title) + "\nlocus of the throw (Fig. 7); ball path traced";
      labels.bottom_left = "side view, gravity down; " + grid_caption(kWallGridM);
      files.push_back(write_locus(sr, m, 11, s.ball, {}, labels, dir, th.stem));
      out.animations.push_back(write_animation(sr, m, "throwing, " + th.who, dir, th.stem));
    }
    render_release_closeup(spec, chain, options, dir, th, m, decor, files);
    render_flight(spec, chain, options, dir, th, m, title, decor, files);
  }
  return out;
}

}  // namespace armstudy::scene
