#include "display/summary_printout.hpp"

#include <cinttypes>

namespace swarmnet {

void print_summary(std::FILE* out, const nlohmann::ordered_json& s,
                   const std::filesystem::path& run_dir) {
  const auto& packets = s["packets"];
  std::fprintf(out, "SwarmNet run '%s' (seed %" PRIu64 ")\n",
               s["scenario"].get<std::string>().c_str(), s["seed"].get<std::uint64_t>());
  std::fprintf(out, "  robots        %u\n", s["robots"].get<unsigned>());
  std::fprintf(out, "  simulated     %.1f s in %" PRIu64 " steps of %g s (%s sync)\n",
               s["sim_time_s"].get<double>(), s["steps"].get<std::uint64_t>(),
               s["step_s"].get<double>(), s["sync"].get<std::string>().c_str());
  // A run with world plugins says how it ended: its task done, or cut off at duration_s.
  if (s.contains("ended")) {
    const auto& ended = s["ended"];
    if (ended["by"] == "task_done") {
      std::fprintf(out, "  ended         task done (world %s) at %.1f s, before the %g s cap\n",
                   ended["world"].get<std::string>().c_str(), ended["at_s"].get<double>(),
                   s["duration_s"].get<double>());
    } else if (s.contains("world")) {
      std::fprintf(out, "  ended         at duration_s, %g s: the worlds' task was not done\n",
                   s["duration_s"].get<double>());
    }
  }
  std::fprintf(out, "  wall time     %.2f s, %.1fx real time\n", s["wall_s"].get<double>(),
               s["realtime_factor"].get<double>());
  std::fprintf(out, "  CPU           robot %.2f s, network %.2f s, transport %.3f s\n",
               s["cpu_s"]["robot"].get<double>(), s["cpu_s"]["network"].get<double>(),
               s["cpu_s"]["transport"].get<double>());
  // summary.json's `delivered` and `pdr` count unicast messages only; broadcasts have their own
  // line: how many robots each reached on average, of the others (the sender excluded).
  const auto sent = packets["sent"].get<std::uint64_t>();
  const auto broadcast_sent = packets["broadcast_sent"].get<std::uint64_t>();
  const std::uint64_t unicast_sent = sent - broadcast_sent;
  if (unicast_sent == 0) {
    std::fprintf(out, "  unicast       none sent\n");
  } else {
    std::fprintf(
        out, "  unicast       %" PRIu64 " sent, %" PRIu64 " delivered, delivery ratio %.1f%%\n",
        unicast_sent, packets["delivered"].get<std::uint64_t>(), 100.0 * s["pdr"].get<double>());
  }
  if (broadcast_sent == 0) {
    std::fprintf(out, "  broadcast     none sent\n");
  } else {
    const auto deliveries = packets["broadcast_deliveries"].get<std::uint64_t>();
    const unsigned others = s["robots"].get<unsigned>() - 1;
    std::fprintf(out,
                 "  broadcast     %" PRIu64 " sent, %" PRIu64
                 " deliveries: reach %.1f of the %u other robots per broadcast\n",
                 broadcast_sent, deliveries,
                 static_cast<double>(deliveries) / static_cast<double>(broadcast_sent), others);
  }
  const auto& delay = s["delay_s"];
  if (!delay["mean"].is_null()) {
    std::fprintf(out, "  unicast delay mean %.2f ms, median %.2f ms, 95th percentile %.2f ms\n",
                 1e3 * delay["mean"].get<double>(), 1e3 * delay["p50"].get<double>(),
                 1e3 * delay["p95"].get<double>());
    std::fprintf(out, "  unicast hops  %.2f on average\n", s["hops_mean"].get<double>());
  }
  std::fprintf(out, "  outputs       %s/ (summary.json, run.log, ...)\n", run_dir.string().c_str());
}

}  // namespace swarmnet
