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

#include <emmintrin.h>

#include <algorithm>
#include <cmath>

namespace armstudy::studies {

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
inline int lanes_set(bool a) { return a ? 1 : 0; }

inline D2 select(M2 m, D2 a, D2 b) {
  return D2(_mm_or_pd(_mm_and_pd(m.m, a.v), _mm_andnot_pd(m.m, b.v)));
}
inline double select(bool m, double a, double b) { return m ? a : b; }

inline D2 lane_abs(D2 a) { return D2(_mm_andnot_pd(_mm_set1_pd(-0.0), a.v)); }
inline double lane_abs(double a) { return std::abs(a); }
inline D2 lane_sqrt(D2 a) { return D2(_mm_sqrt_pd(a.v)); }
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

/// Four lanes as two D2 (two independent chains of the same operations, which the processor
/// overlaps); lanes 0, 1 in a, 2, 3 in b.
struct M4 {
  M2 a, b;
};
struct D4 {
  D2 a, b;
  D4() = default;
  D4(double x) : a(x), b(x) {}  // NOLINT: implicit, a constant in every lane
  D4(D2 lo, D2 hi) : a(lo), b(hi) {}
  static D4 of(double l0, double l1, double l2, double l3) {
    return {D2::of(l0, l1), D2::of(l2, l3)};
  }
  double lane(int i) const { return i < 2 ? a.lane(i) : b.lane(i - 2); }
};

inline D4 operator+(const D4& x, const D4& y) { return {x.a + y.a, x.b + y.b}; }
inline D4 operator-(const D4& x, const D4& y) { return {x.a - y.a, x.b - y.b}; }
inline D4 operator*(const D4& x, const D4& y) { return {x.a * y.a, x.b * y.b}; }
inline D4 operator/(const D4& x, const D4& y) { return {x.a / y.a, x.b / y.b}; }
inline D4 operator-(const D4& x) { return {-x.a, -x.b}; }
inline D4& operator+=(D4& x, const D4& y) { return x = x + y; }
inline D4& operator-=(D4& x, const D4& y) { return x = x - y; }
inline D4& operator/=(D4& x, const D4& y) { return x = x / y; }

inline M4 operator<(const D4& x, const D4& y) { return {x.a < y.a, x.b < y.b}; }
inline M4 operator>(const D4& x, const D4& y) { return {x.a > y.a, x.b > y.b}; }
inline M4 operator<=(const D4& x, const D4& y) { return {x.a <= y.a, x.b <= y.b}; }
inline M4 operator==(const D4& x, const D4& y) { return {x.a == y.a, x.b == y.b}; }
inline M4 operator!=(const D4& x, const D4& y) { return {x.a != y.a, x.b != y.b}; }
inline M4 operator|(const M4& x, const M4& y) { return {x.a | y.a, x.b | y.b}; }
inline M4 operator&(const M4& x, const M4& y) { return {x.a & y.a, x.b & y.b}; }
inline M4 operator!(const M4& x) { return {!x.a, !x.b}; }

inline int lanes_set(const M4& x) { return lanes_set(x.a) | (lanes_set(x.b) << 2); }
inline D4 select(const M4& m, const D4& x, const D4& y) {
  return {select(m.a, x.a, y.a), select(m.b, x.b, y.b)};
}
inline D4 lane_abs(const D4& x) { return {lane_abs(x.a), lane_abs(x.b)}; }
inline D4 lane_sqrt(const D4& x) { return {lane_sqrt(x.a), lane_sqrt(x.b)}; }
inline D4 lane_max(const D4& x, const D4& y) { return {lane_max(x.a, y.a), lane_max(x.b, y.b)}; }
inline D4 lane_min(const D4& x, const D4& y) { return {lane_min(x.a, y.a), lane_min(x.b, y.b)}; }
inline M4 lane_finite(const D4& x) { return {lane_finite(x.a), lane_finite(x.b)}; }
inline void lane_cos_sin(const D4& x, D4& c, D4& s) {
  lane_cos_sin(x.a, c.a, s.a);
  lane_cos_sin(x.b, c.b, s.b);
}
inline double lane_of(const D4& x, int i) { return x.lane(i); }

/// Mask or, not (|| and ! of bools).
inline bool lane_or(bool a, bool b) { return a || b; }
inline M2 lane_or(M2 a, M2 b) { return a | b; }
inline M4 lane_or(const M4& a, const M4& b) { return a | b; }
inline bool lane_not(bool a) { return !a; }
inline M2 lane_not(M2 a) { return !a; }
inline M4 lane_not(const M4& a) { return !a; }

}  // namespace armstudy::studies
