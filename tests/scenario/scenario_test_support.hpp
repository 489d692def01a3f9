// Helpers shared by the scenario tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scenario/scenario_loader.hpp"

namespace swarmnet::test {

inline const std::filesystem::path kFixtures = SWARMNET_TEST_FIXTURE_DIR;
inline const std::filesystem::path kScenarioDir =
    std::filesystem::path(SWARMNET_SOURCE_DIR) / "tests" / "scenario";

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected to find\n  " << part << "\nin\n  " << text;
}

// The ScenarioError that loading `file` throws; fails the test when it loads.
inline ScenarioError load_error(const std::filesystem::path& file,
                                const ScenarioOverrides& overrides = {}) {
  PluginLoader loader({kFixtures});
  try {
    load_scenario(file, overrides, loader);
  } catch (const ScenarioError& error) {
    return error;
  }
  ADD_FAILURE() << file << " loaded, but it should have been refused";
  return ScenarioError({});
}

// A directory of its own for one test, removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("swarmnet-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace swarmnet::test
