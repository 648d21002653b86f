#include "framework/core/config_node.h"

#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

ConfigNode Load(const std::string& text) { return ConfigNode::Parse(text, "s.yaml", ""); }

// Runs `body` and returns the ScenarioError it throws; fails the test if it does not throw one.
template <typename Body>
ScenarioError Catch(Body body) {
  try {
    body();
  } catch (const ScenarioError& e) {
    return e;
  }
  ADD_FAILURE() << "no ScenarioError thrown";
  return ScenarioError({}, "", "", "");
}

TEST(ConfigNodeTest, ReportsOneBasedLineAndColumn) {
  const ConfigNode root = Load("a: 1\nb:\n  c: 20 mm\n");
  const ConfigNode c = root.Child("b").Child("c");
  EXPECT_EQ(c.path(), "b.c");
  EXPECT_EQ(c.location().line, 3);
  EXPECT_EQ(c.location().column, 6);
  EXPECT_EQ(c.location().file, "s.yaml");
  EXPECT_EQ(root.location().line, 1);
  EXPECT_EQ(root.location().column, 1);
}

// A document that begins with a token no node can begin with: yaml-cpp 0.7's LoadAll returned an
// empty document at it forever without consuming it (the scenario fuzzer's find: `fitfeel
// validate` took 7 GB in 15 s). Refused where the token is, as any syntax error.
TEST(ConfigNodeTest, ATokenThatStartsNoNodeIsRefusedWhereItIs) {
  struct Case {
    std::string text;
    int line, column;
  };
  for (const Case& c : {Case{",", 1, 1}, Case{",,\n", 1, 1}, Case{"!,", 1, 2},
                        Case{"&a ,", 1, 4}, Case{"a: 1\n...\n,\n", 3, 1}}) {
    const ScenarioError e = Catch([&] { Load(c.text); });
    EXPECT_EQ(e.expected(), "valid YAML") << c.text;
    EXPECT_THAT(e.found(), HasSubstr("a token that starts no YAML node")) << c.text;
    EXPECT_EQ(e.where().line, c.line) << c.text;
    EXPECT_EQ(e.where().column, c.column) << c.text;
  }
  // A real second document is still that, at its root.
  const ScenarioError two = Catch([] { Load("a: 1\n---\nb: 2\n---\nc: 3\n"); });
  EXPECT_EQ(two.found(), "a second document");
  EXPECT_EQ(two.where().line, 3);
}

TEST(ConfigNodeTest, MissingKeyReportsParentLocationAndFullPath) {
  const ConfigNode root = Load("parts:\n  shaft:\n    role: inner\n    form: {}\n");
  const ScenarioError e = Catch([&] { root.Child("parts").Child("shaft").Child("size"); });
  EXPECT_EQ(e.key_path(), "parts.shaft.size");
  EXPECT_EQ(e.where().line, 3);  // the map `shaft` starts at its first key
  EXPECT_EQ(e.where().column, 5);
  EXPECT_EQ(e.expected(), "key 'size' (required)");
  EXPECT_EQ(e.found(), "only the keys role, form");
  EXPECT_EQ(std::string(e.what()),
            "s.yaml:3:5: parts.shaft.size: expected key 'size' (required), found only the keys "
            "role, form");
}

TEST(ConfigNodeTest, UnknownKeyListsTheAllowedOnes) {
  const ConfigNode root = Load("run:\n  rate: 1 kHz\n  duraton: 5 s\n");
  const ScenarioError e = Catch([&] {
    root.Child("run").ExpectOnlyKeys({"rate", "duration", "seed"});
  });
  EXPECT_EQ(e.key_path(), "run.duraton");
  EXPECT_EQ(e.where().line, 3);
  EXPECT_EQ(e.where().column, 3);
  EXPECT_EQ(e.expected(), "one of the keys rate, duration, seed");
  EXPECT_EQ(e.found(), "unknown key 'duraton'");
  EXPECT_NO_THROW(root.Child("run").ExpectOnlyKeys({"rate", "duraton"}));
}

TEST(ConfigNodeTest, RepeatedKeyIsRefused) {
  const ConfigNode root = Load("a: 1\nb: 2\na: 3\n");
  const ScenarioError e = Catch([&] { root.Keys(); });
  EXPECT_EQ(e.key_path(), "a");
  EXPECT_EQ(e.where().line, 3);
  EXPECT_EQ(e.found(), "'a' a second time");
}

TEST(ConfigNodeTest, KeysInFileOrder) {
  const ConfigNode root = Load("z: 1\na: 2\nm: 3\n");
  EXPECT_THAT(root.Keys(), ElementsAre("z", "a", "m"));
  EXPECT_TRUE(root.Has("a"));
  EXPECT_FALSE(root.Has("b"));
  EXPECT_FALSE(root.Find("b").has_value());
}

TEST(ConfigNodeTest, QuantityErrorsCarryDimensionAndWhatWasFound) {
  const ConfigNode root = Load("x: 20 mmm\ny: 20\nz: 2 kg\nw: {a: 1}\n");
  ScenarioError e = Catch([&] { root.Child("x").AsQuantity(Dimension::kLength); });
  EXPECT_EQ(e.key_path(), "x");
  EXPECT_EQ(e.where().line, 1);
  EXPECT_EQ(e.where().column, 4);
  EXPECT_EQ(e.expected(), "a length (nm, um, mm, cm, m)");
  EXPECT_EQ(e.found(), "'20 mmm' (unknown unit 'mmm')");
  e = Catch([&] { root.Quantity("y", Dimension::kLength); });
  EXPECT_EQ(e.found(), "'20' (no unit)");
  e = Catch([&] { root.Quantity("z", Dimension::kLength); });
  EXPECT_EQ(e.found(), "'2 kg' (kg is a unit of mass)");
  e = Catch([&] { root.Quantity("w", Dimension::kLength); });
  EXPECT_EQ(e.found(), "a map");
  EXPECT_EQ(e.key_path(), "w");
}

