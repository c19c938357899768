// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Two doubles in one SSE2 register, for evaluating two profiles with the same operations at
/// once (simulate_kernel.hpp). Every operation is the IEEE double operation of the scalar
/// code on each lane (SSE2's addpd, subpd, mulpd, divpd, sqrtpd round each lane like addsd,
/// ...; no fused multiply-add), so a lane's result is the scalar result bit for bit.
/// Comparisons return a lane mask with C++'s semantics (false when a NaN is involved, but
/// != true); select(mask, a, b) takes a where the mask is set. max and min are std::max and
/// std::min lane by lane ((a < b) ? b : a and (b < a) ? b : a, NaN and signed zeros
/// included). cos and sin call std::cos and std::sin on each lane.
///
/// The scalar overloads (double, bool) let one template serve both widths.
///
/// Without SSE2 (another architecture, or ARMSTUDY_PORTABLE_LANES defined, as the test of
/// the fallback does) D2 and M2 are two plain doubles and two bools with the same operations
/// lane by lane: the same results bit for bit, without the vector registers. Each variant
/// lives in an inline namespace of its own, so both can be in one program.

#if defined(__SSE2__) && !defined(ARMSTUDY_PORTABLE_LANES)
#define ARMSTUDY_LANES_SSE2 1
#include <emmintrin.h>
#else
#define ARMSTUDY_LANES_SSE2 0
#endif

#include <algorithm>
#include <cmath>

namespace armstudy::studies {
#if ARMSTUDY_LANES_SSE2
inline namespace lanes_sse2 {

/// Lane mask of D2 comparisons (all bits set in a true lane).
struct M2 {
  __m128d m;
};

/// Two double lanes.
struct D2 {
  __m128d v;
  D2() = default;
  D2(double x) : v(_mm_set1_pd(x)) {}  // NOLINT: implicit, a constant in both lanes
  explicit D2(__m128d x) : v(x) {}
  static D2 of(double lane0, double lane1) { return D2(_mm_set_pd(lane1, lane0)); }
  double lane(int i) const {
    alignas(16) double t[2];
    _mm_store_pd(t, v);
    return t[i];
  }
};

inline D2 operator+(D2 a, D2 b) { return D2(_mm_add_pd(a.v, b.v)); }
inline D2 operator-(D2 a, D2 b) { return D2(_mm_sub_pd(a.v, b.v)); }
inline D2 operator*(D2 a, D2 b) { return D2(_mm_mul_pd(a.v, b.v)); }
inline D2 operator/(D2 a, D2 b) { return D2(_mm_div_pd(a.v, b.v)); }
inline D2 operator-(D2 a) { return D2(_mm_xor_pd(a.v, _mm_set1_pd(-0.0))); }
inline D2& operator+=(D2& a, D2 b) { return a = a + b; }
inline D2& operator-=(D2& a, D2 b) { return a = a - b; }
inline D2& operator/=(D2& a, D2 b) { return a = a / b; }

inline M2 operator<(D2 a, D2 b) { return {_mm_cmplt_pd(a.v, b.v)}; }
inline M2 operator>(D2 a, D2 b) { return {_mm_cmpgt_pd(a.v, b.v)}; }
inline M2 operator<=(D2 a, D2 b) { return {_mm_cmple_pd(a.v, b.v)}; }
inline M2 operator==(D2 a, D2 b) { return {_mm_cmpeq_pd(a.v, b.v)}; }
inline M2 operator!=(D2 a, D2 b) { return {_mm_cmpneq_pd(a.v, b.v)}; }
inline M2 operator|(M2 a, M2 b) { return {_mm_or_pd(a.m, b.m)}; }
inline M2 operator&(M2 a, M2 b) { return {_mm_and_pd(a.m, b.m)}; }
inline M2 operator!(M2 a) { return {_mm_xor_pd(a.m, _mm_castsi128_pd(_mm_set1_epi32(-1)))}; }

/// Bit i set: lane i's mask is true.
inline int lanes_set(M2 a) { return _mm_movemask_pd(a.m); }

inline D2 select(M2 m, D2 a, D2 b) {
  return D2(_mm_or_pd(_mm_and_pd(m.m, a.v), _mm_andnot_pd(m.m, b.v)));
}

inline D2 lane_abs(D2 a) { return D2(_mm_andnot_pd(_mm_set1_pd(-0.0), a.v)); }
inline D2 lane_sqrt(D2 a) { return D2(_mm_sqrt_pd(a.v)); }
}  // namespace lanes_sse2
#else
inline namespace lanes_portable {

/// Lane mask of D2 comparisons.
struct M2 {
  bool m[2];
};

/// Two double lanes.
struct D2 {
  double v[2];
  D2() = default;
  D2(double x) : v{x, x} {}  // NOLINT: implicit, a constant in both lanes
  static D2 of(double lane0, double lane1) {
    D2 d;
    d.v[0] = lane0;
    d.v[1] = lane1;
    return d;
  }
  double lane(int i) const { return v[i]; }
};

template <class F>
inline D2 each(D2 a, D2 b, F f) {
  return D2::of(f(a.v[0], b.v[0]), f(a.v[1], b.v[1]));
}
template <class F>
inline M2 each_mask(D2 a, D2 b, F f) {
  return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1])}};
}
inline D2 operator+(D2 a, D2 b) {
  return each(a, b, [](double x, double y) { return x + y; });
}
inline D2 operator-(D2 a, D2 b) {
  return each(a, b, [](double x, double y) { return x - y; });
}
inline D2 operator*(D2 a, D2 b) {
  return each(a, b, [](double x, double y) { return x * y; });
}
inline D2 operator/(D2 a, D2 b) {
  return each(a, b, [](double x, double y) { return x / y; });
}
inline D2 operator-(D2 a) { return D2::of(-a.v[0], -a.v[1]); }
inline D2& operator+=(D2& a, D2 b) { return a = a + b; }
inline D2& operator-=(D2& a, D2 b) { return a = a - b; }
inline D2& operator/=(D2& a, D2 b) { return a = a / b; }

