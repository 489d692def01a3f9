#include "coupling/peer_cpu.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace swarmnet {

std::uint64_t process_cpu_ticks(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return 0;
  // The command name (field 2) is in parentheses and may hold spaces or ')': fields are counted
  // from the last ')'. After it: state (3), ppid (4), ..., utime (14), stime (15).
  const std::size_t name_end = line.rfind(')');
  if (name_end == std::string::npos) return 0;
  std::istringstream fields(line.substr(name_end + 1));
  std::string skipped;
  for (int field = 3; field <= 13; ++field) fields >> skipped;
  std::uint64_t user = 0;
  std::uint64_t system = 0;
  if (!(fields >> user >> system)) return 0;
  return user + system;
}

}  // namespace swarmnet
