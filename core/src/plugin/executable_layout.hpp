// Where the running command's own files are, found from its executable and never from a path
// compiled in: an installed swarmnet must not know the build tree it was built in.
//
//   installed   <prefix>/bin/swarmnet   plugins in <prefix>/<libdir>/swarmnet/plugins,
//                                       engines in <prefix>/<libdir>/swarmnet/engines,
//                                       data (configs/, scripts/) in <prefix>/share/swarmnet
//   build tree  <build>/bin/swarmnet    plugins in <build>/plugins, engines in <build>/engines,
//               (and <build>/tests/*)   data in <build>/share/swarmnet (links to the sources)
//
// The installed layout is recognised by its plugin directory; anything else is a build tree.
#pragma once

#include <filesystem>

namespace swarmnet {

struct ExecutableLayout {
  std::filesystem::path plugin_dir;
  std::filesystem::path data_dir;
  std::filesystem::path engine_dir;  // network engines loaded on demand (the ns-3 engine)
};

// The layout around `executable` (an absolute path to a command in <root>/bin or <root>/tests).
ExecutableLayout layout_around(const std::filesystem::path& executable);

// The running process's executable (/proc/self/exe); empty when it cannot be read.
std::filesystem::path running_executable();

// The layout around running_executable(). Empty paths when the executable cannot be read.
ExecutableLayout executable_layout();

}  // namespace swarmnet
