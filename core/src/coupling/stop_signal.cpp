#include "coupling/stop_signal.hpp"

#include <sys/prctl.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

namespace swarmnet {

namespace {

std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void record_stop_signal(int signal) {
  received.store(signal, std::memory_order_relaxed);
}

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: blocking calls return EINTR and re-check
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGHUP, &action, nullptr);  // the terminal closed: stop cleanly, as for Ctrl-C
}

void follow_parent_from_environment() {
  const char* text = std::getenv(kParentVariable);
  if (text == nullptr) return;
  const long parent = std::strtol(text, nullptr, 10);
  ::unsetenv(kParentVariable);  // for this process only: its own children have another parent
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // stops like Ctrl-C: cleans up, takes its own child along
  if (parent > 0 && ::getppid() != static_cast<pid_t>(parent)) std::_Exit(128 + SIGTERM);
}

const char* stop_signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

int stop_signal() { return received.load(std::memory_order_relaxed); }

}  // namespace swarmnet
