// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/frames.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include "core/kinematics.hpp"
#include "scene/phase_times.hpp"
#include "scene/polyline.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {

namespace {
std::atomic<int> g_frame_processes{1};
}  // namespace

void set_default_frame_processes(int processes) { g_frame_processes = std::clamp(processes, 1, 8); }
int default_frame_processes() { return g_frame_processes; }

std::string time_label(double t) {
  char b[48];
  std::snprintf(b, sizeof b, "t = %.3f s", t);
  return b;
}

std::vector<double> even_times(double t0, double t1, int n) {
  if (n <= 1) return {t0};
  std::vector<double> out(n);
  for (int k = 0; k < n; ++k) out[k] = t0 + (t1 - t0) * k / (n - 1);
  return out;
}

int strip_columns(int n) { return std::clamp(n, 1, 3); }

std::vector<PoseSample> resample(std::span<const double> t, std::span<const core::JointVector> q,
                                 std::span<const core::JointVector> qd,
                                 std::span<const double> at) {
  if (t.empty() || q.size() != t.size()) throw SceneError("resample: no samples");
  std::vector<PoseSample> out;
  for (double ta : at) {
    const double tc = std::clamp(ta, t.front(), t.back());
    const size_t hi = std::min<size_t>(
        t.size() - 1, static_cast<size_t>(std::lower_bound(t.begin(), t.end(), tc) - t.begin()));
    const size_t lo = hi == 0 ? 0 : hi - 1;
    const double span = t[hi] - t[lo];
    const double w = span > 0 ? (tc - t[lo]) / span : 1.0;
    PoseSample s;
    s.t = ta;
    s.q = (1 - w) * q[lo] + w * q[hi];
    if (qd.size() == t.size()) s.qd = (1 - w) * qd[lo] + w * qd[hi];
    out.push_back(s);
  }
  return out;
}

SceneRenderer::SceneRenderer(const ArmScene& scene, const std::string& source,
                             const RenderSettings& settings)
    : load_phase_(std::in_place, "scene_load"),
      chain_(scene.chain),
      model_(scene.mjcf, source),
      map_(scene.chain, model_.model()),
      renderer_(model_.model(), settings, scene.view),
      scene_(scene),
      source_(source),
      settings_(settings),
      strip_threads_(default_frame_processes()) {
  load_phase_.reset();
}

SceneRenderer::~SceneRenderer() {
  for (auto& w : workers_) FrameWorker::release(std::move(w));
}

void SceneRenderer::set_strip_threads(int threads) { strip_threads_ = std::clamp(threads, 1, 8); }

Image SceneRenderer::frame(const PoseSample& s, const FrameLabels& labels) {
  set_pose(model_, map_, s);
  return renderer_.render(model_.data(), labels);
}

std::vector<Image> SceneRenderer::frames(std::span<const PoseSample> samples,
                                         std::span<const FrameLabels> labels) {
  std::vector<Image> out(samples.size());
  draw_frames(samples, labels, [&](size_t k, Image&& image) { out[k] = std::move(image); });
  return out;
}

// (over 60 lines, kept whole: this thread and its helpers' threads share the `next` counter
// and the `taken` flags in its frame)
void SceneRenderer::draw_frames(std::span<const PoseSample> samples,
                                std::span<const FrameLabels> labels,
                                const std::function<void(size_t, Image&&)>& take) {
  if (labels.size() != samples.size())
    throw SceneError("frames: " + std::to_string(labels.size()) + " labels for " +
                     std::to_string(samples.size()) + " poses");
  const size_t n = samples.size();
  // helpers are taken here, once per renderer (a new one takes a fraction of a second to
  // start; one this thread gave back keeps its warm OSMesa contexts), and kept
  const size_t want = std::min<size_t>(static_cast<size_t>(strip_threads_) - 1, n / 2);
  while (!workers_failed_ && workers_.size() < want) {
    auto w = FrameWorker::acquire(scene_, source_, settings_);
    if (!w) {
      workers_failed_ = true;
      break;
    }
    workers_.push_back(std::move(w));
  }
  const size_t helpers = std::min(want, workers_.size());
  // the frames are taken in order, each by whichever process is free: this one draws them
  // itself, a helper's thread keeps two asked of its helper (one drawn while the other
  // travels; one near the end); a helper still starting takes fewer (the model's state of each pose
  // is mapped here, as set_pose maps it)
  std::vector<char> taken(n, 0);
  std::atomic<size_t> next{0};
  std::vector<char> failed(helpers, 0);
  std::exception_ptr stuck;  // a helper that made no progress (frame_worker.cpp)
  std::mutex stuck_mutex;
  std::vector<std::thread> pool;
  for (size_t j = 0; j < helpers; ++j) {
    pool.emplace_back([&, j] {
      FrameWorker& w = *workers_[j];
      std::deque<size_t> asked;
      try {
        w.reset();
        while (true) {
          // two asked while frames are plenty (one drawn while the other travels), one
          // near the end: a frame asked early would wait for the helper while this process
          // could draw it sooner
          while (asked.size() < (n - std::min(n, next.load()) > 2 ? 2u : 1u)) {
            const size_t k = next++;
            if (k >= n) break;
            const PoseSample& s = samples[k];
            const core::JointVector qd =
                s.qd.size() == s.q.size() ? s.qd : core::JointVector::Zero(s.q.size());
            w.send({s.t, map_.jacobian() * s.q, map_.jacobian() * qd, labels[k]});
            asked.push_back(k);
          }
          if (asked.empty()) break;
          const size_t k = asked.front();
          take(k, w.receive());
          taken[k] = 1;
          asked.pop_front();
        }
      } catch (const HelperStuck&) {
        failed[j] = 1;  // ended: the case ends with its error (below)
        const std::lock_guard<std::mutex> lock(stuck_mutex);
        if (!stuck) stuck = std::current_exception();
      } catch (...) {
        failed[j] = 1;  // its frames not drawn are drawn here (below)
      }
    });
  }
  std::exception_ptr here;
  try {
    begin_replay(model_);
    for (size_t k = next++; k < n; k = next++) {
      take(k, frame(samples[k], labels[k]));
      taken[k] = 1;
    }
  } catch (...) {
    here = std::current_exception();
  }
  for (auto& t : pool) t.join();
  if (here) std::rethrow_exception(here);
  if (stuck) {
    workers_failed_ = true;
    workers_.clear();
    std::rethrow_exception(stuck);
  }
  // a helper that failed (died, or its scene raised an error): the frames it did not give
  // are drawn here (where an error of the scene itself is raised again), and no helper is
  // asked again
  if (std::find(failed.begin(), failed.end(), 1) != failed.end()) {
    workers_failed_ = true;
    workers_.clear();
    for (size_t k = 0; k < n; ++k)
      if (!taken[k]) take(k, frame(samples[k], labels[k]));
  }
}

