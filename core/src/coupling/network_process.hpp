// `swarmnet net`: the network half as a process of its own, reached by the robot half through
// a shared-memory segment, a Unix-domain socket or TCP (DESIGN.md section 3).
//
// Started by `swarmnet run` (--shm, --uds, --tcp, --parent) it serves that run. Started by hand
// with --listen it is a server for robot halves elsewhere, and trusts none of them: each must
// prove it knows the token before anything it sends is parsed (handshakes run concurrently, each
// under its own deadline: handshake_acceptor.hpp), it loads plugins only from the server's own
// search path, writes only under the server's own output directory, and serves runs one after
// another (docs/security.md).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace swarmnet {

struct NetworkProcessOptions {
  std::string shm;     // attach to this segment (spawned by `swarmnet run`)
  std::string uds;     // connect to this Unix socket
  std::string tcp;     // connect to HOST:PORT
  std::string listen;  // serve robot halves on [HOST:]PORT (HOST defaults to 127.0.0.1)
  pid_t parent = 0;    // stop as soon as this process is gone (0: no parent to watch)
  std::chrono::milliseconds step_timeout{std::chrono::seconds(60)};
  // With --listen:
  std::filesystem::path out;  // runs go to OUT/run-NNNN (default: private_output_dir())
  std::string token_file;     // else $SWARMNET_NET_TOKEN_FILE; required
  std::vector<std::filesystem::path> plugin_paths;  // searched before $SWARMNET_PLUGIN_PATH
  std::uint32_t runs = 1;                           // runs to serve before exiting
  bool serve_forever = false;                       // ... or never stop
  std::chrono::milliseconds handshake_timeout{std::chrono::seconds(5)};
  std::uint32_t max_pending_handshakes = 64;  // in flight at once; more evict the oldest
  // Memory the runs may take above the server's own footprint (memory_budget.hpp); a quarter of
  // it bounds one step's payloads.
  std::uint64_t max_memory = 0;
};

// The output directory of a server started without --out: $XDG_STATE_HOME/swarmnet/net, else
// ~/.local/state/swarmnet/net, created private (mode 0700).
std::filesystem::path private_output_dir();

// Serves one run (a child of `swarmnet run`), or with --listen the runs asked for. Returns the
// process exit status: 0 when every run served finished, 1 otherwise; what went wrong has been
// sent to the robot half and, for a server, printed.
int run_network_process(const NetworkProcessOptions& options);

}  // namespace swarmnet
