// The DCF's frames: data (with the MSDU), ACK, RTS and CTS, with their sizes and duration fields.
#pragma once

#include <cstdint>

#include "dcf_timing.hpp"
#include "swarmnet/packet.hpp"

namespace swarmnet::dcf80211 {

// A data frame carrying `packet` to `receiver` (kBroadcast: no ACK, NAV 0).
Frame make_data(Packet packet, NodeId receiver, std::uint32_t header_bytes, std::uint16_t sequence,
                bool retry, const DcfTiming& timing);
Frame make_ack(NodeId receiver, const DcfTiming& timing);
// An RTS announcing a data frame of `data_mpdu_bytes`.
Frame make_rts(NodeId receiver, std::uint32_t data_mpdu_bytes, const DcfTiming& timing);
// The CTS answering `rts`.
Frame make_cts(const Frame& rts, const DcfTiming& timing);

// Time on the air of a frame made by the functions above.
SimTime airtime(const Frame& frame, const DcfTiming& timing);

}  // namespace swarmnet::dcf80211
