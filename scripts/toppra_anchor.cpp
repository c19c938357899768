// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// TOPP-RA's side of the exact time-optimal comparison (scripts/bench_toppra.sh builds and runs
// it against a TOPP-RA build; TOPP-RA is not a dependency of armstudy).
//
// The anchor problem: horizontal plane, massless links of 1 m with a 1 kg point mass at the
// end of each, tip on the straight line (1.6, 0.4) -> (0.4, 1.6) m, |tau| <= 10 N m,
// |qd| <= 2 rad/s, rest to rest, elbow q2 > 0. The path is the exact joint path q(s) of the
// line (closed-form inverse kinematics, s the arc length), limits at the grid points
// (TOPP-RA's interpolation discretisation), its Seidel LP solver.
//
// usage: toppra_anchor [intervals (1000)] [repeats (200)]
// prints: intervals, duration (s, full precision), and the solve time per run (ms): wall
// median and minimum, and the median thread CPU time, over the repeats (each run builds the
// constraints' parameters and solves).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <vector>

#include <toppra/algorithm/toppra.hpp>
#include <toppra/constraint/joint_torque.hpp>
#include <toppra/constraint/linear_joint_velocity.hpp>
#include <toppra/geometric_path.hpp>
#include <toppra/solver/seidel.hpp>
#include <toppra/toppra.hpp>

namespace {

constexpr double kL1 = 1.0, kL2 = 1.0, kM1 = 1.0, kM2 = 1.0;
const double kAx = 1.6, kAy = 0.4, kBx = 0.4, kBy = 1.6;

// joint path of the straight tip line, s in [0, length] (arc length)
class LinePath : public toppra::GeometricPath {
 public:
  LinePath() : toppra::GeometricPath(2) {
    length_ = std::hypot(kBx - kAx, kBy - kAy);
    ux_ = (kBx - kAx) / length_;
    uy_ = (kBy - kAy) / length_;
  }
  toppra::Vector eval_single(toppra::value_type s, int order) const override {
    const double px = kAx + s * ux_, py = kAy + s * uy_;
    const double c2 = (px * px + py * py - kL1 * kL1 - kL2 * kL2) / (2 * kL1 * kL2);
    const double s2 = std::sqrt(std::max(0.0, 1 - c2 * c2));  // elbow q2 > 0
    const double q2 = std::atan2(s2, c2);
    const double q1 = std::atan2(py, px) - std::atan2(kL2 * s2, kL1 + kL2 * c2);
    toppra::Vector out(2);
    if (order == 0) {
      out << q1, q2;
      return out;
    }
    // J q' = u; J q'' = -Jdot(q, q') q'
    const double a1 = q1, a12 = q1 + q2;
    const double j11 = -kL1 * std::sin(a1) - kL2 * std::sin(a12), j12 = -kL2 * std::sin(a12);
    const double j21 = kL1 * std::cos(a1) + kL2 * std::cos(a12), j22 = kL2 * std::cos(a12);
    const double det = j11 * j22 - j12 * j21;
    const double qd1 = (j22 * ux_ - j12 * uy_) / det, qd2 = (-j21 * ux_ + j11 * uy_) / det;
    if (order == 1) {
      out << qd1, qd2;
      return out;
    }
    const double w1 = qd1, w12 = qd1 + qd2;
    const double bx = kL1 * std::cos(a1) * w1 * w1 + kL2 * std::cos(a12) * w12 * w12;
    const double by = kL1 * std::sin(a1) * w1 * w1 + kL2 * std::sin(a12) * w12 * w12;
    out << (j22 * bx - j12 * by) / det, (-j21 * bx + j11 * by) / det;
    return out;
  }
  toppra::Bound pathInterval() const override { return {0.0, length_}; }

 private:
  double length_, ux_, uy_;
};

// closed-form inverse dynamics of the two point masses (relative angles, no gravity)
class Torque : public toppra::constraint::JointTorque {
 public:
  Torque(const toppra::Vector& lo, const toppra::Vector& hi)
      : toppra::constraint::JointTorque(lo, hi, toppra::Vector()) {}
  void computeInverseDynamics(const toppra::Vector& q, const toppra::Vector& v,
                              const toppra::Vector& a, toppra::Vector& tau) override {
    const double c2 = std::cos(q[1]), s2 = std::sin(q[1]);
    const double m11 = kM1 * kL1 * kL1 + kM2 * (kL1 * kL1 + kL2 * kL2 + 2 * kL1 * kL2 * c2);
    const double m12 = kM2 * (kL2 * kL2 + kL1 * kL2 * c2), m22 = kM2 * kL2 * kL2;
    const double hh = kM2 * kL1 * kL2 * s2;
    tau.resize(2);
    tau[0] = m11 * a[0] + m12 * a[1] - hh * (2 * v[0] * v[1] + v[1] * v[1]);
    tau[1] = m12 * a[0] + m22 * a[1] + hh * v[0] * v[0];
  }
};

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// wall ms of one solve; its thread CPU ms in *cpu
double solve_once(int intervals, double* duration, double* cpu) {
  const double c0 = thread_cpu_ms();
  const auto t0 = std::chrono::steady_clock::now();
  auto path = std::make_shared<LinePath>();
  toppra::Vector vmax(2), tmax(2);
  vmax << 2.0, 2.0;
  tmax << 10.0, 10.0;
  auto vel = std::make_shared<toppra::constraint::LinearJointVelocity>(-vmax, vmax);
  auto trq = std::make_shared<Torque>(-tmax, tmax);
  vel->discretizationType(toppra::Interpolation);
  trq->discretizationType(toppra::Interpolation);
  toppra::algorithm::TOPPRA algo({vel, trq}, path);
  algo.setN(intervals);
  algo.solver(std::make_shared<toppra::solver::Seidel>());
  const toppra::ReturnCode rc = algo.computePathParametrization(0, 0);
  const auto t1 = std::chrono::steady_clock::now();
  *cpu = thread_cpu_ms() - c0;
  if (rc != toppra::ReturnCode::OK) {
    std::fprintf(stderr, "TOPP-RA failed: %s\n", algo.getErrorMessage().c_str());
    std::exit(1);
  }
  const auto& d = algo.getParameterizationData();
  double T = 0;
  for (int i = 0; i < intervals; ++i) {
    const double ds = d.gridpoints[i + 1] - d.gridpoints[i];
    T += 2 * ds /
         (std::sqrt(std::max(0.0, d.parametrization[i])) +
          std::sqrt(std::max(0.0, d.parametrization[i + 1])));
  }
  *duration = T;
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int intervals = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 200;
  double T = 0, cpu = 0;
  solve_once(intervals, &T, &cpu);  // warm-up
  std::vector<double> ms, cpus;
  for (int r = 0; r < repeats; ++r) {
    ms.push_back(solve_once(intervals, &T, &cpu));
    cpus.push_back(cpu);
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpus.begin(), cpus.end());
  std::printf(
      "toppra intervals %d duration_s %.12f median_ms %.4f min_ms %.4f cpu_median_ms %.4f repeats "
      "%d\n",
      intervals, T, ms[ms.size() / 2], ms.front(), cpus[cpus.size() / 2], repeats);
  return 0;
}
