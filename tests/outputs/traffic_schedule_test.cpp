// The traffic schedule's files (traffic.csv, and send_options.csv and route_queries.csv, opened
// only at their first row): what `swarmnet replay` reads to feed the network half the run's
// batches.
#include "outputs/traffic_schedule.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace swarmnet {
namespace {

StepBatch batch(std::uint64_t step, std::vector<RouteQuery> queries) {
  StepBatch b;
  b.step = step;
  b.start = SimTime{static_cast<std::int64_t>(step) * 100'000'000};
  AppMessage message;
  message.message_id = step;
  message.source = 1;
  message.destination = 2;
  b.messages.push_back(message);
  b.route_queries = std::move(queries);
  return b;
}

struct Files {
  std::ostringstream traffic;
  std::optional<std::ostringstream> options;
  std::optional<std::ostringstream> queries;
  int opened_queries = 0;
  TrafficScheduleWriter writer{traffic, 5, SimTime{100'000'000},
                               [this]() -> std::ostream& { return options.emplace(); },
                               [this]() -> std::ostream& {
                                 ++opened_queries;
                                 return queries.emplace();
                               }};
};

TEST(TrafficSchedule, RouteQueriesAreWrittenInBatchOrderFromTheFirstOne) {
  Files files;
  files.writer.write(batch(0, {}));
  EXPECT_FALSE(files.queries) << "not opened before a controller asked";
  files.writer.write(batch(1, {{0, 2}, {0, 5}, {3, 1}}));
  files.writer.write(batch(2, {}));
  files.writer.write(batch(3, {{4, 0}}));
  ASSERT_TRUE(files.queries);
  EXPECT_EQ(files.opened_queries, 1);
  EXPECT_EQ(files.queries->str(), "step,robot,destination\n1,0,2\n1,0,5\n1,3,1\n3,4,0\n");
  EXPECT_FALSE(files.options) << "no message had send options";
  EXPECT_EQ(files.traffic.str().substr(0, files.traffic.str().find('\n')),
            "message_id,step,inject_ns,source,destination,payload_bytes");
}

TEST(TrafficSchedule, WithoutAnOpenerRouteQueriesAreNotWritten) {
  std::ostringstream traffic;
  TrafficScheduleWriter writer(traffic, 5, SimTime{100'000'000});
  writer.write(batch(0, {{0, 1}}));
  EXPECT_EQ(traffic.str().find("step,robot,destination"), std::string::npos);
}

// A run with a sensing trace records the sending controller's port with the options: its send
// reports name it, and a replay must address them alike.
TEST(TrafficSchedule, WithPortsTheSendOptionsCarryTheSendersPort) {
  for (const bool ports : {false, true}) {
    std::ostringstream traffic;
    std::optional<std::ostringstream> options;
    TrafficScheduleWriter writer(
        traffic, 5, SimTime{100'000'000}, [&]() -> std::ostream& { return options.emplace(); }, {},
        ports);
    StepBatch b = batch(0, {});
    b.messages[0].port = 7;
    b.messages[0].report = true;
    writer.write(b);
    ASSERT_TRUE(options);
    EXPECT_EQ(options->str(), ports ? "message_id,hop_limit,report,port\n0,0,1,7\n"
                                    : "message_id,hop_limit,report\n0,0,1\n");
  }
}

}  // namespace
}  // namespace swarmnet
