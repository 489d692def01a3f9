// `dcf80211`: the IEEE 802.11a Distributed Coordination Function, with ns-3.37's 802.11a ad hoc
// defaults. The transmit state machine lives here; timing, channel access (backoff), the
// interface queue and the frame formats are the units beside it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "channel_access.hpp"
#include "contention_window.hpp"
#include "dcf_timing.hpp"
#include "interface_queue.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::dcf80211 {

class Dcf80211 final : public Mac {
 public:
  static PluginInfo info();
  explicit Dcf80211(const PluginArgs& args);

  void attach(MacContext& context) override;
  // An ACK ends every unicast exchange: MacContext::acknowledged() reports it.
  [[nodiscard]] bool acknowledges_unicasts() const override { return true; }
  void enqueue(Packet packet, NodeId next_hop) override;
  void on_transmit_end() override;
  void on_receive(const Frame& frame, const RxInfo& info) override;
  void on_receive_error() override;
  void on_medium_busy() override;
  void on_medium_idle() override;

  [[nodiscard]] const DcfTiming& timing() const { return timing_; }

 private:
  enum class Await : std::uint8_t { none, cts, ack };
  enum class TxKind : std::uint8_t { data, rts, response };

  // Failed attempts counted against short_retry_limit (RTS, or data sent without RTS) and
  // long_retry_limit (data after a CTS).
  struct RetryCounts {
    std::uint32_t short_count = 0;
    std::uint32_t long_count = 0;
  };

  // The MSDU being sent. Its retry counts are used with retry_counters: per_packet.
  struct Exchange {
    Packet packet;
    NodeId next_hop;
    SimTime enqueued_at;
    std::uint16_t sequence;
    bool use_rts;
    RetryCounts retries{};
    std::uint32_t failed_attempts = 0;  // RTS or data attempts that went unanswered
    bool retry = false;
    bool in_progress = false;  // an attempt is on the air or awaiting its response
    // Its lifetime ran out during an attempt (mpdu_lifetime: ns3): it was reported dropped and
    // left the queue; the attempt runs to its end, but the packet is not sent again.
    bool expired = false;
  };

  void start_exchange_if_needed(bool fresh_arrival);
  // Makes the oldest packet that has not expired the exchange (false: none waits).
  bool take_next_exchange(std::vector<InterfaceQueue::Item>& expired);
  // mpdu_lifetime: ns3 — removes every packet whose lifetime has run out, the exchange's
  // included, as ns-3.37's WifiMacQueue::WipeAllExpiredMpdus, and returns them to be reported.
  std::vector<InterfaceQueue::Item> wipe_expired();
  // The counts the limits apply to: the station's or the exchange's (retry_counters).
  RetryCounts& retry_counts();
  void schedule_access();
  void access_granted();
  void send_data();
  void send_after_sifs(Frame frame, TxKind kind);
  void transmit(Frame frame, TxKind kind);
  void response_timeout();
  void resolve_late_timeout();
  void exchange_failed();
  void exchange_finished();
  void new_backoff();
  // Discards `packet` (to `next_hop`) for `reason` and, for a unicast packet, tells routing as
  // link_failure_reports says (ns-3's DroppedMpdu: every drop; or at the retry limit only).
  void drop_mpdu(const Packet& packet, NodeId next_hop, DropReason reason);
  void drop_expired(const std::vector<InterfaceQueue::Item>& expired);
  [[nodiscard]] SimTime now() const { return context_->now(); }

  MacContext* context_ = nullptr;
  DcfTiming timing_;
  ChannelAccess access_;
  ContentionWindow cw_;
  InterfaceQueue queue_;
  RandomStream random_;
  std::uint32_t header_bytes_;
  std::uint32_t rts_threshold_bytes_;
  std::uint32_t short_retry_limit_;
  std::uint32_t long_retry_limit_;
  bool report_every_drop_;     // link_failure_reports: every_drop (ns-3) or retry_limit
  bool ns3_lifetime_;          // mpdu_lifetime: ns3 (wipes at arrival, access, retry) or at_head
  bool station_retry_counts_;  // retry_counters: station (ns-3.37) or per_packet
  RetryCounts station_retries_;

  std::optional<Exchange> exchange_;
  bool access_requested_ = false;
  bool transmitting_ = false;
  TxKind tx_kind_ = TxKind::data;
  Await awaiting_ = Await::none;
  bool timeout_pending_busy_ = false;  // the response timeout fired while a frame was arriving
  TimerId access_timer_ = kNoTimer;
  TimerId timeout_timer_ = kNoTimer;
  TimerId sifs_timer_ = kNoTimer;
  std::uint16_t next_sequence_ = 0;
  std::map<NodeId, std::uint16_t> last_sequence_;  // duplicate detection, per transmitter
};

}  // namespace swarmnet::dcf80211
