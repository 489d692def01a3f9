// SIGINT, SIGTERM and SIGHUP during a run: the handler only records the signal; the step loop and
// every wait check it, so a run stops promptly and still cleans up (child process, shared memory,
// temporary files) through the ordinary error path.
#pragma once

namespace swarmnet {

// Installs the handlers (idempotent).
void install_stop_handlers();
// The signal that asked the run to stop, or 0.
int stop_signal();
// A process started by another SwarmNet process that must not outlive it (a sweep's runs) is
// given kParentVariable=PID: this asks the kernel for SIGTERM when that parent dies, and exits
// at once if it is gone already. Call first thing in main().
inline constexpr const char* kParentVariable = "SWARMNET_PARENT_PID";
void follow_parent_from_environment();

// "SIGINT", "SIGTERM", "SIGHUP" for messages.
const char* stop_signal_name(int signal);

}  // namespace swarmnet
