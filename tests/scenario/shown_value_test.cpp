// A huge value echoed in a refusal is cut to its first 80 characters and its length, wherever it
// is quoted: a value in the file, a --set value, a --set key path, a --set word without '='.
#include "scenario/shown_value.hpp"

#include <gtest/gtest.h>

#include <string>

#include "scenario/scenario_loader.hpp"
#include "scenario_test_support.hpp"

namespace swarmnet::test {
namespace {

const std::string kHuge(102400, 'a');
const std::string kShown = std::string(80, 'a') + "... (102400 bytes)";

TEST(ShownValue, ShortTextIsShownWholeLongTextCutWithItsLength) {
  EXPECT_EQ(shown_value("robots"), "robots");
  EXPECT_EQ(shown_value(std::string(80, 'b')), std::string(80, 'b'));
  EXPECT_EQ(shown_value(std::string(81, 'b')), std::string(80, 'b') + "... (81 bytes)");
  EXPECT_EQ(shown_value(kHuge), kShown);
  // A path is cut only beyond the longest the system accepts.
  const std::string path = "/" + std::string(200, 'p');
  EXPECT_EQ(shown_value(path, kShownPathChars), path);
  EXPECT_EQ(shown_value(kHuge, kShownPathChars), std::string(4096, 'a') + "... (102400 bytes)");
  // Not in the middle of a character: "é" is 2 bytes, the 80th and 81st.
  const std::string accented = std::string(79, 'c') + "\xC3\xA9" + std::string(10, 'c');
  EXPECT_EQ(shown_value(accented), std::string(79, 'c') + "... (91 bytes)");
}

// Every problem line of a refusal is short, and quotes the value cut.
void expect_short_refusal(const ScenarioError& error) {
  ASSERT_FALSE(error.problems().empty());
  for (const std::string& line : error.problems()) {
    EXPECT_LT(line.size(), 400U) << line.substr(0, 400);
  }
  EXPECT_TRUE(Contains(error.what(), kShown));
}

TEST(ShownValue, AHugeValueInTheFileIsEchoedCut) {
  TempDir dir("shown-value-file");
  std::string text = read_text(kScenarioDir / "good" / "minimal.yaml");
  text += "\nstep_s: " + kHuge + "\n";
  const auto file = dir.write("huge.yaml", text);
  expect_short_refusal(load_error(file));
}

ScenarioOverrides setting(const std::string& word) {
  ScenarioOverrides overrides;
  overrides.set = {word};
  return overrides;
}

TEST(ShownValue, HugeSetValuesAndKeysAreEchoedCut) {
  const auto file = kScenarioDir / "good" / "minimal.yaml";
  expect_short_refusal(load_error(file, setting("robots.count=" + kHuge)));
  expect_short_refusal(load_error(file, setting(kHuge + "=1")));
  expect_short_refusal(load_error(file, setting(kHuge)));
  expect_short_refusal(load_error(file, setting("plugin_paths=[\"" + kHuge + "\"]")));
}

}  // namespace
}  // namespace swarmnet::test
