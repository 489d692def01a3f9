// The summary printed after a run says which messages its figures count: the delivery ratio is
// unicast only, and broadcasts show their own reach.
#include "display/summary_printout.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace swarmnet {
namespace {

nlohmann::ordered_json summary(std::uint64_t sent, std::uint64_t broadcast_sent,
                               std::uint64_t delivered, std::uint64_t broadcast_deliveries) {
  nlohmann::ordered_json s;
  s["scenario"] = "t";
  s["seed"] = 1;
  s["robots"] = 50;
  s["sim_time_s"] = 10.0;
  s["steps"] = 100;
  s["step_s"] = 0.1;
  s["sync"] = "strict";
  s["wall_s"] = 1.0;
  s["realtime_factor"] = 10.0;
  s["cpu_s"] = {{"robot", 0.1}, {"network", 0.2}, {"transport", 0.01}};
  s["packets"] = {{"sent", sent},
                  {"delivered", delivered},
                  {"broadcast_sent", broadcast_sent},
                  {"broadcast_deliveries", broadcast_deliveries}};
  const std::uint64_t unicast = sent - broadcast_sent;
  s["pdr"] = unicast == 0 ? 0.0 : static_cast<double>(delivered) / static_cast<double>(unicast);
  s["delay_s"] = {{"mean", nullptr}, {"p50", nullptr}, {"p95", nullptr}};
  return s;
}

std::string printed(const nlohmann::ordered_json& s) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  print_summary(out, s, "runs/t");
  std::fclose(out);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

TEST(SummaryPrintout, UnicastAndBroadcastAreCountedApart) {
  // 100 messages: 80 unicast (60 delivered), 20 broadcast reaching 490 robots in all.
  const std::string text = printed(summary(100, 20, 60, 490));
  EXPECT_NE(text.find("unicast       80 sent, 60 delivered, delivery ratio 75.0%"),
            std::string::npos)
      << text;
  EXPECT_NE(
      text.find(
          "broadcast     20 sent, 490 deliveries: reach 24.5 of the 49 other robots per broadcast"),
      std::string::npos)
      << text;
}

TEST(SummaryPrintout, AKindNotSentSaysSoRatherThanAZeroRatio) {
  const std::string only_broadcast = printed(summary(20, 20, 0, 100));
  EXPECT_NE(only_broadcast.find("unicast       none sent"), std::string::npos) << only_broadcast;
  EXPECT_EQ(only_broadcast.find("delivery ratio"), std::string::npos) << only_broadcast;
  const std::string only_unicast = printed(summary(10, 0, 10, 0));
  EXPECT_NE(only_unicast.find("broadcast     none sent"), std::string::npos) << only_unicast;
}

TEST(SummaryPrintout, ARunAWorldEndedSaysHowItEnded) {
  nlohmann::ordered_json s = summary(10, 10, 0, 90);
  s["duration_s"] = 3000.0;
  s["ended"] = {{"by", "task_done"}, {"world", "task_events"}, {"at_s", 572.5}};
  s["world"] = nlohmann::ordered_json::object();
  EXPECT_NE(printed(s).find("ended         task done (world task_events) at 572.5 s, before the "
                            "3000 s cap"),
            std::string::npos)
      << printed(s);
  s["ended"] = {{"by", "duration"}, {"world", nullptr}, {"at_s", 3000.0}};
  EXPECT_NE(printed(s).find("ended         at duration_s, 3000 s: the worlds' task was not done"),
            std::string::npos)
      << printed(s);
  // Without world plugins a run always ends at duration_s: nothing to say.
  s.erase("world");
  EXPECT_EQ(printed(s).find("ended"), std::string::npos) << printed(s);
}

}  // namespace
}  // namespace swarmnet