TEST(ConfigNodeTest, QuantityRangeIsChecked) {
  const ConfigNode root = Load("f: 1.6\ng: 0.15\nt: -2 um\nd: 0 s\n");
  EXPECT_EQ(root.QuantityIn("g", Dimension::kDimensionless, 0.0, 1.5), 0.15);
  ScenarioError e = Catch([&] { root.QuantityIn("f", Dimension::kDimensionless, 0.0, 1.5); });
  EXPECT_EQ(e.expected(), "a dimensionless number in [0, 1.5]");
  EXPECT_EQ(e.found(), "'1.6'");
  e = Catch([&] {
    root.Child("t").AsQuantityIn(Dimension::kLength, 0.0, std::numeric_limits<double>::infinity());
  });
  EXPECT_EQ(e.expected(), "a length >= 0 m");
  EXPECT_EQ(e.found(), "'-2 um'");
  e = Catch([&] { root.Child("d").AsQuantityIn(Dimension::kTime, 0.0, 3600.0, false); });
  EXPECT_EQ(e.expected(), "a time in (0 s, 3600 s]");
}

TEST(ConfigNodeTest, IntegersAreStrict) {
  const ConfigNode root = Load("a: 42\nb: 1.5\nc: -3\nd: 99999999999999999999999\ne: x\n");
  EXPECT_EQ(root.Child("a").AsInteger(0), 42);
  EXPECT_EQ(root.Child("c").AsInteger(), -3);
  EXPECT_EQ(Catch([&] { root.Child("b").AsInteger(0); }).found(), "'1.5'");
  const ScenarioError negative = Catch([&] { root.Child("c").AsInteger(0); });
  EXPECT_EQ(negative.expected(), "an integer >= 0");
  EXPECT_THAT(Catch([&] { root.Child("d").AsInteger(0); }).found(), HasSubstr("too large"));
  EXPECT_EQ(Catch([&] { root.Child("e").AsInteger(1, 10); }).expected(), "an integer in [1, 10]");
}

// Seeds take every 64-bit value (a fit study's pair seeds are SplitMix64 outputs, half of them
// past 2^63), and nothing else.
TEST(ConfigNodeTest, SeedsTakeTheWhole64BitRange) {
  const ConfigNode root = Load(
      "a: 18446744073709551615\nb: 18446744073709551616\nc: -1\nd: 1.5\ne: ''\nf: +7\n"
      "g: 9223372036854775808\n");
  EXPECT_EQ(root.Child("a").AsSeed(), 18446744073709551615ull);
  EXPECT_EQ(root.Child("f").AsSeed(), 7u);
  EXPECT_EQ(root.Child("g").AsSeed(), 9223372036854775808ull);
  EXPECT_THAT(Catch([&] { root.Child("b").AsSeed(); }).found(), HasSubstr("too large"));
  for (const char* key : {"b", "c", "d", "e"}) {
    EXPECT_EQ(Catch([&] { root.Child(key).AsSeed(); }).expected(), kSeedRange) << key;
  }
  EXPECT_FALSE(ParseSeed("-0").has_value());
  EXPECT_FALSE(ParseSeed("0x10").has_value());
  EXPECT_FALSE(ParseSeed(" 5").has_value());
}

TEST(ConfigNodeTest, ChoicesBoolsStringsAndLists) {
  const ConfigNode root =
      Load("clock: virtual\nbad: sometimes\nflag: true\nlist: [a, b]\nmap: {k: v}\nnull_key:\n");
  EXPECT_EQ(root.Child("clock").AsOneOf({"virtual", "realtime"}), "virtual");
  const ScenarioError e = Catch([&] { root.Child("bad").AsOneOf({"virtual", "realtime"}); });
  EXPECT_EQ(e.expected(), "one of virtual, realtime");
  EXPECT_EQ(e.found(), "'sometimes'");
  EXPECT_TRUE(root.Child("flag").AsBool());
  EXPECT_EQ(Catch([&] { root.Child("clock").AsBool(); }).expected(), "true or false");
  const auto items = root.Child("list").Items();
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[1].path(), "list[1]");
  EXPECT_EQ(items[1].AsString(), "b");
  EXPECT_EQ(Catch([&] { root.Child("map").Items(); }).found(), "a map");
  EXPECT_EQ(Catch([&] { root.Child("list").AsString(); }).found(), "a list");
  EXPECT_EQ(Catch([&] { root.Child("null_key").Keys(); }).found(), "nothing");
  EXPECT_EQ(root.StringOr("missing", "dflt"), "dflt");
  EXPECT_EQ(root.QuantityOr("missing", Dimension::kLength, 3.0), 3.0);
}

TEST(ConfigNodeTest, FailUsesThisNodesLocationAndPath) {
  const ConfigNode root = Load("model:\n  law: magic\n");
  const ScenarioError e =
      Catch([&] { root.Child("model").Child("law").Fail("one of gps, ve1", "'magic'"); });
  EXPECT_EQ(std::string(e.what()),
            "s.yaml:2:8: model.law: expected one of gps, ve1, found 'magic'");
}

}  // namespace
}  // namespace fitfeel
