// The corpus of refused scenarios (tests/scenario/bad/): each is refused with the problem located
// at the right place, naming the right key, saying what is wrong, and nothing else reported.
#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "scenario_test_support.hpp"

namespace swarmnet {
namespace {

using test::Contains;

struct BadCase {
  std::string file;              // in tests/scenario/bad/ (good/ for --set cases)
  std::vector<std::string> set;  // --set overrides
  std::string where;         // "LINE:COLUMN" in the file, or "--set KEY.PATH", or "" (file only)
  std::string key;           // the key path named
  std::string what;          // a fragment of the message (what is wrong; expected FORM)
  std::size_t problems = 1;  // how many problems the file has in all
};

void PrintTo(const BadCase& c, std::ostream* out) { *out << c.file << " " << c.where; }

std::filesystem::path path_of(const BadCase& c) {
  return test::kScenarioDir / (c.set.empty() ? "bad" : "good") / c.file;
}

// clang-format off
const std::vector<BadCase> kBadCases = {
  // Syntax and shape.
  {"syntax_error.yaml", {}, "5:7", "", "YAML syntax error: end of sequence flow not found"},
  // yaml-cpp 0.7 looped forever on it (found by fuzzing): refused before it is parsed.
  {"leading_comma.yaml", {}, "2:5", "", "YAML syntax error: ',' cannot begin a value outside [ ] or { }, nor stand in a tag or an anchor"},
  {"tagged_leading_comma.yaml", {}, "2:7", "", "YAML syntax error: ',' cannot begin a value outside [ ] or { }, nor stand in a tag or an anchor"},
  {"not_a_mapping.yaml", {}, "2:1", "(top level)", "the file is not a mapping of keys; expected a mapping of scenario keys"},
  {"two_documents.yaml", {}, "17:1", "(top level)", "the file holds 2 YAML documents; expected one document"},
  // Keys.
  {"unknown_top_level_key.yaml", {}, "16:1", "colour", "unknown key; expected one of name, seed, duration_s, step_s, sync, plugin_paths, arena, robots, world, physics, network, output"},
  {"unknown_nested_key.yaml", {}, "7:3", "arena.heigth_m", "unknown key (did you mean 'height_m'?); expected one of width_m, height_m, obstacles, objects"},
  {"duplicate_key.yaml", {}, "7:3", "arena.width_m", "is given twice (first at line 5:3); expected each key once"},
  {"missing_required_key.yaml", {}, "2:1", "duration_s", "missing required key; expected real > 0 (s)"},
  {"missing_nested_key.yaml", {}, "5:3", "arena.height_m", "missing required key; expected real > 0 (m)"},
  {"missing_routing_plugin.yaml", {}, "15:5", "network.routing.plugin", "missing required key; expected the name of a routing plugin"},
  // Types.
  {"wrong_type_text.yaml", {}, "5:12", "arena.width_m", "'wide' is not a number; expected real > 0 (m)"},
  {"wrong_type_quoted.yaml", {}, "8:10", "robots.count", "\"10\" (quoted) is text, not an integer (remove the quotes); expected integer 1..100000"},
  {"wrong_type_real_for_integer.yaml", {}, "8:10", "robots.count", "2.5 is not an integer; expected integer 1..100000"},
  {"wrong_type_boolean.yaml", {}, "17:17", "output.packet_trace", "'yes' is not a boolean; expected true or false"},
  {"wrong_type_mapping.yaml", {}, "13:5", "network.propagation", "a mapping is not a list; expected a non-empty list of {plugin: NAME, params: {...}} naming propagation plugins"},
  {"bad_name.yaml", {}, "2:7", "name", "'my/scenario' is not a valid name; expected a name of letters, digits, '_', '-' and '.'"},
  // Ranges and choices.
  {"out_of_range.yaml", {}, "10:11", "robots.proximity.rays", "400 is out of range; expected integer 0..360"},
  {"negative_step.yaml", {}, "4:9", "step_s", "-0.1 is out of range; expected real >= 1e-09 (s)"},
  {"empty_controller_list.yaml", {}, "9:16", "robots.controllers", "is an empty list; expected a non-empty list of {plugin: NAME, params: {...}} naming controller plugins"},
  {"bad_choice.yaml", {}, "4:7", "sync", "'strickt' is not a valid choice (did you mean 'strict'?); expected one of strict, pipelined"},
  // Plugins.
  {"missing_plugin.yaml", {}, "15:13", "network.routing.plugin", "plugin 'no_such_routing' not found; searched: " + (test::kFixtures / "swarmnet_no_such_routing.so").string() + ": no such file; "},
  {"wrong_kind_plugin.yaml", {}, "10:15", "robots.controllers.0.plugin", "is a routing plugin; a controller plugin is expected here; expected a controller plugin: "},
  {"broken_plugin.yaml", {}, "15:13", "network.routing.plugin", "plugin 'test_no_entry': " + (test::kFixtures / "swarmnet_test_no_entry.so").string() + " is not a SwarmNet plugin"},
  {"missing_plugin_path.yaml", {}, "5:5", "plugin_paths.0", "'no/such/directory' (" + (test::kScenarioDir / "bad/no/such/directory").string() + ") is not a directory; expected an existing directory"},
  {"undeclared_plugin_param.yaml", {}, "12:9", "robots.controllers.0.params.sped_mps", "not a parameter of plugin 'test_controller' (did you mean 'speed_mps'?); expected one of speed_mps, rate_hz, count, enabled, mode, label (see `swarmnet plugins test_controller`)"},
  {"cut_short_plugin_param.yaml", {}, "12:9", "robots.controllers.0.params.rat", "not a parameter of plugin 'test_controller' (did you mean 'rate_hz'?); expected one of speed_mps"},
  {"one_letter_plugin_param.yaml", {}, "12:9", "robots.controllers.0.params.D", "not a parameter of plugin 'test_controller'; expected one of speed_mps, rate_hz, count, enabled, mode, label"},
  {"plugin_param_out_of_range.yaml", {}, "12:20", "robots.controllers.0.params.speed_mps", "50 is out of range; expected real 0..10 (m/s)"},
  {"plugin_param_wrong_type.yaml", {}, "17:12", "network.routing.params.ttl", "2.5 is not an integer; expected integer 1..255"},
  {"plugin_param_bad_choice.yaml", {}, "12:15", "robots.controllers.0.params.mode", "'randm' is not a valid choice (did you mean 'random'?); expected one of random, straight"},
  // Keys that must agree.
  {"obstacle_outside_arena.yaml", {}, "9:7", "arena.obstacles.1", "[90, 110] x [10, 20] reaches outside the arena [0, 100] x [0, 50]; expected an obstacle inside the arena"},
  {"obstacle_inverted.yaml", {}, "8:7", "arena.obstacles.0", "[30, 20] x [10, 20] is empty; expected x_min_m < x_max_m and y_min_m < y_max_m"},
  {"obstacle_missing_edge.yaml", {}, "8:7", "arena.obstacles.0.y_max_m", "missing required key; expected real (m)"},
  {"object_outside_arena.yaml", {}, "9:7", "arena.objects.1", "reaching outside the arena [0, 100] x [0, 50]; expected an object inside the arena"},
  {"object_box_without_size.yaml", {}, "8:7", "arena.objects.0", "a box of 0 x 0 m has no area; expected a box with size_x_m > 0 and size_y_m > 0"},
  {"object_bad_shape.yaml", {}, "8:15", "arena.objects.0.shape", "'sphere' is not a valid choice"},
  {"minimal.yaml", {"arena.objects=[{shape: cylinder, x_m: 5, y_m: 5}]"}, "--set arena.objects", "arena.objects.0", "a cylinder of radius 0 m; expected a cylinder with radius_m > 0"},
  {"minimal.yaml", {"arena.objects=[{shape: box, x_m: 5, size_x_m: 1, size_y_m: 1}]"}, "--set arena.objects", "arena.objects.0.y_m", "missing required key; expected real (m)"},
  {"placement_outside_arena.yaml", {}, "10:13", "robots.placement.region", "[0, 10] x [-5, 10] reaches outside the arena [0, 100] x [0, 50]; expected a region inside the arena"},
  {"duration_not_multiple_of_step.yaml", {}, "3:13", "duration_s", "1.05 s is not a whole number of steps of 0.1 s; expected a positive multiple of step_s, such as 1 or 1.1"},
  {"duration_shorter_than_step.yaml", {}, "3:13", "duration_s", "0.01 s is shorter than one step of 0.1 s; expected a positive multiple of step_s"},
  {"too_many_robots.yaml", {}, "8:10", "robots.count", "1000 robots of radius 0.085 m cover 22.7 m^2, more than half of the 6 m^2 free area of the placement region; expected at most 132 robots"},
  {"robots_in_obstacles.yaml", {}, "10:10", "robots.count", "40 robots of radius 0.085 m cover 0.9079 m^2, more than half of the 1 m^2 free area"},
  {"robot_larger_than_region.yaml", {}, "9:13", "robots.radius_m", "a robot of radius 3 m does not fit in the placement region [0, 5] x [0, 50]"},
  // The range-and-bearing device's keys.
  {"minimal.yaml", {"robots.range_and_bearing.range_m=0"}, "--set robots.range_and_bearing.range_m", "robots.range_and_bearing.range_m", "0 is out of range; expected real > 0 (m)"},
  {"minimal.yaml", {"robots.range_and_bearing.range_noise_sd_m=-0.1"}, "--set robots.range_and_bearing.range_noise_sd_m", "robots.range_and_bearing.range_noise_sd_m", "-0.1 is out of range; expected real >= 0 (m)"},
  {"minimal.yaml", {"robots.range_and_bearing.bearing_noise_sd_rad=-1"}, "--set robots.range_and_bearing.bearing_noise_sd_rad", "robots.range_and_bearing.bearing_noise_sd_rad", "-1 is out of range; expected real >= 0 (rad)"},
  {"minimal.yaml", {"robots.range_and_bearing.loss_probability=1.5"}, "--set robots.range_and_bearing.loss_probability", "robots.range_and_bearing.loss_probability", "1.5 is out of range; expected real 0..1"},
  {"minimal.yaml", {"robots.range_and_bearing.loss_probability=-0.5"}, "--set robots.range_and_bearing.loss_probability", "robots.range_and_bearing.loss_probability", "-0.5 is out of range; expected real 0..1"},
  {"minimal.yaml", {"robots.range_and_bearing.data_bytes=257"}, "--set robots.range_and_bearing.data_bytes", "robots.range_and_bearing.data_bytes", "257 is out of range; expected integer 0..256"},
  {"minimal.yaml", {"robots.range_and_bearing.enabled=maybe"}, "--set robots.range_and_bearing.enabled", "robots.range_and_bearing.enabled", "'maybe' is not a boolean; expected true or false"},
  {"minimal.yaml", {"robots.range_and_bearing.rnage_m=2"}, "--set robots.range_and_bearing.rnage_m", "robots.range_and_bearing.rnage_m", "unknown key (did you mean 'range_m'?)"},
  // Overrides.
  {"minimal.yaml", {"robots.controllers.3.plugin=x"}, "--set robots.controllers.3.plugin", "robots.controllers.3", "index 3 is out of range: the list has 1 element; expected an index 0..0"},
  {"minimal.yaml", {"robots.count.x=1"}, "--set robots.count.x", "robots.count", "is a scalar (10), so it has no key or index 'x'"},
  {"minimal.yaml", {"robots.controllers.first.plugin=x"}, "--set robots.controllers.first.plugin", "robots.controllers.first", "'first' is not an index, and robots.controllers is a list"},
  {"minimal.yaml", {"robots.count"}, "--set robots.count", "", "'robots.count' has no '='; expected KEY.PATH=VALUE"},
  {"minimal.yaml", {"=5"}, "--set =5", "", "'=5' has an empty key path or component"},
  {"minimal.yaml", {"robots..count=5"}, "--set robots..count", "", "'robots..count=5' has an empty key path or component"},
  {"minimal.yaml", {"arena.width_m=[1,"}, "--set arena.width_m", "arena.width_m", "value '[1,' is not valid YAML (end of sequence flow not found)"},
  {"minimal.yaml", {"robots.colour=red"}, "--set robots.colour", "robots.colour", "unknown key; expected one of count, radius_m"},
  {"minimal.yaml", {"robots.count=many"}, "--set robots.count", "robots.count", "'many' is not an integer; expected integer 1..100000"},
  {"minimal.yaml", {"robots.controllers.0.params.speed_mps=20"}, "--set robots.controllers.0.params.speed_mps", "robots.controllers.0.params.speed_mps", "20 is out of range; expected real 0..10 (m/s)"},
  {"minimal.yaml", {"network.mac.plugin=test_routing"}, "--set network.mac.plugin", "network.mac.plugin", "is a routing plugin; a mac plugin is expected here"},
  {"minimal.yaml", {"physics.params.gravity=1"}, "--set physics.params.gravity", "physics.params.gravity", "not a parameter of plugin 'kinematic2d'; expected no parameters: plugin 'kinematic2d' declares none"},
  {"minimal.yaml", {"seed=-1"}, "--set seed", "seed", "-1 is out of range; expected integer >= 0"},
  // What the run would refuse, validate refuses: the network half counts time in whole ns.
  {"minimal.yaml", {"step_s=1e-12", "duration_s=1e-11"}, "--set step_s", "step_s", "1e-12 is out of range; expected real >= 1e-09 (s)"},
  // A name becomes part of a directory name: bounded, and not echoed back whole.
  {"minimal.yaml", {"name=" + std::string(5000, 'n')}, "--set name", "name", "a name of 5000 characters is too long; expected a name of letters, digits, '_', '-' and '.', at most 128 characters"},
  // A later override replaces the whole list: its elements are located at the override.
  {"minimal.yaml", {"network.propagation=[{plugin: test_propagation, params: {range_m: -1}}]"}, "--set network.propagation", "network.propagation.0.params.range_m", "-1 is out of range; expected real >= 0 (m)"},
};
// clang-format on

class BadScenario : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScenario, IsRefusedWithLocationKeyAndReason) {
  const BadCase& c = GetParam();
  const auto file = path_of(c);
  ScenarioOverrides overrides;
  overrides.set = c.set;
  const ScenarioError error = test::load_error(file, overrides);
  const auto& problems = error.problems();
  EXPECT_EQ(problems.size(), c.problems) << error.what();

