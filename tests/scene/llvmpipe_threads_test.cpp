// llvmpipe's rasteriser threads per run: one per case's context when the jobs fill the
// cores; the user's LP_NUM_THREADS always wins.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "scene/osmesa_context.hpp"

namespace armstudy::scene {
namespace {

struct KeepEnv {
  std::string saved;
  bool had;
  KeepEnv() : had(std::getenv("LP_NUM_THREADS") != nullptr) {
    if (had) saved = std::getenv("LP_NUM_THREADS");
  }
  ~KeepEnv() {
    if (had) ::setenv("LP_NUM_THREADS", saved.c_str(), 1);
    else ::unsetenv("LP_NUM_THREADS");
  }
};

TEST(LlvmpipeThreads, JobsThatFillTheCoresRasteriseOnOneThreadEach) {
  KeepEnv keep;
  ::unsetenv("LP_NUM_THREADS");
  EXPECT_EQ(choose_llvmpipe_threads(1024), "1");
  EXPECT_STREQ(std::getenv("LP_NUM_THREADS"), "1");
}

TEST(LlvmpipeThreads, OneJobLeavesItToLlvmpipeUnlessOneCore) {
  KeepEnv keep;
  ::unsetenv("LP_NUM_THREADS");
  const std::string v = choose_llvmpipe_threads(1);
  EXPECT_TRUE(v.empty() || v == "1") << v;  // "1" only on a one-core machine
}

TEST(LlvmpipeThreads, TheUsersSettingWins) {
  KeepEnv keep;
  ::setenv("LP_NUM_THREADS", "3", 1);
  EXPECT_EQ(choose_llvmpipe_threads(1024), "3");
  EXPECT_STREQ(std::getenv("LP_NUM_THREADS"), "3");
}

}  // namespace
}  // namespace armstudy::scene
