// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Ordinary differential equation integrators for the small state vectors of the tray arm
/// (passive joints' angles and rates, plus quadrature states such as energy).
///
/// - rk4_step: the classical fourth-order Runge-Kutta step (fixed step h). The throwing
///   study integrates each IDP stage with a whole number of such steps, so that the
///   active joints' piecewise-constant accelerations never jump inside a step (both of its
///   simulations, simulate.cpp's and the lanes of simulate_kernel.cpp, through the form
///   that takes the step's first stage k1 already evaluated).
/// - integrate_dopri5: Dormand-Prince 5(4) with embedded error control (Hairer, Norsett,
///   Wanner, Solving ODE I, II.4 and II.5; the FSAL coefficients of DOPRI5). The step is
///   accepted when the scaled error norm max_i |err_i| / (atol + rtol max(|x_i|, |x_new_i|))
///   is <= 1, and the next step is h * clamp(0.9 err^(-1/5), 0.2, 5). Steps never cross the
///   requested output times, which are hit exactly.
/// Both are templates over the right-hand side f(t, x) -> dx/dt (same size as x).
/// integrate_dopri5 is used by the pendulum study and the throw's open-loop replay.

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

namespace armstudy::core {

/// A state vector of at most 16 entries (no heap allocation).
using OdeState = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 16, 1>;

/// One classical RK4 step of size h (s) from (t, x) whose first stage k1 = f(t, x) the
/// caller has already evaluated (the throwing study reads its constraints at that point);
/// returns x(t + h). State is any value type with State + State and double * State whose
/// results convert to State (OdeState, or the throwing kernel's lanes of five states); f(t,
/// x) returns a State. Component by component, the stages are evaluated at x + (0.5 h) k1,
/// x + (0.5 h) k2 and x + h k3, and the step is x + (h / 6) (((k1 + 2 k2) + 2 k3) + k4),
/// in exactly this order of double operations.
template <typename State, typename F>
State rk4_step(F&& f, double t, const State& x, const State& k1, double h) {
  const State k2 = f(t + 0.5 * h, State(x + 0.5 * h * k1));
  const State k3 = f(t + 0.5 * h, State(x + 0.5 * h * k2));
  const State k4 = f(t + h, State(x + h * k3));
  return State(x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
}

/// One classical RK4 step of size h (s) from (t, x); returns x(t + h).
template <typename F>
OdeState rk4_step(F&& f, double t, const OdeState& x, double h) {
  return rk4_step(f, t, x, OdeState(f(t, x)), h);
}

/// Settings of the adaptive Dormand-Prince integrator.
struct Dopri5Options {
  double rtol = 1e-10;      ///< relative tolerance per component
  double atol = 1e-12;      ///< absolute tolerance per component (units of the state)
  double h_initial = 1e-4;  ///< s, first trial step
  double h_min = 1e-12;     ///< s, below this the integration fails
  long max_steps = 10'000'000;
};

/// Statistics of one adaptive integration.
struct Dopri5Stats {
  long accepted = 0;
  long rejected = 0;
  long evaluations = 0;  ///< right-hand side calls
};

/// Integrates x' = f(t, x) from (t0, x0) through the increasing `times` (all >= t0) with
/// DOPRI5; returns the state at each requested time (hit exactly, no interpolation).
/// `stats`, if given, receives step counts.
/// @throws std::runtime_error if the step falls below h_min or max_steps is exceeded
/// (a stiff or singular right-hand side).
/// (Over 60 lines, kept whole: one adaptive DOPRI5 loop, read as the method's tableau.)
template <typename F>
std::vector<OdeState> integrate_dopri5(F&& f, double t0, const OdeState& x0,
                                       const std::vector<double>& times,
                                       const Dopri5Options& opt = {},
                                       Dopri5Stats* stats = nullptr) {
  // Dormand-Prince 5(4) tableau
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                   a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                   b6 = 11.0 / 84;
  // error coefficients: b - b_hat
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  Dopri5Stats st;
  std::vector<OdeState> out;
  out.reserve(times.size());
  double t = t0;
  OdeState x = x0;
  double h = opt.h_initial;
  OdeState k1 = f(t, x);
  ++st.evaluations;
  for (double t_out : times) {
    if (t_out < t) throw std::invalid_argument("integrate_dopri5: output times must increase");
    while (t < t_out) {
      if (st.accepted + st.rejected >= opt.max_steps)
        throw std::runtime_error("integrate_dopri5: too many steps");
      bool last = false;
      const double h_wanted = h;
      if (t + h >= t_out) {
        h = t_out - t;
        last = true;
      }
      const OdeState k2 = f(t + c2 * h, OdeState(x + h * a21 * k1));
      const OdeState k3 = f(t + c3 * h, OdeState(x + h * (a31 * k1 + a32 * k2)));
      const OdeState k4 = f(t + c4 * h, OdeState(x + h * (a41 * k1 + a42 * k2 + a43 * k3)));
      const OdeState k5 =
          f(t + c5 * h, OdeState(x + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4)));
      const OdeState k6 =
          f(t + h, OdeState(x + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5)));
      const OdeState x_new = x + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
      const OdeState k7 = f(t + h, x_new);
      st.evaluations += 6;
      const OdeState err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
      double norm = 0.0;
      for (int i = 0; i < x.size(); ++i) {
        const double sc = opt.atol + opt.rtol * std::max(std::abs(x[i]), std::abs(x_new[i]));
        norm = std::max(norm, std::abs(err[i]) / sc);
      }
      if (!std::isfinite(norm))
        throw std::runtime_error("integrate_dopri5: the right-hand side is not finite");
      const double factor = std::clamp(0.9 * std::pow(std::max(norm, 1e-10), -0.2), 0.2, 5.0);
      if (norm <= 1.0) {
        ++st.accepted;
        t = last ? t_out : t + h;
        x = x_new;
        k1 = k7;  // first same as last
        // a step shortened to hit an output time does not shrink the next one
        h = last ? std::max(h * factor, h_wanted) : h * factor;
      } else {
        ++st.rejected;
        h *= std::max(factor, 0.2);
        if (h < opt.h_min) throw std::runtime_error("integrate_dopri5: step size underflow");
      }
    }
    out.push_back(x);
  }
  if (stats) *stats = st;
  return out;
}

}  // namespace armstudy::core
