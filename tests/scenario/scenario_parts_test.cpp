// The scenario module's small parts: free area, name suggestions, scalar rules, and the key
// reference against docs/scenario.md.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "plugin/plugin_catalog.hpp"
#include "scenario/free_area.hpp"
#include "scenario/nearest_name.hpp"
#include "scenario/scalar_rule.hpp"
#include "scenario/scenario_loader.hpp"
#include "scenario/yaml_hazard.hpp"
#include "scenario_test_support.hpp"

namespace swarmnet {
namespace {

TEST(ScenarioFreeArea, CountsOverlapsOnceAndClipsToTheRegion) {
  const Rect region{0, 0, 10, 10};
  EXPECT_DOUBLE_EQ(free_area(region, {}), 100.0);
  EXPECT_DOUBLE_EQ(free_area(region, {{0, 0, 5, 5}}), 75.0);
  EXPECT_DOUBLE_EQ(free_area(region, {{0, 0, 5, 5}, {2, 2, 7, 7}}), 100.0 - 25 - 25 + 9);
  EXPECT_DOUBLE_EQ(free_area(region, {{0, 0, 5, 5}, {0, 0, 5, 5}}), 75.0);
  EXPECT_DOUBLE_EQ(free_area(region, {{-5, -5, 2, 2}}), 96.0) << "clipped to the region";
  EXPECT_DOUBLE_EQ(free_area(region, {{20, 20, 30, 30}}), 100.0) << "outside the region";
  EXPECT_DOUBLE_EQ(free_area(region, {{-1, -1, 11, 11}}), 0.0);
  EXPECT_DOUBLE_EQ(free_area(Rect{2, 2, 4, 6}, {{3, 0, 10, 3}}), 8.0 - 1.0);
}

TEST(ScenarioNearestName, SuggestsOnlyLikelyTypos) {
  const std::vector<std::string> keys{"width_m", "height_m", "obstacles"};
  EXPECT_EQ(nearest_name("widht_m", keys), "width_m");  // a swap is one edit
  EXPECT_EQ(nearest_name("Width_m", keys), "width_m");  // case is ignored
  EXPECT_EQ(nearest_name("height", keys), "height_m");
  EXPECT_EQ(nearest_name("obstacle", keys), "obstacles");
  EXPECT_EQ(nearest_name("colour", keys), std::nullopt);
  EXPECT_EQ(nearest_name("x", keys), std::nullopt);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
}

TEST(ScenarioNearestName, NoSuggestionForAOneLetterNameOrAFarOneAndAPrefixCompletes) {
  // One edit turns any one-letter name into another: "D" is no typo of "k".
  EXPECT_EQ(nearest_name("D", {"k", "n_max", "step_s"}), std::nullopt);
  EXPECT_EQ(nearest_name("kk", {"k"}), std::nullopt);  // as many edits as "k" has letters
  // Long words allow length / 3 edits, short ones one.
  EXPECT_EQ(nearest_name("tx_pwr_dbm", {"tx_power_dbm"}), "tx_power_dbm");
  EXPECT_EQ(nearest_name("rnage", {"range_m"}), std::nullopt);
  // A name cut short completes when exactly one declared name starts so.
  EXPECT_EQ(nearest_name("rad", {"radius_m", "range_m"}), "radius_m");
  EXPECT_EQ(nearest_name("RAD", {"radius_m"}), "radius_m");
  EXPECT_EQ(nearest_name("ra", {"radius_m"}), std::nullopt);
  EXPECT_EQ(nearest_name("ra_", {"ra_max", "ra_min"}), std::nullopt);
}

std::string problem_for(const ScalarRule& rule, const std::string& yaml) {
  std::string problem;
  const auto value = check_scalar(rule, YAML::Load(yaml), &problem);
  return value ? "ok: " + format_param_value(*value) : problem;
}

TEST(ScenarioScalarRule, ReadsYamlScalarsStrictly) {
  ScalarRule real;  // any real
  EXPECT_EQ(problem_for(real, "3"), "ok: 3");
  EXPECT_EQ(problem_for(real, "-2.5e3"), "ok: -2500");
  EXPECT_EQ(problem_for(real, "'3'"), "\"3\" (quoted) is text, not a number (remove the quotes)");
  EXPECT_EQ(problem_for(real, ".inf"), ".inf is not a finite number");
  EXPECT_EQ(problem_for(real, "nan"), "'nan' is not a number");
  EXPECT_EQ(problem_for(real, "[1, 2]"), "a list is not a number");
  EXPECT_EQ(problem_for(real, "~"), "has no value");

  ScalarRule integer;
  integer.type = ScalarType::integer;
  EXPECT_EQ(problem_for(integer, "-12"), "ok: -12");
  EXPECT_EQ(problem_for(integer, "2.0"), "2.0 is not an integer");
  EXPECT_EQ(problem_for(integer, "1e3"), "1e3 is not an integer");
  EXPECT_EQ(problem_for(integer, "99999999999999999999"), "99999999999999999999 is out of range");

  ScalarRule boolean;
  boolean.type = ScalarType::boolean;
  EXPECT_EQ(problem_for(boolean, "false"), "ok: false");
  EXPECT_EQ(problem_for(boolean, "on"), "'on' is not a boolean");
  EXPECT_EQ(problem_for(boolean, "True"), "'True' is not a boolean");
  EXPECT_EQ(problem_for(boolean, "\"true\""), "\"true\" (quoted) is not a boolean");

  ScalarRule text;
  text.type = ScalarType::text;
  EXPECT_EQ(problem_for(text, "12"), "ok: 12");
  EXPECT_EQ(problem_for(text, "{a: 1}"), "a mapping is not a single value");
}

TEST(ScenarioScalarRule, DescribesRanges) {
  ScalarRule rule;
  rule.min = 0;
  rule.min_open = true;
  rule.unit = "m";
  EXPECT_EQ(rule.describe(), "real > 0 (m)");
  rule.max = 1;
  EXPECT_EQ(rule.describe(), "real > 0 and <= 1 (m)");
  rule.min_open = false;
  EXPECT_EQ(rule.describe(), "real 0..1 (m)");
  EXPECT_EQ(rule_for(integer_param("n", 1, "", "", 1, 255)).describe(), "integer 1..255");
  EXPECT_EQ(rule_for(integer_param("n", 1, "", "")).describe(), "integer");
  EXPECT_EQ(rule_for(text_param("t", "a", "", {"a", "b"})).describe(), "one of a, b");
}

// yaml-cpp stops at a NUL byte and then loops on a ',' after it (found by fuzz_peer_hello); YAML
// allows no NUL, so one is refused where it stands.
TEST(YamlHazard, ANulByteIsRefusedWhereItStands) {
  using namespace std::string_literals;
  const auto hazard = find_yaml_hazard("a: 1\nb: \0,x"s);
  ASSERT_TRUE(hazard.has_value());
  EXPECT_EQ(hazard->line, 1);
  EXPECT_EQ(hazard->column, 3);
  EXPECT_STREQ(hazard->problem, kYamlNulProblem);
  PluginLoader loader;
  try {
    (void)load_scenario_text("\0,\0` \0a[w"s, "fuzz.yaml", loader);
    FAIL() << "a text with NUL bytes was read";
  } catch (const ScenarioError& error) {
    EXPECT_NE(
        std::string(error.what()).find("fuzz.yaml:1:1: YAML syntax error: the text holds a NUL"),
        std::string::npos)
        << error.what();
  }
  EXPECT_STREQ(find_yaml_hazard(",a: 1")->problem, kYamlHazardProblem);
}

TEST(ScenarioReference, DocsDescribeEveryKeyWithItsDefault) {
  const std::string docs =
      test::read_text(std::filesystem::path(SWARMNET_SOURCE_DIR) / "docs" / "scenario.md");
  ASSERT_FALSE(docs.empty()) << "docs/scenario.md is missing";
  const auto keys = scenario_key_reference();
  EXPECT_GT(keys.size(), 40u);
  for (const auto& key : keys) {
    // Every key has a table row: | `path` | form | default | ...
    const std::string row = "| `" + key.path + "` |";
    const std::size_t at = docs.find(row);
    ASSERT_NE(at, std::string::npos) << "docs/scenario.md has no row for " << key.path;
    const std::string line = docs.substr(at, docs.find('\n', at) - at);
    const std::string fallback = key.required ? "required" : key.fallback;
    EXPECT_NE(line.find(fallback), std::string::npos)
        << key.path << ": the row should show " << fallback << "\n  " << line;
  }
}

}  // namespace
}  // namespace swarmnet

