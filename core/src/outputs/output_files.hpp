// The files of a run directory (DESIGN.md section 6).
#pragma once

namespace swarmnet {

inline constexpr const char* kSummaryFile = "summary.json";
inline constexpr const char* kResolvedScenarioFile = "scenario.resolved.yaml";
inline constexpr const char* kLogFile = "run.log";
inline constexpr const char* kPacketTraceFile = "packets.csv";
inline constexpr const char* kFrameTraceFile = "frames.csv";  // network/frame_trace.hpp
// What the network half handed the controllers to sense (network/sensing_trace.hpp).
inline constexpr const char* kSensingTraceFile = "sensing.csv";
inline constexpr const char* kMobilityTraceFile = "mobility.ns2";
inline constexpr const char* kPositionsTraceFile = "positions.bin";  // outputs/positions_trace.hpp
inline constexpr const char* kHeadingsTraceFile = "headings.bin";    // outputs/headings_trace.hpp
inline constexpr const char* kTrafficScheduleFile = "traffic.csv";
// The traffic's send options, when a message had any (outputs/traffic_schedule.hpp).
inline constexpr const char* kSendOptionsFile = "send_options.csv";
// The controllers' route queries, when one asked (outputs/traffic_schedule.hpp).
inline constexpr const char* kRouteQueriesFile = "route_queries.csv";
inline constexpr const char* kObjectTraceFile = "objects.csv";  // outputs/object_trace.hpp
// What plugins asked the viewer to show (robot/view_record.hpp); only when one did.
inline constexpr const char* kViewStatesFile = "view_states.csv";
// What controllers record(), per robot (robot/robot_metrics.hpp); only when one recorded.
inline constexpr const char* kRobotMetricsFile = "robot_metrics.csv";
// What controllers and worlds sample() (robot/metric_series.hpp); only when one sampled.
inline constexpr const char* kSeriesFile = "series.csv";
// The replay page `swarmnet view` and `swarmnet run --view` write (docs/viewer.md).
inline constexpr const char* kViewPageFile = "view.html";

}  // namespace swarmnet