Image SceneRenderer::strip(std::span<const PoseSample> samples, const std::string& title,
                           int columns) {
  std::vector<FrameLabels> labels(samples.size());
  for (size_t k = 0; k < samples.size(); ++k) {
    labels[k].top_left = time_label(samples[k].t);
    if (k == 0 && !title.empty()) labels[k].bottom_left = title;
  }
  // each frame goes to its place on the strip as it comes, on the thread that drew or
  // received it (tile() after frames() gives the same image, one copy after the other);
  // every frame, a helper's too, is this renderer's size
  if (samples.empty()) return {};
  const TileGrid grid(renderer_.width(), renderer_.height(), samples.size(), columns, 8);
  Image out = grid.canvas(Rgb{255, 255, 255});
  draw_frames(samples, labels, [&](size_t k, Image&& image) { grid.place(image, k, &out); });
  return out;
}

std::vector<size_t> evenly_spaced(size_t n, size_t at_most) {
  std::vector<size_t> out;
  if (n <= at_most) {
    for (size_t k = 0; k < n; ++k) out.push_back(k);
    return out;
  }
  const size_t m = std::max<size_t>(at_most, 2);
  for (size_t k = 0; k < m; ++k) out.push_back(k * (n - 1) / (m - 1));
  return out;
}

Image SceneRenderer::locus(std::span<const PoseSample> samples,
                           std::span<const Eigen::Vector2d> path,
                           std::span<const Eigen::Vector2d> flight, const FrameLabels& labels,
                           const LocusStyle& style) {
  if (samples.empty()) throw SceneError("locus: no poses");
  begin_replay(model_);
  const int n = static_cast<int>(samples.size());
  double r = 0;
  for (const auto& l : chain_.links) r = std::max(r, 0.04 * l.length);
  std::vector<mjvGeom> extra;
  // older poses: colours blended toward white and pushed slightly away from the camera
  for (int k = 0; k + 1 < n; ++k) {
    set_pose(model_, map_, samples[k]);
    const double weight = style.faintest + (1 - style.faintest) * k / std::max(1, n - 1);
    for (mjvGeom g : renderer_.dynamic_geoms(model_.data())) {
      if (g.rgba[3] == 0) continue;
      for (int c = 0; c < 3; ++c)
        g.rgba[c] = static_cast<float>(weight * g.rgba[c] + (1 - weight) * 1.0);
      g.pos[2] -= static_cast<float>(0.05 * r * (n - 1 - k));
      extra.push_back(g);
    }
  }
  // the end-effector path on top of everything the last pose draws
  set_pose(model_, map_, samples[n - 1]);
  double top = 3.0 * r;
  for (const mjvGeom& g : renderer_.dynamic_geoms(model_.data())) {
    // z extent of the geom's box (rows of mat are the world axes in the geom frame)
    double ext = std::abs(g.mat[6]) * g.size[0] + std::abs(g.mat[7]) * g.size[1] +
                 std::abs(g.mat[8]) * g.size[2];
    if (g.type == mjGEOM_CAPSULE) ext += g.size[0];
    top = std::max(top, 1.02 * (g.pos[2] + ext));
  }
  // a long path is traced through evenly spaced points of it (both ends kept): the scene
  // has room for a few thousand geoms and a frame for fewer distinct segments than that
  // then as the fewest of those segments that draw the same line (every point dropped
  // within a tenth of a pixel of it)
  std::vector<size_t> along;
  {
    const std::vector<size_t> even = evenly_spaced(path.size(), kMaxTracedSegments + 1);
    std::vector<Eigen::Vector2d> pts;
    for (const size_t k : even) pts.push_back(path[k]);
    for (const size_t k : simplify_polyline(pts, 0.1 * renderer_.metres_per_pixel()))
      along.push_back(even[k]);
  }
  for (size_t k = 1; k < along.size(); ++k)
    extra.push_back(
        segment_geom(Eigen::Vector3d(path[along[k - 1]].x(), path[along[k - 1]].y(), top),
                     Eigen::Vector3d(path[along[k]].x(), path[along[k]].y(), top),
                     style.path_radius * r, style.path_rgba));
  // the thrown object's flight: dots
  const double dot = std::max(0.45 * r, 3.0 * renderer_.metres_per_pixel());
  for (const size_t k : evenly_spaced(flight.size(), kMaxFlightDots))
    extra.push_back(
        sphere_geom(Eigen::Vector3d(flight[k].x(), flight[k].y(), top), dot, style.flight_rgba));
  set_pose(model_, map_, samples[n - 1]);
  return renderer_.render(model_.data(), labels, extra);
}

}  // namespace armstudy::scene
