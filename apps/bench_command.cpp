#include "bench_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "coupling/process_spawn.hpp"
#include "plugin/executable_layout.hpp"

namespace swarmnet {

namespace {

std::filesystem::path own_directory() { return running_executable().parent_path(); }

// Benchmark name "Family/transport/arg/..." -> value of `field`, keyed by (family, transport, arg).
using Key = std::tuple<std::string, std::string, std::string>;

std::map<Key, nlohmann::json> index_results(const nlohmann::json& results) {
  std::map<Key, nlohmann::json> by_key;
  for (const auto& b : results["benchmarks"]) {
    const std::string name = b["name"];
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t slash = name.find('/'); slash != std::string::npos;
         start = slash + 1, slash = name.find('/', start)) {
      parts.push_back(name.substr(start, slash - start));
    }
    parts.push_back(name.substr(start));
    if (parts.size() < 2) continue;
    const std::string arg =
        parts.size() > 2 && parts[2].find(':') == std::string::npos ? parts[2] : "";
    by_key[{parts[0], parts[1], arg}] = b;
  }
  return by_key;
}

double ns_per_item(const nlohmann::json& b) { return 1e9 / b["items_per_second"].get<double>(); }

double real_ns(const nlohmann::json& b) {
  const std::string unit = b["time_unit"];
  const double t = b["real_time"].get<double>();
  return unit == "ns" ? t : unit == "us" ? t * 1e3 : unit == "ms" ? t * 1e6 : t * 1e9;
}

}  // namespace

int bench_transport_command(const std::filesystem::path& out, double min_time_s) {
  const auto binary = own_directory() / "transport_bench";
  if (!std::filesystem::exists(binary)) {
    std::fprintf(stderr,
                 "swarmnet: error: %s is not built (./swarmnet bench transport installs "
                 "libbenchmark-dev and builds it; by hand: cmake --build build --target "
                 "transport_bench)\n",
                 binary.c_str());
    return 2;
  }
  std::filesystem::create_directories(out.parent_path().empty() ? "." : out.parent_path());
  std::vector<std::string> args = {binary.string(), "--benchmark_out=" + out.string(),
                                   "--benchmark_out_format=json",
                                   "--benchmark_min_time=" + std::to_string(min_time_s)};
  std::string error;
  const pid_t pid = spawn_process({binary, std::move(args), {}, std::nullopt}, error);
  if (pid < 0) {
    std::fprintf(stderr, "swarmnet: error: cannot start %s: %s\n", binary.c_str(), error.c_str());
    return 1;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "swarmnet: error: the transport benchmarks failed\n");
    return 1;
  }
  nlohmann::json results;
  try {
    std::ifstream in(out);
    results = nlohmann::json::parse(in);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: cannot read %s: %s\n", out.c_str(), error.what());
    return 1;
  }
  const auto r = index_results(results);
  auto get = [&](const std::string& family, const std::string& kind, const std::string& arg) {
    const auto it = r.find({family, kind, arg});
    return it == r.end() ? nlohmann::json() : it->second;
  };
  std::printf("\nTransport comparison (side by side in one run; JSON: %s)\n", out.c_str());
  for (const char* family : {"PerMessage", "Throughput"}) {
    std::printf("\n%s: ns per message (ring vs others: how many times cheaper)\n",
                std::string(family) == "PerMessage"
                    ? "Each message made visible on its own"
                    : "Messages made visible once per 256 (per step)");
    std::printf("  %8s %12s %12s %8s %12s %8s\n", "bytes", "ring", "uds", "x", "tcp", "x");
    for (const char* bytes : {"16", "64", "256", "1024", "4096", "16384", "65536"}) {
      const auto ring = get(family, "ring", bytes);
      const auto uds = get(family, "uds", bytes);
      const auto tcp = get(family, "tcp", bytes);
      if (ring.is_null() || uds.is_null() || tcp.is_null()) continue;
      std::printf("  %8s %12.1f %12.1f %8.1f %12.1f %8.1f\n", bytes, ns_per_item(ring),
                  ns_per_item(uds), ns_per_item(uds) / ns_per_item(ring), ns_per_item(tcp),
                  ns_per_item(tcp) / ns_per_item(ring));
    }
  }
  std::printf("\nRound trip of one 64-byte record, us:");
  for (const char* kind : {"ring", "uds", "tcp"}) {
    const auto b = get("RoundTrip", kind, "");
    if (!b.is_null()) std::printf("  %s %.2f", kind, real_ns(b) * 1e-3);
  }
  std::printf(
      "\n\nOne step exchange (batch there, deliveries back), us; last column: the same\n"
      "encoded and decoded with both ends in one thread (CPU only, no cross-core moves):\n");
  std::printf("  %8s %10s %10s %10s %10s\n", "robots", "ring", "uds", "tcp", "1 thread");
  for (const char* robots : {"25", "100", "400", "2000"}) {
    std::printf("  %8s", robots);
    for (const char* kind : {"ring", "uds", "tcp"}) {
      const auto b = get("StepExchange", kind, robots);
      std::printf(" %10.2f", b.is_null() ? 0.0 : real_ns(b) * 1e-3);
    }
    const auto codec = get("StepCodec", "ring", robots);
    std::printf(" %10.2f\n", codec.is_null() ? 0.0 : real_ns(codec) * 1e-3);
  }
  return 0;
}

}  // namespace swarmnet