inline M2 operator<(D2 a, D2 b) {
  return each_mask(a, b, [](double x, double y) { return x < y; });
}
inline M2 operator>(D2 a, D2 b) {
  return each_mask(a, b, [](double x, double y) { return x > y; });
}
inline M2 operator<=(D2 a, D2 b) {
  return each_mask(a, b, [](double x, double y) { return x <= y; });
}
inline M2 operator==(D2 a, D2 b) {
  return each_mask(a, b, [](double x, double y) { return x == y; });
}
inline M2 operator!=(D2 a, D2 b) {
  return each_mask(a, b, [](double x, double y) { return x != y; });
}
inline M2 operator|(M2 a, M2 b) { return {{a.m[0] || b.m[0], a.m[1] || b.m[1]}}; }
inline M2 operator&(M2 a, M2 b) { return {{a.m[0] && b.m[0], a.m[1] && b.m[1]}}; }
inline M2 operator!(M2 a) { return {{!a.m[0], !a.m[1]}}; }

/// Bit i set: lane i's mask is true.
inline int lanes_set(M2 a) { return (a.m[0] ? 1 : 0) | (a.m[1] ? 2 : 0); }

inline D2 select(M2 m, D2 a, D2 b) {
  return D2::of(m.m[0] ? a.v[0] : b.v[0], m.m[1] ? a.v[1] : b.v[1]);
}
inline D2 lane_abs(D2 a) { return D2::of(std::abs(a.v[0]), std::abs(a.v[1])); }
inline D2 lane_sqrt(D2 a) { return D2::of(std::sqrt(a.v[0]), std::sqrt(a.v[1])); }
}  // namespace lanes_portable
#endif
inline int lanes_set(bool a) { return a ? 1 : 0; }
inline double select(bool m, double a, double b) { return m ? a : b; }
inline double lane_abs(double a) { return std::abs(a); }
inline double lane_sqrt(double a) { return std::sqrt(a); }
inline D2 lane_max(D2 a, D2 b) { return select(a < b, b, a); }
inline double lane_max(double a, double b) { return std::max(a, b); }
inline D2 lane_min(D2 a, D2 b) { return select(b < a, b, a); }
inline double lane_min(double a, double b) { return std::min(a, b); }
/// x - x == x - x: false for an infinite or NaN lane (Eigen's allFinite)
inline M2 lane_finite(D2 a) {
  const D2 d = a - a;
  return d == d;
}
inline bool lane_finite(double a) { return std::isfinite(a); }

