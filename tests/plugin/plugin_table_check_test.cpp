// The check of a plugin's own table (plugin_table_check.hpp), on tables built in the test; the
// loader's use of it runs against fixture libraries in plugin_loader_test.cpp.
#include "plugin/plugin_table_check.hpp"

#include <gtest/gtest.h>

#include <string>

#include "plugin/plugin_error.hpp"

namespace swarmnet {
namespace {

PluginInfo table(std::vector<ParamSpec> params, std::string name = "good_plugin") {
  return {std::move(name), "1.0.0", "summary", "", std::move(params)};
}

std::string refusal(const PluginInfo& info) {
  try {
    check_plugin_table(info, "/plugins/swarmnet_good_plugin.so");
  } catch (const PluginError& error) {
    return error.what();
  }
  return "";
}

TEST(PluginTableCheck, AcceptsAWellFormedTable) {
  EXPECT_EQ(refusal(table({
                real_param("jitter_max_s", 0.005, "s", "jitter", 0.0, 1.0),
                integer_param("ttl", 32, "", "hops", 1, 255),
                bool_param("enabled", true, "on"),
                text_param("mode", "fast", "mode", {"fast", "slow"}),
                text_param("label", "anything", "free text"),
            })),
            "");
}

TEST(PluginTableCheck, RefusesANameThatIsNotLowerSnakeCase) {
  for (const char* name : {"Ttl", "ttl_", "_ttl", "t__tl", "1ttl", "tt-l", ""}) {
    EXPECT_NE(refusal(table({integer_param(name, 1, "", "", 0, 9)}))
                  .find("its name is not lower_snake_case"),
              std::string::npos)
        << name;
  }
  EXPECT_NE(refusal(table({}, "GoodPlugin")).find("plugin 'GoodPlugin'"), std::string::npos);
  EXPECT_TRUE(is_lower_snake_case("tx_power_dbm"));
  EXPECT_TRUE(is_lower_snake_case("p2p"));
}

TEST(PluginTableCheck, RefusesADefaultOutsideItsRangeOrChoices) {
  EXPECT_NE(refusal(table({real_param("p", 1.5, "", "", 0.0, 1.0)}))
                .find("parameter 'p': its default 1.5 is outside its range [0, 1]"),
            std::string::npos);
  EXPECT_NE(refusal(table({real_param("p", 0.5, "", "", 1.0, 0.0)})).find("is empty"),
            std::string::npos);
  EXPECT_NE(refusal(table({text_param("mode", "medium", "", {"fast", "slow"})}))
                .find("parameter 'mode': its default 'medium' is not among its choices"),
            std::string::npos);
}

TEST(PluginTableCheck, RefusesANameDeclaredTwiceAndADefaultOfAnotherType) {
  const std::string twice =
      refusal(table({integer_param("n", 1, "", ""), real_param("n", 0.5, "", "")}));
  EXPECT_NE(twice.find("plugin 'good_plugin' (/plugins/swarmnet_good_plugin.so): parameter 'n' "
                       "is declared twice"),
            std::string::npos)
      << twice;
  ParamSpec wrong = integer_param("window", 4, "", "");
  wrong.default_value = std::string("four");
  EXPECT_NE(refusal(table({wrong})).find("it is declared integer but its default is text"),
            std::string::npos);
}

}  // namespace
}  // namespace swarmnet
