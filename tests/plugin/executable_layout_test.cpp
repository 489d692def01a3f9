// Where the command finds its own plugins and data (executable_layout.hpp): from its location,
// in an installed prefix and in a build tree alike.
#include "plugin/executable_layout.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "plugin/plugin_loader.hpp"

namespace swarmnet {
namespace {

namespace fs = std::filesystem;

// This test runs from <build>/tests/; the fixtures are built to <build>/test_fixtures/.
const fs::path kBuildDir = fs::path(SWARMNET_TEST_FIXTURE_DIR).parent_path();

TEST(ExecutableLayout, ABuildTreeCommandUsesTheBuildTreesPluginsAndData) {
  const ExecutableLayout layout = executable_layout();
  EXPECT_EQ(layout.plugin_dir, kBuildDir / "plugins");
  EXPECT_EQ(layout.data_dir, kBuildDir / "share" / "swarmnet");
  EXPECT_TRUE(fs::exists(layout.data_dir / "configs" / "quickstart.yaml"));
  EXPECT_EQ(PluginLoader().search_path().back(), kBuildDir / "plugins");
}

TEST(ExecutableLayout, AnInstalledCommandUsesItsPrefixWhereverThePrefixIs) {
  const fs::path prefix =
      fs::temp_directory_path() / ("swarmnet-layout-" + std::to_string(getpid()));
  fs::remove_all(prefix);
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / SWARMNET_INSTALL_LIBDIR / "swarmnet" / "plugins");
  const ExecutableLayout layout = layout_around(prefix / "bin" / "swarmnet");
  EXPECT_EQ(layout.plugin_dir, prefix / SWARMNET_INSTALL_LIBDIR / "swarmnet" / "plugins");
  EXPECT_EQ(layout.data_dir, prefix / SWARMNET_INSTALL_DATADIR / "swarmnet");
  fs::remove_all(prefix);
}

}  // namespace
}  // namespace swarmnet