/// cos and sin of each lane (std::cos, std::sin).
inline void lane_cos_sin(D2 a, D2& c, D2& s) {
  const double a0 = a.lane(0), a1 = a.lane(1);
  const double c0 = std::cos(a0), s0 = std::sin(a0);
  const double c1 = std::cos(a1), s1 = std::sin(a1);
  c = D2::of(c0, c1);
  s = D2::of(s0, s1);
}
inline void lane_cos_sin(double a, double& c, double& s) {
  c = std::cos(a);
  s = std::sin(a);
}

/// Lane i of a value (the value itself for a double).
inline double lane_of(D2 a, int i) { return a.lane(i); }
inline double lane_of(double a, int) { return a; }

/// Mask or and not (|| and ! of bools).
inline bool lane_or(bool a, bool b) { return a || b; }
inline M2 lane_or(M2 a, M2 b) { return a | b; }
inline bool lane_not(bool a) { return !a; }
inline M2 lane_not(M2 a) { return !a; }

/// Lanes side by side: A's, then B's (D2, double or another LanePair). Their operations are
/// independent chains, which the processor overlaps: four lanes as two D2 run faster than
/// two D2 one after the other. The operators are hidden friends, so that a double converts to
/// a constant in every lane as it does for D2.
template <typename A, typename B>
struct LanePair;

/// Lanes of a value type: 1 (double), 2 (D2), the sum for a LanePair.
template <typename T>
inline constexpr int lane_count = 1;
template <>
inline constexpr int lane_count<D2> = 2;
template <typename A, typename B>
inline constexpr int lane_count<LanePair<A, B>> = lane_count<A> + lane_count<B>;

/// The mask of a LanePair's comparisons.
template <typename MA, typename MB, int WA>
struct MaskPair {
  MA a;
  MB b;
  friend MaskPair operator|(const MaskPair& x, const MaskPair& y) {
    return {lane_or(x.a, y.a), lane_or(x.b, y.b)};
  }
  friend MaskPair operator!(const MaskPair& x) { return {lane_not(x.a), lane_not(x.b)}; }
};

template <typename MA, typename MB, int WA>
MaskPair<MA, MB, WA> lane_or(const MaskPair<MA, MB, WA>& a, const MaskPair<MA, MB, WA>& b) {
  return a | b;
}
template <typename MA, typename MB, int WA>
MaskPair<MA, MB, WA> lane_not(const MaskPair<MA, MB, WA>& a) {
  return !a;
}
template <typename MA, typename MB, int WA>
int lanes_set(const MaskPair<MA, MB, WA>& x) {
  return lanes_set(x.a) | (lanes_set(x.b) << WA);
}

template <typename A, typename B>
struct LanePair {
  using Mask = MaskPair<decltype(A() < A()), decltype(B() < B()), lane_count<A>>;
  A a;
  B b;
  LanePair() = default;
  LanePair(double x) : a(x), b(x) {}  // NOLINT: implicit, a constant in every lane
  LanePair(const A& lo, const B& hi) : a(lo), b(hi) {}

