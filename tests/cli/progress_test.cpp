// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Progress is real: time left only once there is something to extrapolate from, growing
// while a stage says nothing, and a line at least every period even without reports.
#include "cli/progress.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace armstudy::cli {
namespace {
using namespace std::chrono_literals;

TEST(Progress, TimeLeftIsExtrapolatedFromTheTimeElapsedNow) {
  // 3 % after a second: too early to say
  EXPECT_EQ(ProgressReporter::status_text(0.03, "sweep", 1.0, 0.0),
            "  3 % sweep, 0:01 elapsed, time left unknown");
  // 3 % after two minutes, the last report long ago: about an hour left, not "0:00"
  EXPECT_EQ(ProgressReporter::status_text(0.03, "sweep", 120.0, 115.0),
            "  3 % sweep, 2:00 elapsed, about 1:04:40 left (last report 1:55 ago)");
  EXPECT_EQ(ProgressReporter::status_text(0.5, "", 10.0, 0.0),
            " 50 %, 0:10 elapsed, about 0:10 left");
  // 99.6 % is not "100 %"
  EXPECT_EQ(ProgressReporter::status_text(0.996, "x", 100.0, 0.0).substr(0, 6), " 99 % ");
}

struct Capture {
  char* buf = nullptr;
  size_t len = 0;
  FILE* f = open_memstream(&buf, &len);
  std::string text() {
    std::fflush(f);
    return std::string(buf, len);
  }
  ~Capture() {
    std::fclose(f);
    std::free(buf);
  }
};

TEST(Progress, HeartbeatPrintsEveryPeriodWithoutReportsAndStopsWhenTheTaskEnds) {
  Capture out;
  auto now = ProgressReporter::Clock::time_point{} + 1000s;
  ProgressReporter p(out.f, false, 5s, [&] { return now; });
  {
    const studies::ProgressFn fn = p.task("case-a");
    fn(0.03, "sweep");  // the first report prints
    EXPECT_EQ(out.text(), "case-a:   3 % sweep, 0:00 elapsed, time left unknown\n");
    now += 2s;
    p.heartbeat();  // within the period: quiet
    EXPECT_EQ(out.text(), "case-a:   3 % sweep, 0:00 elapsed, time left unknown\n");
    now += 118s;  // a stage silent for two minutes: the heartbeat says so
    p.heartbeat();
    EXPECT_NE(out.text().find(
                  "case-a:   3 % sweep, 2:00 elapsed, about 1:04:40 left (last report 2:00 ago)\n"),
              std::string::npos)
        << out.text();
  }
  // two tasks in a log: each gets its line every period, however often the other reports
  {
    const studies::ProgressFn a = p.task("case-b");
    const studies::ProgressFn b = p.task("case-c");
    a(0.1, "one");
    b(0.1, "two");
    for (int i = 0; i < 6; ++i) {
      now += 1s;
      a(0.1 + 0.01 * i, "one");
      p.heartbeat();
    }
    const std::string t = out.text();
    EXPECT_NE(t.find("case-c:  10 % two, 0:05 elapsed"), std::string::npos) << t;
    EXPECT_NE(t.find("case-b:  14 % one, 0:05 elapsed"), std::string::npos) << t;
  }
  // the task's callback is gone: nothing more about it
  const std::string before = out.text();
  now += 60s;
  p.heartbeat();
  EXPECT_EQ(out.text(), before);
}

}  // namespace
}  // namespace armstudy::cli
