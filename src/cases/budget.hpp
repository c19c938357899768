// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Resource budgets: before anything is solved, each study's loader estimates the work and
/// memory its case asks for (a Demand); the case is refused (exit 2, at the keys that set
/// it) when the estimate is beyond the documented budget, unless the user raised it
/// (`armstudy run|validate --allow-large`). The estimates are coarse (within a few times of
/// the truth) and documented with each study's keys in docs/budgets.md:
///
/// | what                  | unit                                  | budget     |
/// | --------------------- | ------------------------------------- | ---------- |
/// | placement sweep       | trajectory samples evaluated          | 1e10       |
/// | time-optimal solvers  | limit checks (DP states, Complex)     | 1e9        |
/// | throwing IDP + SLSQP  | RK4 steps                             | 1e9        |
/// | pendulum              | output samples                        | 1e7        |
/// | frames                | pixels of the largest strip           | 1e8        |
/// | memory (any study)    | bytes held at once                    | 4 GiB      |

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace armstudy::cases {

inline constexpr double kMemoryBudgetBytes = 4.0 * (1ull << 30);
inline constexpr double kPixelBudget = 1e8;

/// What one study's case asks for, estimated from its keys.
struct Demand {
  std::string what;    ///< e.g. "the placement sweep" (it "asks for")
  std::string keys;    ///< the keys that set it, e.g. "placement.nx_s, placement.phi_step_deg"
  std::string detail;  ///< how the estimate is made, with the numbers
  double work = 0;     ///< in `unit`
  std::string unit;    ///< e.g. "trajectory samples"
  double work_budget = 0;
  /// The part of `work` a warm re-solve of the sensitivity part stands in proportion to (0:
  /// all of it): a study's global phase, which no re-solve repeats, left out.
  double resolve_base = 0;
  /// About how much of `work` one core does per second (measured on the bundled cases);
  /// a run starts its longest cases first by it. 0 when unknown.
  double work_per_second = 0;
  /// About how many frames the study renders (its motions' animations and strips, a
  /// locus pose counted as a frame); with work_per_second, it orders a run's cases.
  double frames_rendered = 0;
  double memory_bytes = 0;  ///< of the solve (frames are added from `render:`)
  int strip_frames = 0;     ///< frames of the study's largest strip, beyond `render.frames`
  YAML::Mark mark;          ///< where to report it (the study's section)
};

/// "3.1 GB", "640 MB", "12 kB".
std::string bytes_text(double bytes);

/// One way a demand is beyond the budget.
struct OverBudget {
  bool frames = false;  ///< about the frames (reported at `render:`), else at the demand
  std::string message;  ///< names the keys and the estimate
};

/// The sensitivity part of a case (`sensitivity:`): each key re-solves the case twice, each
/// re-solve about `fraction` of the solve's work (app/run_order.hpp measures it), so the
/// part asks for the solve's work x 2 keys fraction. It has a budget of its own, the
/// study's: a case spends at most its budget on the solve and as much again on the
/// re-solves. Memory is the solve's: the re-solves run one after another.
struct Resolves {
  size_t keys = 0;
  double fraction = 0;
  /// The sensitivity part's work as a share of the solve's.
  double share() const { return 2.0 * double(keys) * fraction; }
};

/// The complaints about `d` with frames of width x height px (`frames` per strip), and
/// about its sensitivity part (`resolves`) against a work budget of its own; empty when
/// within budget.
std::vector<OverBudget> over_budget(const Demand& d, int frames, int width, int height,
                                    const Resolves& resolves = {});

}  // namespace armstudy::cases
