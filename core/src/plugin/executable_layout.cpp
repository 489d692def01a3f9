#include "plugin/executable_layout.hpp"

#include <system_error>

namespace swarmnet {

ExecutableLayout layout_around(const std::filesystem::path& executable) {
  const std::filesystem::path root = executable.parent_path().parent_path();
  const std::filesystem::path installed_plugins =
      root / SWARMNET_INSTALL_LIBDIR / "swarmnet" / "plugins";
  std::error_code ec;
  if (std::filesystem::is_directory(installed_plugins, ec)) {
    return {installed_plugins, root / SWARMNET_INSTALL_DATADIR / "swarmnet",
            root / SWARMNET_INSTALL_LIBDIR / "swarmnet" / "engines"};
  }
  return {root / "plugins", root / "share" / "swarmnet", root / "engines"};
}

std::filesystem::path running_executable() {
  std::error_code ec;
  auto executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : executable;
}

ExecutableLayout executable_layout() {
  const auto executable = running_executable();
  if (executable.empty()) return {};
  return layout_around(executable);
}

}  // namespace swarmnet
