// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// `sensitivity:` lists: a repeated key is said once, and a long list is read in linear time.
#include "cases/sensitivity_spec.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cases/yaml_reader.hpp"

namespace armstudy::cases {
namespace {

struct SensitivityLoad {
  SensitivitySpec spec;
  std::vector<std::string> errors;
};

SensitivityLoad load_sensitivity(const std::string& yaml) {
  Diagnostics d("c.yaml");
  const YAML::Node n = YAML::Load(yaml);
  Map root(n, d, "");
  SensitivityLoad out;
  out.spec = read_sensitivity(root);
  for (const auto& e : d.errors()) out.errors.push_back(e.format());
  return out;
}

const char* kSensitivityCase =
    "time_optimal:\n"
    "  velocity_limit_rad_s: [3.0, 4.0]\n"
    "  torque_limit_Nm: [10.0, 4.0]\n";

TEST(SensitivitySpec, AKeyListedFourTimesIsOneMessageAtItsSecondEntry) {
  const SensitivityLoad l = load_sensitivity(std::string(kSensitivityCase) +
                                             "sensitivity:\n"
                                             "  - time_optimal.velocity_limit_rad_s\n"
                                             "  - time_optimal.torque_limit_Nm\n"
                                             "  - time_optimal.velocity_limit_rad_s\n"
                                             "  - time_optimal.velocity_limit_rad_s\n"
                                             "  - {key: time_optimal.velocity_limit_rad_s}\n"
                                             "  - time_optimal.torque_limit_Nm\n");
  ASSERT_EQ(l.errors.size(), 2u) << ::testing::PrintToString(l.errors);
  EXPECT_EQ(l.errors[0],
            "c.yaml:7:5: 'time_optimal.velocity_limit_rad_s' is listed 4 times in 'sensitivity'; "
            "expected each key once");
  EXPECT_EQ(l.errors[1],
            "c.yaml:10:5: 'time_optimal.torque_limit_Nm' is listed twice in 'sensitivity'; "
            "expected each key once");
}

// every pair of 150,000 entries was compared: 20,000 took 117 s, 150,000 hours. 4,000
// entries, repeats of two keys, are read here in linear time (0.2 s) with two messages,
// beside the one that says the list is longer than a run would re-solve
TEST(SensitivitySpec, ALongListOfRepeatsIsReadInLinearTimeWithOneMessagePerKey) {
  std::string yaml = std::string(kSensitivityCase) + "sensitivity:\n";
  for (int k = 0; k < 2000; ++k)
    yaml += "  - time_optimal.velocity_limit_rad_s\n  - time_optimal.torque_limit_Nm\n";
  const SensitivityLoad l = load_sensitivity(yaml);
  ASSERT_EQ(l.errors.size(), 3u) << ::testing::PrintToString(l.errors);
  EXPECT_NE(l.errors[0].find("has 4000 entries; expected at most 100"), std::string::npos)
      << l.errors[0];
  EXPECT_NE(l.errors[1].find("is listed 2000 times"), std::string::npos) << l.errors[1];
  EXPECT_NE(l.errors[2].find("is listed 2000 times"), std::string::npos) << l.errors[2];
}

// each key is two re-solves of the case: a list of 150,000 distinct keys (a long path's
// points, each a key) validated and then ran for days. 100 keys are the most a case lists.
TEST(SensitivitySpec, AListOfMoreThanAHundredKeysIsRefusedOnce) {
  std::string yaml = "time_optimal:\n  path:\n    points_m:\n";
  for (int k = 0; k < 101; ++k) yaml += "      - [0.3, " + std::to_string(0.1 + 0.001 * k) + "]\n";
  std::string hundred = yaml + "sensitivity:\n", more = hundred;
  for (int k = 0; k < 101; ++k) {
    const std::string entry = "  - time_optimal.path.points_m[" + std::to_string(k + 1) + "]\n";
    if (k < 100) hundred += entry;
    more += entry;
  }
  const SensitivityLoad ok = load_sensitivity(hundred);
  EXPECT_TRUE(ok.errors.empty()) << ::testing::PrintToString(ok.errors);
  EXPECT_EQ(ok.spec.items.size(), 100u);
  const SensitivityLoad l = load_sensitivity(more);
  ASSERT_EQ(l.errors.size(), 1u) << ::testing::PrintToString(l.errors);
  EXPECT_EQ(l.errors[0].substr(l.errors[0].find(": ") + 2),
            "'sensitivity' has 101 entries; expected at most 100 (each key is two re-solves of "
            "the case)");
}

// the documented form arm.links[2].length was refused with "'arm.links' is a mapping;
// expected a list" (reading the key wrote the second link over the list), and the same
// false error was added to the entries after it; a word where a number belongs is named
TEST(SensitivitySpec, AKeyIntoAListIsReadWithoutChangingTheFile) {
  const SensitivityLoad l = load_sensitivity(
      "arm:\n  links:\n    - {length: 0.5, mass: 0, inertia: rod}\n    - {length: 0.4, mass: 0}\n"
      "sensitivity:\n  - arm.links[2].length\n  - arm.links[1].length\n");
  EXPECT_TRUE(l.errors.empty()) << ::testing::PrintToString(l.errors);
  ASSERT_EQ(l.spec.items.size(), 2u);
  EXPECT_EQ(l.spec.items[0].nominal, std::vector<double>{0.4});
  EXPECT_EQ(l.spec.items[1].nominal, std::vector<double>{0.5});
  const SensitivityLoad w = load_sensitivity(
      "arm:\n  links:\n    - {length: 0.5, mass: 0, inertia: rod}\n"
      "sensitivity:\n  - arm.links[1].inertia\n");
  ASSERT_EQ(w.errors.size(), 1u);
  EXPECT_NE(w.errors[0].find("'arm.links[1].inertia' is 'rod' in the case file; expected a key "
                             "whose value is a number"),
            std::string::npos)
      << w.errors[0];
}

}  // namespace
}  // namespace armstudy::cases
