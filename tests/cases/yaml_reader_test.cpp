// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/yaml_reader.hpp"

#include <gtest/gtest.h>

#include "cases/arm_loader.hpp"

namespace armstudy::cases {
namespace {

TEST(YamlReader, MarksAreOneBasedLineAndColumn) {
  Diagnostics d("f.yaml");
  const YAML::Node n = YAML::Load("a: 1\nb:\n  c: -2\n");
  Map root(n, d, "");
  auto b = root.map("b");
  ASSERT_TRUE(b);
  b->number("c", NumberRule::positive("m"));
  root.number("a", NumberRule::positive("m"));
  root.finish();
  ASSERT_EQ(d.errors().size(), 1u);
  EXPECT_EQ(d.errors()[0].format(), "f.yaml:3:6: 'b.c' is -2; should be > 0 m");
}

TEST(YamlReader, DuplicateAndUnknownKeysAreReportedWithSuggestion) {
  Diagnostics d("f.yaml");
  const YAML::Node n = YAML::Load("mass: 1\nmass: 2\nlenght: 3\n");
  Map root(n, d, "");
  EXPECT_EQ(*root.number("mass", NumberRule::positive("kg")), 1.0);  // yaml-cpp keeps the first
  root.number("length", NumberRule::positive("m"));
  root.finish();
  ASSERT_EQ(d.errors().size(), 2u);
  EXPECT_EQ(d.errors()[0].format(), "f.yaml:2:1: duplicate key 'mass'; expected each key once");
  EXPECT_EQ(d.errors()[1].format(), "f.yaml:3:1: unknown key 'lenght'; did you mean 'length'?");
}

TEST(YamlReader, ClosestSuggestsOnlyNearWords) {
  EXPECT_EQ(closest("placemnet", {"placement", "pendulum"}).value_or(""), "placement");
  EXPECT_FALSE(closest("zzzzzz", {"placement", "pendulum"}).has_value());
}

TEST(ArmLoader, RodShorthandPayloadAndDefaultsBuildTheChain) {
  Diagnostics d("f.yaml");
  const YAML::Node n = YAML::Load(
      "arm:\n  links:\n    - {length: 0.4, mass: 4}\n    - {length: 0.2, mass: 2, inertia: 0.01, "
      "joint: passive}\n"
      "  payload: 1.5\ngravity: 9.81\n");
  Map root(n, d, "");
  const core::PlanarChain c = load_arm(root, core::PlanarChain{}, 2);
  root.finish();
  ASSERT_TRUE(d.empty()) << d.errors()[0].format();
  ASSERT_EQ(c.num_links(), 2);
  EXPECT_DOUBLE_EQ(c.links[0].inertia, 4 * 0.16 / 12);
  EXPECT_DOUBLE_EQ(c.links[0].com, 0.2);
  EXPECT_DOUBLE_EQ(c.links[1].inertia, 0.01);
  EXPECT_FALSE(c.links[1].active);
  EXPECT_DOUBLE_EQ(c.gravity, 9.81);
  EXPECT_DOUBLE_EQ(payload_mass(c), 1.5);
}

TEST(ArmLoader, MasslessLinkNeedsAPointMass) {
  Diagnostics d("f.yaml");
  const YAML::Node ok = YAML::Load(
      "arm:\n  links:\n    - {length: 0.4, mass: 0}\n    - {length: 0.2, mass: 0}\n"
      "  point_masses: [{link: 1, at: 0.4, mass: 1}]\n  payload: 1\n");
  Map root(ok, d, "");
  const core::PlanarChain c = load_arm(root, core::PlanarChain{}, 2);
  root.finish();
  EXPECT_TRUE(d.empty());
  EXPECT_DOUBLE_EQ(c.total_mass(), 2.0);
}

}  // namespace
}  // namespace armstudy::cases

namespace armstudy::cases {
namespace {

// a file saved with old Mac line breaks (CR alone) was read as one comment line: "the file
// is empty"; its keys are read, and an error is placed on its own line
TEST(YamlReader, CrOnlyLineBreaksAreLineBreaks) {
  Diagnostics d("f.yaml");
  const auto root = parse_text("# a comment\ra: 1\rb: -2\r", d);
  ASSERT_TRUE(root) << (d.empty() ? "" : d.errors()[0].format());
  Map m(*root, d, "");
  EXPECT_EQ(m.number("a", NumberRule::positive("")).value_or(0), 1.0);
  EXPECT_FALSE(m.number("b", NumberRule::positive("m")));
  ASSERT_EQ(d.errors().size(), 1u);
  EXPECT_EQ(d.errors()[0].format(), "f.yaml:3:4: 'b' is -2; should be > 0 m");
}

// yaml-cpp converts "1.0" and !!str 0.5 to numbers: text where a number belongs is refused
// with the key and the place; !!float and !!int stay numbers
TEST(YamlReader, QuotedOrStrTaggedNumbersAreRefusedNamingTheKey) {
  Diagnostics d("f.yaml");
  const YAML::Node n =
      YAML::Load("a: \"1.0\"\nb: '2'\nc: !!str 0.5\nd: !!float 0.25\ne: !!int 3\nf: 4\n");
  Map m(n, d, "");
  EXPECT_FALSE(m.number("a", NumberRule::any("")));
  EXPECT_FALSE(m.number("b", NumberRule::any("")));
  EXPECT_FALSE(m.integer("c", 0, 10));
  EXPECT_EQ(m.number("d", NumberRule::any("")).value_or(0), 0.25);
  EXPECT_EQ(m.integer("e", 0, 10).value_or(0), 3);
  EXPECT_EQ(m.number("f", NumberRule::any("")).value_or(0), 4.0);
  ASSERT_EQ(d.errors().size(), 3u);
  EXPECT_EQ(d.errors()[0].format(),
            "f.yaml:1:4: 'a' is the quoted text '1.0'; expected a number (written without quotes)");
  EXPECT_EQ(d.errors()[1].format(),
            "f.yaml:2:4: 'b' is the quoted text '2'; expected a number (written without quotes)");
  EXPECT_EQ(d.errors()[2].format(),
            "f.yaml:3:4: 'c' is '0.5' tagged !!str; expected a number (untagged, or tagged "
            "!!float or !!int)");
}

// a zero-width space or a byte order mark inside a name printed as nothing: two different
// names looked the same in a message
TEST(YamlSource, BriefEscapesCharactersThatPrintAsNothing) {
  EXPECT_EQ(brief("arm\xE2\x80\x8Bone"), "arm\\u200bone");
  EXPECT_EQ(brief("\xEF\xBB\xBFname"), "\\ufeffname");
  EXPECT_EQ(brief("a\xE2\x80\xAE"
                  "b"),
            "a\\u202eb");                                        // right-to-left override
  EXPECT_EQ(brief("gr\xC3\xBC\xC3\x9F"), "gr\xC3\xBC\xC3\x9F");  // visible text stays
}

}  // namespace
}  // namespace armstudy::cases
