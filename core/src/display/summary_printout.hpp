// The human-readable summary printed after a run, read from its summary.json document.
#pragma once

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace swarmnet {

void print_summary(std::FILE* out, const nlohmann::ordered_json& summary,
                   const std::filesystem::path& run_dir);

}  // namespace swarmnet
