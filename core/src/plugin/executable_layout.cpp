#include "plugin/executable_layout.hpp"

#include <system_error>

namespace swarmnet {

ExecutableLayout layout_around(const std::filesystem::path& executable) {
  const std::filesystem::path root = executable.parent_path().parent_path();
  const std::filesystem::path installed_plugins =
      root / SWARMNET_INSTALL_LIBDIR / "swarmnet" / "plugins";
  std::error_code ec;
  if (std::filesystem::is_directory(installed_plugins, ec)) {
    return {installed_plugins, root / SWARMNET_INSTALL_DATADIR / "swarmnet"};
  }
  return {root / "plugins", root / "share" / "swarmnet"};
}

ExecutableLayout executable_layout() {
  std::error_code ec;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return layout_around(executable);
}

}  // namespace swarmnet
