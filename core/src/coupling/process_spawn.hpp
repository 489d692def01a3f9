// Starting another program: the one place SwarmNet calls posix_spawn (the network half's child
// process, a sweep's runs, the transport benchmark).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swarmnet {

struct SpawnRequest {
  std::filesystem::path executable;
  std::vector<std::string> arguments;          // argv, argv[0] included
  std::vector<std::string> extra_environment;  // NAME=VALUE, after this process's environment
  // When set: standard output and error go to this file (created or truncated, mode 0644) and
  // standard input reads /dev/null.
  std::optional<std::filesystem::path> output_file;
  // Otherwise, when set: standard output and error go to these descriptors (the write ends of a
  // caller's pipes) and standard input reads /dev/null. Otherwise all three are inherited.
  int output_fd = -1;
  int error_fd = -1;
  // Look `executable` up on PATH when it has no slash, as a shell does.
  bool search_path = false;
};

// Starts the program; returns its pid, or -1 with `error` set to the reason.
pid_t spawn_process(const SpawnRequest& request, std::string& error);

}  // namespace swarmnet
