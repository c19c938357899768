#include "cases/pendulum_case.hpp"

#include "cases/throwing_case.hpp"
#include "core/types.hpp"

namespace armstudy::cases {

studies::PendulumSpec load_pendulum_spec(Map& root) {
  constexpr double kDeg = core::kPi / 180.0;
  studies::PendulumSpec s = studies::default_pendulum_spec();
  auto sec = root.map("pendulum");
  if (!sec) return s;
  read_tray_arm(*sec, s.arm, nullptr);
  if (const auto v = sec->numbers("locked_deg", NumberRule::range(-360, 360, "deg"), 2)) {
    s.theta1 = (*v)[0] * kDeg;
    s.theta2 = (*v)[1] * kDeg;
  }
  if (const auto v = sec->numbers("start_deg", NumberRule::range(-360, 360, "deg"), 2)) {
    s.theta3 = (*v)[0] * kDeg;
    s.theta4 = (*v)[1] * kDeg;
  }
  if (const auto v = sec->numbers("start_rate_deg_s", NumberRule::range(-1e4, 1e4, "deg/s"), 2)) {
    s.theta3_rate = (*v)[0] * kDeg;
    s.theta4_rate = (*v)[1] * kDeg;
  }
  if (const auto v = sec->number("duration_s", NumberRule::range(1e-3, 60.0, "s"))) s.duration = *v;
  if (const auto v = sec->number("sample_s", NumberRule::range(1e-4, 1.0, "s"))) s.sample_step = *v;
  if (const auto v = sec->number("snapshot_s", NumberRule::range(1e-3, 60.0, "s"))) s.snapshot_step = *v;
  if (const auto v = sec->number("rtol", NumberRule::range(1e-14, 1e-3, ""))) s.rtol = *v;
  if (const auto v = sec->number("atol", NumberRule::range(1e-16, 1e-3, ""))) s.atol = *v;
  if (const auto v = sec->number("drift_tolerance", NumberRule::positive(""))) s.drift_tolerance = *v;
  sec->finish();
  return s;
}

}  // namespace armstudy::cases