  std::string location = c.where;
  if (c.where.empty()) location = file.string();
  if (!c.where.empty() && c.where.front() != '-') location = file.string() + ":" + c.where;
  const std::string prefix = location + ": " + (c.key.empty() ? "" : c.key + ": ");
  bool found = false;
  for (const auto& line : problems) {
    if (line.rfind(prefix, 0) == 0) {
      found = true;
      EXPECT_TRUE(Contains(line, c.what));
      EXPECT_EQ(line.find('\n'), std::string::npos) << "one problem per line: " << line;
    }
  }
  EXPECT_TRUE(found) << "no problem starts with\n  " << prefix << "\nin\n" << error.what();
}

std::string case_name(const ::testing::TestParamInfo<BadCase>& info) {
  std::string name = info.param.file.substr(0, info.param.file.find('.'));
  if (!info.param.set.empty()) name = "set_" + std::to_string(info.index);
  for (auto& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadScenario, ::testing::ValuesIn(kBadCases), case_name);

TEST(BadScenario, EveryFileInTheCorpusIsATableCase) {
  std::set<std::string> listed;
  for (const auto& c : kBadCases) {
    if (c.set.empty()) listed.insert(c.file);
  }
  listed.insert("many_problems.yaml");  // checked below
  for (const auto& entry : std::filesystem::directory_iterator(test::kScenarioDir / "bad")) {
    EXPECT_TRUE(listed.contains(entry.path().filename().string()))
        << entry.path() << " is in the corpus but not in the table";
  }
  EXPECT_GE(listed.size(), 15u);
}

TEST(BadScenario, EveryProblemIsReportedAtOnce) {
  const auto file = test::kScenarioDir / "bad" / "many_problems.yaml";
  const ScenarioError error = test::load_error(file);
  const std::string f = file.string();
  EXPECT_EQ(error.problems(),
            (std::vector<std::string>{
                f + ":3:13: duration_s: 'ten' is not a number; expected real > 0 (s)",
                f + ":8:10: robots.count: 0 is out of range; expected integer 1..100000",
                f + ":12:20: robots.controllers.0.params.speed_mps: -1 is out of range; expected "
                    "real 0..10 (m/s)",
                f + ":19:17: output.packet_trace: 1 is not a boolean; expected true or false",
            }));
  // what() is the same, one per line.
  std::string joined;
  for (const auto& line : error.problems()) joined += (joined.empty() ? "" : "\n") + line;
  EXPECT_EQ(std::string(error.what()), joined);
}

TEST(BadScenario, UnreadableFileIsNamed) {
  const auto file = test::kScenarioDir / "bad" / "no_such_file.yaml";
  const ScenarioError error = test::load_error(file);
  ASSERT_EQ(error.problems().size(), 1u);
  EXPECT_TRUE(Contains(error.problems()[0], file.string() + ": cannot read the scenario file ("));
}

TEST(BadScenario, CommandLineSeedIsLocatedAtTheOption) {
  // --seed beyond int64 cannot be written into the scenario.
  ScenarioOverrides overrides;
  overrides.seed = 18446744073709551615u;
  const ScenarioError error =
      test::load_error(test::kScenarioDir / "good" / "minimal.yaml", overrides);
  ASSERT_EQ(error.problems().size(), 1u) << error.what();
  EXPECT_EQ(error.problems()[0],
            "--seed: seed: 18446744073709551615 is out of range; expected integer >= 0");
}

}  // namespace
}  // namespace swarmnet
