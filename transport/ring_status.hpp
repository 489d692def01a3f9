// Outcomes of ring and transport operations. The ring never throws: callers decide.
#pragma once

#include <cstdint>

namespace swarmnet {

enum class IoStatus : std::uint8_t {
  ok,
  would_block,  // try_* only: the ring is full (push) or empty (pop)
  closed,       // the peer closed its end; nothing more will come
  timeout,      // the deadline passed while waiting
  peer_dead,    // the liveness check reported the peer gone
  too_large,    // the record is longer than the channel ever takes
  corrupt,      // the ring's contents break the framing rules
};

inline const char* to_string(IoStatus status) {
  switch (status) {
    case IoStatus::ok:
      return "ok";
    case IoStatus::would_block:
      return "would block";
    case IoStatus::closed:
      return "closed by the peer";
    case IoStatus::timeout:
      return "timed out";
    case IoStatus::peer_dead:
      return "peer died";
    case IoStatus::too_large:
      return "record too long for the channel";
    case IoStatus::corrupt:
      return "corrupt framing";
  }
  return "?";
}

}  // namespace swarmnet
