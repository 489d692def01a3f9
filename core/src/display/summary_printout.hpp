// The human-readable summary printed after a run, read from its summary.json document. Unicast
// and broadcast messages are shown apart: the delivery ratio, delay and hops are unicast only.
#pragma once

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace swarmnet {

void print_summary(std::FILE* out, const nlohmann::ordered_json& summary,
                   const std::filesystem::path& run_dir);

}  // namespace swarmnet
