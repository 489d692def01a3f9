// Where `swarmnet run` finds configs/quickstart.yaml when no file is given: the data directory
// beside the command (<prefix>/share/swarmnet installed, <build>/share/swarmnet in a build tree,
// which links to the sources' configs/).
#pragma once

#include <filesystem>
#include <system_error>

#include "plugin/executable_layout.hpp"

namespace swarmnet {

inline std::filesystem::path default_scenario_path() {
  const auto path = executable_layout().data_dir / "configs" / "quickstart.yaml";
  // Through the build tree's link to the real file, so that messages name the source file.
  std::error_code ec;
  const auto real = std::filesystem::canonical(path, ec);
  return ec ? path : real;
}

}  // namespace swarmnet