namespace swarmnet {
namespace {

// yaml-cpp 0.7 loops forever on these (found by fuzzing); they are refused before it parses them,
// and nothing valid is refused with them.
TEST(YamlHazard, ACommaOpeningTheFirstNodeOrInItsTagOrAnchorIsFound) {
  for (const char* text : {",a: 1",
                           "--- ,a",
                           "# c\n  ,x",
                           " ! ,a",
                           "! ,a",
                           " !t ,a",
                           " &x ,a",
                           " !,a",
                           "!\n ,a",
                           "x: 1\n---\n ! ,a",
                           "x: ! ,a",
                           "- ! ,a",
                           "x: ,a",
                           "a:\n  - b\n  - ! ,c",
                           "x: [1]\n ! ,a",
                           "x: 'q'\n ,a",
                           "x: |\n  t\n,a: 1",
                           "  \"   ,a\n b\n  \"   ,c",
                           "x: \"a\" ,b",
                           "x: [1] ,b",
                           "x: *a ,b",
                           "x: *a,b",
                           "x: | ,a"}) {
    EXPECT_TRUE(find_yaml_hazard(text).has_value()) << text;
  }
  const auto at = find_yaml_hazard("# comment\n !    ,ar\n");
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(at->line, 1);
  EXPECT_EQ(at->column, 6);  // the comma
  for (const char* text :
       {"a: 1", "name: a,b", "x: [1, 2]", "! a, b", "!!str a", "&a x: 1", "# ,\na: 1",
        "%YAML 1.2\n---\na: 1", "x: [1\n  , 2]", "x: {a: 1,\n  b: 2}", "x: \"a,\n  ,b\"",
        "notes: |\n  , text\n  ,more\ny: 1", "'a,b': 1", "x: 'don''t, ok'", "x: [a, [b, c]]",
        "- [1, 2]\n- {a: [3,4]}", "x: \"q\\\", ,\"", "x: a # ,b"}) {
    EXPECT_FALSE(find_yaml_hazard(text).has_value()) << text;
  }
}

}  // namespace
}  // namespace swarmnet
