// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Report speed: a line plot of the optima (8 curves, 101 points) and a shaded placement
// map (120 x 60 cells with regions and a marker), written as SVG to a temporary folder.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "report/case_report.hpp"
#include "report/plot.hpp"

namespace {
namespace fs = std::filesystem;
using namespace armstudy::report;

fs::path bench_dir() {
  const fs::path d = fs::temp_directory_path() / "armstudy_report_bench";
  fs::create_directories(d);
  return d;
}

LinePlot four_optima_plot() {
  LinePlot p;
  p.title = "joint angles of the optima";
  p.x_label = "time (s)";
  p.y_label = "joint angle (rad)";
  for (int o = 0; o < 8; ++o) {
    Series s;
    s.label = "series " + std::to_string(o);
    s.colour = colour_for("series" + std::to_string(o));
    for (int i = 0; i <= 100; ++i) {
      s.x.push_back(i * 0.01);
      s.y.push_back(std::sin(3.0 * i * 0.01 + o));
    }
    p.series.push_back(std::move(s));
  }
  return p;
}

// a 120 x 60 map like a thinned placement map: an annulus with a singular band
ShadedMap placement_like_map() {
  ShadedMap m;
  m.title = "energy over root locations";
  m.x_label = "X (m)";
  m.y_label = "Y (m)";
  m.z_label = "energy (J)";
  m.nx = 120;
  m.ny = 60;
  m.x_min = -0.6;
  m.x_max = 0.6;
  m.y_min = 0;
  m.y_max = 0.6;
  m.z.assign(m.nx * m.ny, NAN);
  MapRegion out{"unreachable", {215, 215, 215}, std::vector<std::uint8_t>(m.nx * m.ny, 0)};
  MapRegion sing{"singular", {238, 120, 120}, std::vector<std::uint8_t>(m.nx * m.ny, 0)};
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      const double x = m.x_min + (m.x_max - m.x_min) * i / (m.nx - 1);
      const double y = m.y_min + (m.y_max - m.y_min) * j / (m.ny - 1);
      const double r = std::hypot(x - 0.1, y);
      const size_t k = static_cast<size_t>(j) * m.nx + i;
      if (r > 0.55 || r < 0.15)
        out.mask[k] = 1;
      else if (r < 0.2)
        sing.mask[k] = 1;
      else
        m.z[k] = 2 + 10 * (0.55 - r) * (0.55 - r) + x;
    }
  m.regions = {out, sing};
  m.markers = {{0.3, 0.2, "optimum", colour_for("cycloidal/1")}};
  return m;
}

void BM_LinePlot8Series101Points(benchmark::State& state) {
  const auto plot = four_optima_plot();
  const fs::path svg = bench_dir() / "line.svg";
  for (auto _ : state) write_line_plot(plot, svg);
}
BENCHMARK(BM_LinePlot8Series101Points)->Unit(benchmark::kMillisecond);

void BM_ShadedMap120x60(benchmark::State& state) {
  const auto map = placement_like_map();
  const fs::path svg = bench_dir() / "map.svg";
  for (auto _ : state) write_shaded_map(map, svg);
  state.counters["svg_kB"] = static_cast<double>(fs::file_size(svg)) / 1024;
}
BENCHMARK(BM_ShadedMap120x60)->Unit(benchmark::kMillisecond);

}  // namespace
