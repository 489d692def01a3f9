// `swarmnet bench transport`: runs the transport micro-benchmarks (bench/transport) side by side
// in one run, keeps Google Benchmark's JSON and prints the comparison table with ratios.
#pragma once

#include <filesystem>

namespace swarmnet {

int bench_transport_command(const std::filesystem::path& out, double min_time_s);

}  // namespace swarmnet
