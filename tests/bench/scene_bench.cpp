// Off-screen rendering throughput at 640x480 (frames per second): MuJoCo render + pixel
// read-back through one reused OSMesa context, with and without PNG encoding (zlib level 1,
// no filters), with shadows, and the locus (a frame with every earlier pose as extra geoms).
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/planar_chain.hpp"
#include "scene/frames.hpp"
#include "scene/model_files.hpp"
#include "scene/png_writer.hpp"

namespace armstudy::scene {
namespace {

PoseSample pose(double t) {
  PoseSample s;
  s.t = t;
  s.q = core::JointVector(4);
  s.q << -0.8 + 1.5 * t, -0.8 + 0.4 * t, 0.3 * std::sin(6 * t), 0.5 * std::sin(9 * t);
  return s;
}

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
    PoseSample p;
    p.t = 0.01 * (k++ % 80);
    p.q = core::JointVector(2);
    p.q << -0.8 + 1.5 * p.t, 0.3 * std::sin(6 * p.t);
    const Image img = sr.frame(p, {"t = 0.000 s", "", ""});
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

// a 16-frame strip (SceneRenderer::strip, PNG of the tiled strip included, compressed in
// bands on the second argument's threads) on 1 or 2 threads (first argument); frames_per_s counts
// the strip's frames. llvmpipe's rasteriser threads (LP_NUM_THREADS, read once per process; one per
// core by default) are shared by every context of the process: LP_NUM_THREADS=0 gives one
// core's rate (all work on the calling thread), the default both cores' from one thread
void BM_Strip16Frames640x480(benchmark::State& state) {
  SceneRenderer sr(default_tray_scene(), "bench", RenderSettings{});
  sr.set_strip_threads(static_cast<int>(state.range(0)));
  std::vector<PoseSample> poses;
  for (int k = 0; k < 16; ++k) poses.push_back(pose(0.05 * k));
  benchmark::DoNotOptimize(sr.strip(poses, "warm-up", 3).rgb.data());  // twins made here
  const int png_threads = static_cast<int>(state.range(1));
  for (auto _ : state)
    benchmark::DoNotOptimize(encode_png(sr.strip(poses, "strip", 3), png_threads).size());
  state.counters["frames_per_s"] = benchmark::Counter(
      16.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Strip16Frames640x480)
    ->Args({1, 1})
    ->Args({1, 2})
    ->Args({2, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

BENCHMARK(BM_RenderReadback640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPngShadows640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodePng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Locus11Poses640x480)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace armstudy::scene
