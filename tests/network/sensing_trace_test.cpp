// The sensing trace's rows (output.sensing_trace, sensing.csv): every field of every neighbour
// table entry, send report and route answer a StepResult carries, in its order, under one header.
#include "network/sensing_trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

namespace swarmnet {
namespace {

RadioNeighbor neighbor(RobotId id, std::int64_t last_heard_ns, double rssi_dbm) {
  RadioNeighbor entry;
  entry.id = id;
  entry.last_heard = SimTime{last_heard_ns};
  entry.rssi_dbm = rssi_dbm;
  entry.rssi_smoothed_dbm = -71.25;
  entry.sinr_db = 0.1;  // not exact in binary: written as the shortest text that reads back
  entry.frames = 3;
  entry.unicasts = 2;
  entry.first_attempt_acks = 1;
  return entry;
}

// Step 7's window, [700 ms, 800 ms): robot 0 heard robots 1 and 2, robot 1 nobody, robot 2
// heard robot 0 (the threshold PHY: no SINR); three reports; two route answers.
StepResult hand_built_result() {
  StepResult result;
  result.step = 7;
  result.neighbor_counts = {2, 0, 1};
  result.neighbors = {neighbor(1, 712'000'001, -60.5), neighbor(2, 799'999'999, -88.0),
                      neighbor(0, 700'000'000, -1e-7)};
  result.neighbors[2].sinr_db = std::numeric_limits<double>::infinity();
  result.neighbors[2].unicasts = 0;
  result.neighbors[2].first_attempt_acks = 0;
  result.send_reports = {
      {2, 9,
       SendReport{41, SendOutcome::acknowledged, DropReason::no_route, SimTime{703'000'000}, 1, 2}},
      {0, 9,
       SendReport{42, SendOutcome::sent, DropReason::no_route, SimTime{704'000'000}, kBroadcast,
                  0}},
      {1, 65535,
       SendReport{18446744073709551615ULL, SendOutcome::dropped, DropReason::buffer_timeout,
                  SimTime{750'000'000}, kNoNode, 0}}};
  result.routes = {{RouteQuery{0, 2}, Route{RouteStatus::valid, 1, 2, SimTime{800'000'000}}},
                   {RouteQuery{1, 0}, Route{RouteStatus::none, kNoNode, 0, SimTime{800'000'000}}}};
  return result;
}

TEST(SensingTrace, WritesEveryFieldOfEveryRecordInTheResultsOrder) {
  std::ostringstream out;
  SensingTraceWriter writer(&out);
  ASSERT_TRUE(writer.enabled());
  writer.record(hand_built_result(), SimTime{800'000'000});
  writer.finish();
  EXPECT_EQ(out.str(),
            "step,window_end_ns,robot,record,peer,time_ns,port,message_id,status,reason,next_hop,"
            "hops,attempts,frames,unicasts,first_attempt_acks,rssi_dbm,rssi_smoothed_dbm,sinr_db\n"
            "7,800000000,0,neighbor,1,712000001,,,,,,,,3,2,1,-60.5,-71.25,0.1\n"
            "7,800000000,0,neighbor,2,799999999,,,,,,,,3,2,1,-88,-71.25,0.1\n"
            "7,800000000,2,neighbor,0,700000000,,,,,,,,3,0,0,-1e-07,-71.25,inf\n"
            "7,800000000,2,report,,703000000,9,41,acknowledged,,1,,2,,,,,,\n"
            "7,800000000,0,report,,704000000,9,42,sent,,-1,,0,,,,,,\n"
            "7,800000000,1,report,,750000000,65535,18446744073709551615,dropped,buffer_timeout,,,0,"
            ",,,,,\n"
            "7,800000000,0,route,2,800000000,,,valid,,1,2,,,,,,,\n"
            "7,800000000,1,route,0,800000000,,,none,,,0,,,,,,,\n");
}

TEST(SensingTrace, EveryRowHasTheHeadersColumns) {
  std::ostringstream out;
  SensingTraceWriter writer(&out);
  writer.record(hand_built_result(), SimTime{800'000'000});
  writer.finish();
  std::istringstream lines(out.str());
  std::string line;
  std::size_t rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 18) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 9U);
}

TEST(SensingTrace, AppendsWindowAfterWindowAndWritesNothingForAnEmptyOne) {
  std::ostringstream out;
  SensingTraceWriter writer(&out);
  StepResult empty;
  empty.step = 0;
  writer.record(empty, SimTime{100});
  StepResult routes;
  routes.step = 1;
  routes.routes = {{RouteQuery{3, 4}, Route{RouteStatus::not_tracked, kNoNode, 0, SimTime{200}}}};
  writer.record(routes, SimTime{200});
  writer.flush();
  EXPECT_EQ(out.str(), std::string(SensingTraceWriter::kHeader) +
                           "1,200,3,route,4,200,,,not_tracked,,,0,,,,,,,\n");
}

TEST(SensingTrace, WithoutAStreamWritesNothing) {
  SensingTraceWriter writer(nullptr);
  EXPECT_FALSE(writer.enabled());
  writer.record(hand_built_result(), SimTime{800'000'000});
  writer.finish();
}

}  // namespace
}  // namespace swarmnet