  friend LanePair operator+(const LanePair& x, const LanePair& y) { return {x.a + y.a, x.b + y.b}; }
  friend LanePair operator-(const LanePair& x, const LanePair& y) { return {x.a - y.a, x.b - y.b}; }
  friend LanePair operator*(const LanePair& x, const LanePair& y) { return {x.a * y.a, x.b * y.b}; }
  friend LanePair operator/(const LanePair& x, const LanePair& y) { return {x.a / y.a, x.b / y.b}; }
  friend LanePair operator-(const LanePair& x) { return {-x.a, -x.b}; }
  friend LanePair& operator+=(LanePair& x, const LanePair& y) { return x = x + y; }
  friend LanePair& operator-=(LanePair& x, const LanePair& y) { return x = x - y; }
  friend LanePair& operator/=(LanePair& x, const LanePair& y) { return x = x / y; }
  friend Mask operator<(const LanePair& x, const LanePair& y) { return {x.a < y.a, x.b < y.b}; }
  friend Mask operator>(const LanePair& x, const LanePair& y) { return {x.a > y.a, x.b > y.b}; }
  friend Mask operator<=(const LanePair& x, const LanePair& y) { return {x.a <= y.a, x.b <= y.b}; }
  friend Mask operator==(const LanePair& x, const LanePair& y) { return {x.a == y.a, x.b == y.b}; }
  friend Mask operator!=(const LanePair& x, const LanePair& y) { return {x.a != y.a, x.b != y.b}; }
};

template <typename A, typename B>
LanePair<A, B> select(const typename LanePair<A, B>::Mask& m, const LanePair<A, B>& x,
                      const LanePair<A, B>& y) {
  return {select(m.a, x.a, y.a), select(m.b, x.b, y.b)};
}
template <typename A, typename B>
LanePair<A, B> lane_abs(const LanePair<A, B>& x) {
  return {lane_abs(x.a), lane_abs(x.b)};
}
template <typename A, typename B>
LanePair<A, B> lane_sqrt(const LanePair<A, B>& x) {
  return {lane_sqrt(x.a), lane_sqrt(x.b)};
}
template <typename A, typename B>
LanePair<A, B> lane_max(const LanePair<A, B>& x, const LanePair<A, B>& y) {
  return {lane_max(x.a, y.a), lane_max(x.b, y.b)};
}
template <typename A, typename B>
LanePair<A, B> lane_min(const LanePair<A, B>& x, const LanePair<A, B>& y) {
  return {lane_min(x.a, y.a), lane_min(x.b, y.b)};
}
template <typename A, typename B>
typename LanePair<A, B>::Mask lane_finite(const LanePair<A, B>& x) {
  return {lane_finite(x.a), lane_finite(x.b)};
}
template <typename A, typename B>
void lane_cos_sin(const LanePair<A, B>& x, LanePair<A, B>& c, LanePair<A, B>& s) {
  lane_cos_sin(x.a, c.a, s.a);
  lane_cos_sin(x.b, c.b, s.b);
}
template <typename A, typename B>
double lane_of(const LanePair<A, B>& x, int i) {
  return i < lane_count<A> ? lane_of(x.a, i) : lane_of(x.b, i - lane_count<A>);
}

/// A value of lanes v[0 .. lane_count<T>).
template <typename T>
T pack_lanes(const double* v);
template <>
inline double pack_lanes<double>(const double* v) {
  return v[0];
}
template <>
inline D2 pack_lanes<D2>(const double* v) {
  return D2::of(v[0], v[1]);
}
template <typename T>
requires(lane_count<T> > 2) T pack_lanes(const double* v) {
  using A = decltype(T::a);
  using B = decltype(T::b);
  return {pack_lanes<A>(v), pack_lanes<B>(v + lane_count<A>)};
}

using D3 = LanePair<D2, double>;  ///< three lanes
using D4 = LanePair<D2, D2>;      ///< four lanes
using D5 = LanePair<D4, double>;  ///< five lanes

}  // namespace armstudy::studies
