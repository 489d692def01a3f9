// Every application message the controllers sent, as CSV, so the same traffic can be replayed:
//   message_id,step,inject_ns,source,destination,payload_bytes
// inject_ns is when the network half takes the message in (step start plus its jitter);
// destination is the robot id, or "broadcast".
//
// Two more files are opened only when their first row is written, so that a run that needs
// neither writes exactly what it always did:
// - messages sent with options (SendOptions: a hop limit, a report) get a row in the first:
//     message_id,hop_limit,report
//   report is 0 or 1. With `ports` (a run that writes its sensing trace, whose send reports name
//   the port they are for), a fourth column holds the sending controller's port, so a replay
//   addresses each report as the run did:
//     message_id,hop_limit,report,port
// - every route query a controller made (RobotContext::route_to), one row per StepBatch query
//   in the batch's order (ascending by robot, then destination, within a step), in the second:
//     step,robot,destination
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string_view>
#include <utility>

#include "protocol/step_data.hpp"

namespace swarmnet {

class TrafficScheduleWriter {
 public:
  // Opens one of the files written only once a row needs it; called at most once.
  using Open = std::function<std::ostream&()>;

  // `open_send_options` opens the send options' file, `open_route_queries` the route queries'.
  // Without one, those rows are not written. `ports`: the send options carry the port column.
  TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step,
                        Open open_send_options = {}, Open open_route_queries = {},
                        bool ports = false);
  void write(const StepBatch& batch);

 private:
  // A CSV file opened, and its header written, when its first row is.
  class LazyFile {
   public:
    LazyFile(Open open, std::string_view header) : open_(std::move(open)), header_(header) {}
    [[nodiscard]] bool wanted() const { return static_cast<bool>(open_); }
    // The stream, opened with its header at the first call. Only when wanted().
    std::ostream& stream();

   private:
    Open open_;
    std::string_view header_;
    std::ostream* out_ = nullptr;
  };

  std::ostream& out_;
  std::uint64_t seed_;
  SimTime step_;
  bool ports_;
  LazyFile send_options_;
  LazyFile route_queries_;
};

}  // namespace swarmnet
