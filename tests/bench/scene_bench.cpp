// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Off-screen rendering throughput at 640x480 (frames per second): MuJoCo render + pixel
// read-back through one reused OSMesa context, with and without PNG encoding (zlib level 1,
// no filters), with shadows, and the locus (a frame with every earlier pose as extra geoms);
// a scene's load in a fresh and in a reused context; the real scene against a minimal one; a
// 16-frame strip on one core and on two.
#include <benchmark/benchmark.h>

#include <chrono>

#include <sched.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/planar_chain.hpp"
#include "scene/frames.hpp"
#include "scene/model_files.hpp"
#include "scene/osmesa_context.hpp"
#include "scene/png_writer.hpp"
#include "testing/tray_poses.hpp"

namespace armstudy::scene {
namespace {

PoseSample pose(double t) { return testing::tray_arm_pose(t); }

void run(benchmark::State& state, bool png, bool shadows) {
  RenderSettings rs;
  rs.frame = {640, 480};
  rs.shadows = shadows;
  SceneRenderer sr(default_tray_scene(), "bench", rs);
  int k = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const Image img = sr.frame(pose(0.01 * (k++ % 80)), {"t = 0.000 s", "", ""});
    if (png) bytes += encode_png(img).size();
    benchmark::DoNotOptimize(img.rgb.data());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (png) state.counters["png_kB"] = bytes / 1024.0 / std::max<int64_t>(1, state.iterations());
}

void BM_RenderReadback640x480(benchmark::State& s) { run(s, false, false); }
void BM_RenderReadbackPng640x480(benchmark::State& s) { run(s, true, false); }
void BM_RenderReadbackPngShadows640x480(benchmark::State& s) { run(s, true, true); }

void BM_EncodePng640x480(benchmark::State& state) {
  SceneRenderer sr(default_tray_scene(), "bench", RenderSettings{});
  const Image img = sr.frame(pose(0.3), {});
  for (auto _ : state) benchmark::DoNotOptimize(encode_png(img));
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Locus11Poses640x480(benchmark::State& state) {
  SceneRenderer sr(default_tray_scene(), "bench", RenderSettings{});
  std::vector<PoseSample> poses;
  for (int k = 0; k < 11; ++k) poses.push_back(pose(0.08 * k));
  for (auto _ : state) benchmark::DoNotOptimize(sr.locus(poses, {}, {}, {}));
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The minimal scene beside the real one: a plane with a checker texture, two capsule links
// and one shadow-casting light, through the same code path (SceneRenderer::frame: pose,
// scene update, render, labels, read-back) with the same settings; argument: shadows.
ArmScene minimal_scene() {
  ArmScene s;
  s.chain = core::make_chain([] {
    core::PlanarChain c;
    c.links = {{0.5, 1.0, 0.25, 0.0, 0.02, true}, {0.4, 1.0, 0.2, 0.0, 0.01, true}};
    return c;
  }());
  s.mjcf = R"(<mujoco model="minimal">
  <compiler angle="radian" inertiafromgeom="false"/>
  <visual>
    <global offwidth="640" offheight="480" fovy="45"/>
    <quality shadowsize="1024" offsamples="0"/>
  </visual>
  <asset>
    <texture name="checker" type="2d" builtin="checker" rgb1="0.85 0.85 0.85" rgb2="0.7 0.7 0.7" width="256" height="256"/>
    <material name="floor" texture="checker" texrepeat="8 8"/>
  </asset>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1" castshadow="true"/>
    <geom type="plane" size="1.2 1.2 0.1" pos="0 0 -0.05" material="floor" contype="0" conaffinity="0"/>
    <body name="link1">
      <joint name="joint1" type="hinge" axis="0 0 1"/>
      <inertial pos="0.25 0 0" mass="1" diaginertia="0.02 0.02 0.02"/>
      <geom type="capsule" fromto="0 0 0 0.5 0 0" size="0.03" rgba="0.3 0.45 0.7 1" contype="0" conaffinity="0"/>
      <body name="link2" pos="0.5 0 0">
        <joint name="joint2" type="hinge" axis="0 0 1"/>
        <inertial pos="0.2 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
        <geom type="capsule" fromto="0 0 0 0.4 0 0" size="0.03" rgba="0.2 0.6 0.6 1" contype="0" conaffinity="0"/>
      </body>
    </body>
  </worldbody>
</mujoco>
)";
  s.view = {-1.0, 1.0, -0.8, 0.8};
  return s;
}

// the minimal scene's 2-link arm at time t of its sweep
PoseSample minimal_pose(double t) {
  PoseSample p;
  p.t = t;
  p.q = core::JointVector(2);
  p.q << -0.8 + 1.5 * t, 0.3 * std::sin(6 * t);
  return p;
}

void BM_MinimalScene640x480(benchmark::State& state) {
  RenderSettings rs;
  rs.shadows = state.range(0) == 1;
  SceneRenderer sr(minimal_scene(), "minimal", rs);
  PoseSample warm;
  warm.q = core::JointVector::Zero(2);
  benchmark::DoNotOptimize(
      sr.frame(warm, {"warm-up", "", ""}).rgb.data());  // shaders compiled here
  int k = 0;
  for (auto _ : state) {
    const Image img = sr.frame(minimal_pose(0.01 * (k++ % 80)), {"t = 0.000 s", "", ""});
    benchmark::DoNotOptimize(img.rgb.data());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
// the real scene (the tray arm), same loop, same arguments
void BM_RealScene640x480(benchmark::State& state) {
  RenderSettings rs;
  rs.shadows = state.range(0) == 1;
  SceneRenderer sr(default_tray_scene(), "bench", rs);
  benchmark::DoNotOptimize(sr.frame(pose(0.0), {"warm-up", "", ""}).rgb.data());
  int k = 0;
  for (auto _ : state) {
    const Image img = sr.frame(pose(0.01 * (k++ % 80)), {"t = 0.000 s", "", ""});
    benchmark::DoNotOptimize(img.rgb.data());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MinimalScene640x480)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_RealScene640x480)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

// The real scene against the minimal one in one loop: blocks of 8 frames of each in turn,
// each block timed, so that the machine's drift (other jobs, clock changes) falls on both
// alike; real_over_minimal is the real scene's frame rate over the minimal scene's
// (argument: shadows).
void BM_RealAgainstMinimalScene640x480(benchmark::State& state) {
  RenderSettings rs;
  rs.shadows = state.range(0) == 1;
  SceneRenderer minimal(minimal_scene(), "minimal", rs);
  SceneRenderer real(default_tray_scene(), "bench", rs);
  PoseSample warm;
  warm.q = core::JointVector::Zero(2);
  benchmark::DoNotOptimize(minimal.frame(warm, {"warm-up", "", ""}).rgb.data());
  benchmark::DoNotOptimize(real.frame(pose(0.0), {"warm-up", "", ""}).rgb.data());
  constexpr int kBlock = 8;
  double t_minimal = 0, t_real = 0;
  int k = 0;
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const int k0 = k;
    const auto t0 = clock::now();
    for (int i = 0; i < kBlock; ++i)
      benchmark::DoNotOptimize(
          minimal.frame(minimal_pose(0.01 * (k++ % 80)), {"t = 0.000 s", "", ""}).rgb.data());
    const auto t1 = clock::now();
    for (int i = 0; i < kBlock; ++i)
      benchmark::DoNotOptimize(
          real.frame(pose(0.01 * ((k0 + i) % 80)), {"t = 0.000 s", "", ""}).rgb.data());
    const auto t2 = clock::now();
    t_minimal += std::chrono::duration<double>(t1 - t0).count();
    t_real += std::chrono::duration<double>(t2 - t1).count();
  }
  const double frames = static_cast<double>(state.iterations()) * kBlock;
  state.counters["minimal_fps"] = frames / t_minimal;
  state.counters["real_fps"] = frames / t_real;
  state.counters["real_over_minimal"] = t_minimal / t_real;
}
BENCHMARK(BM_RealAgainstMinimalScene640x480)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

// Every thread of this process (llvmpipe's rasteriser threads included) on the first
// `cores` CPUs it may use, for the scope's life; then back on all of them.
class PinnedToCores {
 public:
  explicit PinnedToCores(int cores) {
    sched_getaffinity(0, sizeof all_, &all_);
    cpu_set_t some;
    CPU_ZERO(&some);
    for (int c = 0, n = 0; c < CPU_SETSIZE && n < cores; ++c)
      if (CPU_ISSET(c, &all_)) {
        CPU_SET(c, &some);
        ++n;
      }
    set(some);
  }
  ~PinnedToCores() { set(all_); }
  static int available() {
    cpu_set_t s;
    sched_getaffinity(0, sizeof s, &s);
    return CPU_COUNT(&s);
  }

 private:
  static void set(const cpu_set_t& mask) {
    for (const auto& e : std::filesystem::directory_iterator("/proc/self/task"))
      sched_setaffinity(std::stoi(e.path().filename().string()), sizeof mask, &mask);
  }
  cpu_set_t all_;
};

// a 16-frame strip (SceneRenderer::strip, PNG of the tiled strip included, compressed in
// bands on the second argument's threads) on 1 or 2 drawing processes (first argument: this
// one and a frame helper), this process pinned to the third argument's cores (1: one core's
// rate; 2: both); frames_per_s counts the strip's frames. llvmpipe rasterises every context of
// a process on one set of LP_NUM_THREADS threads (one per core by default), so one process's
// strip already rasterises on both cores: {1, 2, 2} against {1, 1, 1} is what a second
// rasteriser thread gives, {2, 2, 2} what a second process gives
// (BM_StripTwoCoresAgainstOne640x480 measures the latter's ratio interleaved)
void BM_Strip16Frames640x480(benchmark::State& state) {
  const int cores = static_cast<int>(state.range(2));
  if (PinnedToCores::available() < cores) {
    state.SkipWithError("fewer cores than asked");
    return;
  }
  SceneRenderer sr(default_tray_scene(), "bench", RenderSettings{});
  sr.set_strip_threads(static_cast<int>(state.range(0)));
  std::vector<PoseSample> poses;
  for (int k = 0; k < 16; ++k) poses.push_back(pose(0.05 * k));
  PinnedToCores pin(cores);
  benchmark::DoNotOptimize(sr.strip(poses, "warm-up", 3).rgb.data());  // helpers started here
  const int png_threads = static_cast<int>(state.range(1));
  for (auto _ : state)
    benchmark::DoNotOptimize(encode_png(sr.strip(poses, "strip", 3), png_threads).size());
  state.counters["frames_per_s"] = benchmark::Counter(
      16.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Strip16Frames640x480)
    ->Args({1, 1, 1})
    ->Args({1, 1, 2})
    ->Args({1, 2, 2})
    ->Args({2, 2, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

// The 16-frame strip (PNG included) on both cores against one core, in one loop: strips in
// turn, one as armstudy draws a strip with one core (this process pinned to one core, one
// drawing process, one PNG band) and one with two (all cores: a frame helper process beside
// this one, two PNG bands), each timed, so that the machine's drift falls on both;
// two_over_one_core is the two-core strips' frame rate over the one-core strips'.
void BM_StripTwoCoresAgainstOne640x480(benchmark::State& state) {
  if (PinnedToCores::available() < 2) {
    state.SkipWithError("fewer than 2 cores");
    return;
  }
  SceneRenderer one(default_tray_scene(), "bench", RenderSettings{});
  SceneRenderer two(default_tray_scene(), "bench", RenderSettings{});
  two.set_strip_threads(2);
  std::vector<PoseSample> poses;
  for (int k = 0; k < 16; ++k) poses.push_back(pose(0.05 * k));
  benchmark::DoNotOptimize(two.strip(poses, "warm-up", 3).rgb.data());  // the helper starts
  {
    PinnedToCores pin(1);
    benchmark::DoNotOptimize(one.strip(poses, "warm-up", 3).rgb.data());
  }
  using clock = std::chrono::steady_clock;
  double t_one = 0, t_two = 0;
  for (auto _ : state) {
    const auto t0 = clock::now();
    {
      PinnedToCores pin(1);
      benchmark::DoNotOptimize(encode_png(one.strip(poses, "strip", 3), 1).size());
    }
    const auto t1 = clock::now();
    benchmark::DoNotOptimize(encode_png(two.strip(poses, "strip", 3), 2).size());
    const auto t2 = clock::now();
    t_one += std::chrono::duration<double>(t1 - t0).count();
    t_two += std::chrono::duration<double>(t2 - t1).count();
  }
  const double frames = 16.0 * static_cast<double>(state.iterations());
  state.counters["one_core_fps"] = frames / t_one;
  state.counters["two_core_fps"] = frames / t_two;
  state.counters["two_over_one_core"] = t_one / t_two;
}
BENCHMARK(BM_StripTwoCoresAgainstOne640x480)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(4.0);

// Loading a scene and drawing its first frame (SceneRenderer construction + frame), in a
// fresh OSMesa context (argument 0: every kept context held aside, so take_context makes a new
// one and llvmpipe compiles MuJoCo's shaders for it) or in one an earlier renderer gave back
// (argument 1: what every renderer of a run but the first gets)
void BM_SceneLoadAndFirstFrame640x480(benchmark::State& state) {
  const bool reuse = state.range(0) == 1;
  const ArmScene scene = default_tray_scene();
  const RenderSettings rs;
  for (auto _ : state) {
    std::vector<std::unique_ptr<OsmesaContext>> held;
    if (!reuse) {
      state.PauseTiming();
      for (int k = 0; k < 8; ++k) held.push_back(take_context(rs.frame.width, rs.frame.height));
      OsmesaContext::release_current();
      state.ResumeTiming();
    }
    {
      SceneRenderer sr(scene, "bench", rs);
      benchmark::DoNotOptimize(sr.frame(pose(0.1), {"t = 0.100 s", "", ""}).rgb.data());
    }
    if (!reuse) {
      state.PauseTiming();
      for (auto& c : held) give_back_context(std::move(c));
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_SceneLoadAndFirstFrame640x480)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK(BM_RenderReadback640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPngShadows640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodePng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Locus11Poses640x480)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace armstudy::scene
