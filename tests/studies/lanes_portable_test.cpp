// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The portable two-lane arithmetic (studies/throwing/lanes.hpp without SSE2, as on a machine
// of another architecture) gives each lane the scalar result bit for bit, NaN, infinities
// and signed zeros included, as the SSE2 one does.
#define ARMSTUDY_PORTABLE_LANES 1
#include "studies/throwing/lanes.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace armstudy::studies::lanes_portable_test {

static_assert(!ARMSTUDY_LANES_SSE2, "this test must see the portable lanes");

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

TEST(PortableLanes, EachLaneIsTheScalarResultBitForBit) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> xs = {0.0, -0.0, 1.0, -2.5, 1e-310, -1e308, inf, -inf, nan, 3.0};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 10.0);
  for (int k = 0; k < 200; ++k) xs.push_back(n(rng));
  for (size_t i = 0; i < xs.size(); ++i) {
    const double a0 = xs[i], a1 = xs[(i * 7 + 3) % xs.size()];
    const double b0 = xs[(i * 13 + 5) % xs.size()], b1 = xs[(i * 3 + 1) % xs.size()];
    const D2 a = D2::of(a0, a1), b = D2::of(b0, b1);
    const double as[2] = {a0, a1}, bs[2] = {b0, b1};
    for (int l = 0; l < 2; ++l) {
      const double x = as[l], y = bs[l];
      EXPECT_EQ(bits((a + b).lane(l)), bits(x + y));
      EXPECT_EQ(bits((a - b).lane(l)), bits(x - y));
      EXPECT_EQ(bits((a * b).lane(l)), bits(x * y));
      EXPECT_EQ(bits((a / b).lane(l)), bits(x / y));
      EXPECT_EQ(bits((-a).lane(l)), bits(-x));
      EXPECT_EQ(bits(lane_abs(a).lane(l)), bits(lane_abs(x)));
      EXPECT_EQ(bits(lane_sqrt(a).lane(l)), bits(lane_sqrt(x)));
      EXPECT_EQ(bits(lane_max(a, b).lane(l)), bits(lane_max(x, y)));
      EXPECT_EQ(bits(lane_min(a, b).lane(l)), bits(lane_min(x, y)));
      EXPECT_EQ((lanes_set(a < b) >> l) & 1, x < y ? 1 : 0);
      EXPECT_EQ((lanes_set(a != b) >> l) & 1, x != y ? 1 : 0);
      EXPECT_EQ((lanes_set(!(a <= b)) >> l) & 1, !(x <= y) ? 1 : 0);
      EXPECT_EQ((lanes_set(lane_finite(a)) >> l) & 1, lane_finite(x) ? 1 : 0);
      EXPECT_EQ(bits(select(a > b, a, b).lane(l)), bits(select(x > y, x, y)));
    }
  }
}

}  // namespace armstudy::studies::lanes_portable_test
