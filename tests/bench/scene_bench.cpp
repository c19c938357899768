// Off-screen rendering throughput at 640x480 (frames per second): MuJoCo render + pixel
// read-back through one reused OSMesa context, with and without PNG encoding (zlib level 1,
// no filters), with shadows, and the locus (a frame with every earlier pose as extra geoms).
#include <benchmark/benchmark.h>

#include <cmath>

#include "scene/model_files.hpp"
#include "scene/frames.hpp"
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
  rs.width = 640;
  rs.height = 480;
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

BENCHMARK(BM_RenderReadback640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderReadbackPngShadows640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodePng640x480)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Locus11Poses640x480)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace armstudy::scene
