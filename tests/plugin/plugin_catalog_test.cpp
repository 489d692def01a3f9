// What `swarmnet plugins` and `swarmnet plugins NAME` print, checked on the fixtures.
#include "plugin/plugin_catalog.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace swarmnet {
namespace {

namespace fs = std::filesystem;

const fs::path kFixtures = SWARMNET_TEST_FIXTURE_DIR;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// The first line that contains `part`, or "" when none does.
std::string line_with(const std::vector<std::string>& lines, const std::string& part) {
  for (const auto& line : lines) {
    if (line.find(part) != std::string::npos) return line;
  }
  return "";
}

TEST(PluginCatalog, FormatsRealsReadably) {
  EXPECT_EQ(format_real(6.0e6), "6000000");
  EXPECT_EQ(format_real(0.1), "0.1");
  EXPECT_EQ(format_real(16.0206), "16.0206");
  EXPECT_EQ(format_real(-96.0), "-96");
  EXPECT_EQ(format_real(0.0), "0");
  EXPECT_EQ(format_real(1e-9), "1e-09");
  EXPECT_EQ(format_real(2.5e20), "2.5e+20");
  EXPECT_EQ(format_param_value(ParamValue{std::int64_t{-3}}), "-3");
  EXPECT_EQ(format_param_value(ParamValue{false}), "false");
  EXPECT_EQ(format_param_value(ParamValue{std::string("random")}), "random");
}

TEST(PluginCatalog, FormatsRanges) {
  EXPECT_EQ(format_param_range(real_param("a", 1, "m", "", 0.0, 10.0)), "0..10");
  EXPECT_EQ(format_param_range(real_param("a", 1, "m", "", 0.0)), ">= 0");
  EXPECT_EQ(format_param_range(real_param("a", 1, "m", "")), "any");
  EXPECT_EQ(format_param_range(integer_param("a", 1, "", "", 1, 255)), "1..255");
  EXPECT_EQ(format_param_range(integer_param("a", 1, "", "")), "any");
  EXPECT_EQ(format_param_range(
                integer_param("a", 1, "", "", std::numeric_limits<std::int64_t>::min(), 5)),
            "<= 5");
  EXPECT_EQ(format_param_range(bool_param("a", true, "")), "");
}

TEST(PluginCatalog, TableListsPluginsInAlignedColumnsThenBrokenFilesThenSearchPath) {
  PluginLoader loader({kFixtures});
  std::ostringstream out;
  print_plugin_table(out, loader);
  const std::string text = out.str();
  const auto lines = lines_of(text);
  ASSERT_FALSE(lines.empty());

  const std::string& header = lines.front();
  EXPECT_EQ(header.rfind("KIND", 0), 0u) << header;
  const std::size_t name_column = header.find("NAME");
  const std::size_t version_column = header.find("VERSION");
  const std::size_t path_column = header.find("PATH");
  const std::size_t summary_column = header.find("SUMMARY");
  ASSERT_NE(summary_column, std::string::npos) << header;

  const std::string row = line_with(lines, "test_controller");
  EXPECT_EQ(row.rfind("controller", 0), 0u) << row;
  EXPECT_EQ(row.find("test_controller"), name_column) << row;
  EXPECT_EQ(row.find("1.2.3"), version_column) << row;
  EXPECT_EQ(row.find((kFixtures / "swarmnet_test_controller.so").string()), path_column) << row;
  EXPECT_EQ(row.find("Test fixture: records its parameters on every step."), summary_column) << row;
  // Kind order: physics before controller.
  EXPECT_LT(text.find("kinematic2d"), text.find("test_controller"));

  const std::size_t broken = text.find("Broken plugin files (not loaded):");
  const std::size_t search = text.find("Search path, in order:");
  ASSERT_NE(broken, std::string::npos) << text;
  ASSERT_NE(search, std::string::npos) << text;
  EXPECT_LT(broken, search);
  const std::string abi_line = line_with(lines, "swarmnet_test_abi_mismatch.so was built");
  EXPECT_EQ(abi_line.rfind("  " + (kFixtures / "swarmnet_test_abi_mismatch.so").string(), 0), 0u)
      << abi_line;
  EXPECT_NE(abi_line.find("ABI version " + std::to_string(kAbiVersion + 1)), std::string::npos);
  EXPECT_NE(line_with(lines, "swarmnet_test_not_elf.so").find("invalid ELF header"),
            std::string::npos);
  EXPECT_NE(line_with(lines, "swarmnet_test_no_entry.so").find("is not a SwarmNet plugin"),
            std::string::npos);
  EXPECT_NE(text.find("  1. " + kFixtures.string() + "\n", search), std::string::npos) << text;
}

TEST(PluginCatalog, DetailsShowInfoDescriptionAndParameterTable) {
  PluginLoader loader({kFixtures});
  std::ostringstream out;
  print_plugin_details(out, *loader.find("test_controller"));
  const std::string text = out.str();
  const auto lines = lines_of(text);

  EXPECT_EQ(line_with(lines, "name:"), "name:     test_controller");
  EXPECT_EQ(line_with(lines, "kind:"), "kind:     controller");
  EXPECT_EQ(line_with(lines, "version:"), "version:  1.2.3");
  EXPECT_EQ(line_with(lines, "path:"),
            "path:     " + (kFixtures / "swarmnet_test_controller.so").string());
  EXPECT_NE(
      text.find("It never moves the robot; each step it records speed_mps, rate_hz and count."),
      std::string::npos);

  const std::string header = line_with(lines, "NAME");
  ASSERT_FALSE(header.empty()) << text;
  std::vector<std::size_t> columns;
  for (const char* title : {"NAME", "TYPE", "DEFAULT", "RANGE", "UNIT", "CHOICES", "HELP"}) {
    columns.push_back(header.find(title));
    ASSERT_NE(columns.back(), std::string::npos) << title;
  }
  const auto expect_row = [&](const std::vector<std::string>& cells) {
    const std::string row = line_with(lines, "  " + cells[0] + " ");
    ASSERT_FALSE(row.empty()) << cells[0];
    for (std::size_t c = 0; c < cells.size(); ++c) {
      EXPECT_EQ(row.compare(columns[c], cells[c].size(), cells[c]), 0)
          << "column " << c << " of: " << row;
    }
  };
  expect_row({"speed_mps", "real", "1", "0..10", "m/s", "-", "Wheel speed."});
  expect_row({"rate_hz", "real", "1", ">= 0", "1/s", "-", "Messages per second."});
  expect_row({"count", "integer", "3", "1..100", "-", "-", "How many of something."});
  expect_row({"enabled", "boolean", "true", "-", "-", "-", "Whether the controller acts."});
  expect_row({"mode", "text", "\"random\"", "-", "-", "random, straight", "Motion mode."});
  expect_row({"label", "text", "\"\"", "-", "-", "-", "Free text."});
}

TEST(PluginCatalog, DetailsOfAPluginWithoutParameters) {
  PluginLoader loader({kFixtures});
  std::ostringstream out;
  print_plugin_details(out, *loader.find("kinematic2d"));
  EXPECT_NE(out.str().find("kind:     physics\n"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("Parameters: none\n"), std::string::npos) << out.str();
}

TEST(PluginCatalog, MacParameterDefaultIsReadable) {
  PluginLoader loader({kFixtures});
  std::ostringstream out;
  print_plugin_details(out, *loader.find("ideal_mac"));
  const auto lines = lines_of(out.str());
  const std::string row = line_with(lines, "bitrate_bps");
  EXPECT_NE(row.find(" 6000000 "), std::string::npos) << row;
  EXPECT_NE(row.find(" >= 1 "), std::string::npos) << row;
  EXPECT_NE(row.find(" bit/s "), std::string::npos) << row;
}

}  // namespace
}  // namespace swarmnet
