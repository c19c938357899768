#include "scene/throwing_frames.hpp"

#include <algorithm>
#include <cstdio>

#include "scene/arm_scene.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {

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
  decor.offwidth = options.width;
  decor.offheight = options.height;
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
  return tray_arm_scene(chain, throwing_decor(spec, chain, throwing_motion(result.idp.series), options));
}

std::vector<std::string> render_throwing_frames(const studies::ThrowingSpec& spec,
                                                const studies::ThrowingResult& result,
                                                const cases::RenderOptions& options,
                                                const std::filesystem::path& dir) {
  const studies::ThrowSeries& s = result.idp.series;
  if (s.t.size() < 2) return {};
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  const SampledMotion m = throwing_motion(s);
  std::vector<std::string> files;
  const std::vector<Eigen::Vector2d>& flight = result.flight.path;
  char title[200];
  std::snprintf(title, sizeof title, "throwing, IDP optimum: %.3f J (eq. 7) in %.2f s",
                result.idp.evaluation.energy, spec.tf);
  const double pad = spec.arm.r4 + 2 * spec.arm.rb + 0.02;
  TrayDecor decor = throwing_decor(spec, chain, m, options);
  {
    SceneRenderer sr(tray_arm_scene(chain, decor), "throwing scene", render_settings(options));
    files.push_back(write_strip(sr, m, options.frames, title, dir, "throwing_idp"));
    FrameLabels labels;
    labels.top_left = std::string(title) + "\nlocus of the throw (Fig. 7); ball path traced";
    labels.bottom_left = "side view, gravity down; grid 0.05 m";
    files.push_back(write_locus(sr, m, 11, s.ball, {}, labels, dir, "throwing_idp"));
  }
  if (flight.size() >= 2) {
    // frame the motion and the whole flight
    ViewBox v = fit_view(chain, m.q, flight, pad);
    v.y_max += 0.15 * (v.y_max - v.y_min);  // room for the labels
    decor.view = v;
    SceneRenderer sr(tray_arm_scene(chain, decor), "throwing scene", render_settings(options));
    FrameLabels labels;
    char t2[200];
    std::snprintf(t2, sizeof t2, "release and flight: %.2f s, lands at x = %.3f m", 
                  result.flight.duration, result.flight.landing.x());
    labels.top_left = std::string(title) + "\n" + t2;
    labels.bottom_left = "side view; red dots: the ball after release";
    std::vector<Eigen::Vector2d> dots;
    for (size_t k = 0; k < flight.size(); ++k) dots.push_back(flight[k]);
    files.push_back(write_locus(sr, m, 11, s.ball, dots, labels, dir, "throwing_flight"));
  }
  return files;
}

}  // namespace armstudy::scene
