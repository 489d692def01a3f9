// Where `swarmnet run` finds configs/quickstart.yaml when no file is given: the source tree this
// binary was built from, else the install prefix's share directory.
#pragma once

#include <filesystem>

namespace swarmnet {

inline std::filesystem::path default_scenario_path() {
  std::filesystem::path in_source = SWARMNET_SOURCE_DIR "/configs/quickstart.yaml";
  if (std::filesystem::exists(in_source)) return in_source;
  return SWARMNET_INSTALL_DATA_DIR "/configs/quickstart.yaml";
}

}  // namespace swarmnet
