// The files of a run directory (DESIGN.md section 6).
#pragma once

namespace swarmnet {

inline constexpr const char* kSummaryFile = "summary.json";
inline constexpr const char* kResolvedScenarioFile = "scenario.resolved.yaml";
inline constexpr const char* kLogFile = "run.log";
inline constexpr const char* kPacketTraceFile = "packets.csv";
inline constexpr const char* kMobilityTraceFile = "mobility.ns2";
inline constexpr const char* kPositionsTraceFile = "positions.bin";  // outputs/positions_trace.hpp
inline constexpr const char* kTrafficScheduleFile = "traffic.csv";
inline constexpr const char* kObjectTraceFile = "objects.csv";  // outputs/object_trace.hpp

}  // namespace swarmnet
