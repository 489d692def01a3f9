// A run directory read into what the viewer page draws (docs/viewer.md): a small JSON
// description (`meta`) and one binary blob of typed arrays that the page decodes without
// parsing text.
//
// Read from the run directory:
//   scenario.resolved.yaml  required: arena (size, obstacles, objects), robot radius, step
//   positions.bin           required: every robot's position at every step
//   headings.bin            optional: every robot's heading (runs before it existed: the
//                           direction of motion stands in)
//   summary.json            required: what ran (robots, steps, packets, pdr); its absence says the
//                           run did not finish
//   packets.csv             optional: messages (send, forward, deliver, drop)
//   view_states.csv         optional: robot states and world objects plugins showed
//   objects.csv             optional: poses of the arena's movable objects
//   series.csv              optional: what plugins sampled, binned for the panel's chart as
//                           meta.series = {bin_s, series: [{name, mean, low, high}], not_shown}
// Every problem (missing, truncated or malformed file) is a RunError naming the file, and the
// line where there is one.
//
// Decimation: positions are kept every `stride` steps so that frames x robots stays within
// ViewLimits::robot_frames; the page interpolates between frames. Packet events beyond
// ViewLimits::packet_events are thinned evenly (every k-th kept; meta.events.kept_every = k); the
// delivery figures of the panel are computed from every line before thinning.
//
// The blob: arrays one after another, each starting at a multiple of 4 bytes, little-endian;
// meta.arrays names each: {"name": [byte_offset, element_count, "Float32"|"Uint32"|...]}.
//   pos      Uint16 [frames][robots][2]  x / width * 65535, y / height * 65535 (rounded, clamped)
//   heading  Uint8  [frames][robots]     heading * 256 / 2pi (headings.bin, else the direction
//                                        of the last motion; meta.headings says which)
//   state    Uint8  [frames][robots]     index into meta.states (0 = none); only with states
//   obj_t, obj_x, obj_y, obj_r Float32, obj_id Uint32, obj_kind, obj_state Uint16 [rows]: the
//            world objects' changes in time order (obj_state 65535 = hidden)
//   mov      Float32 [frames][movables][3] x, y, heading of the arena's movable objects
//   ev_t Float32 [events] (s), ev_from, ev_to Uint32, ev_kind Uint8 (0 send, 1 forward,
//            2 deliver, 3 drop), ev_reason Uint8 (index into meta.events.reasons): packet
//            events of data messages in time order; ev_from is the inferred previous hop
//   r_sent, r_recv, r_fwd, r_drop Uint32 [robots]: per-robot message counts over the run
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

namespace swarmnet {

struct ViewLimits {
  std::size_t robot_frames = 4'000'000;  // frames x robots kept at most
  std::size_t packet_events = 400'000;   // packet events kept at most
  std::size_t max_frames = 20'000;       // frames kept at most, whatever the swarm's size
  std::size_t series = 32;               // series of series.csv the chart offers at most
};

struct ViewData {
  nlohmann::ordered_json meta;
  std::vector<std::uint8_t> blob;
};

// Reads `run_dir`; throws RunError naming the file at fault.
ViewData read_view_data(const std::filesystem::path& run_dir, const ViewLimits& limits = {});

}  // namespace swarmnet
