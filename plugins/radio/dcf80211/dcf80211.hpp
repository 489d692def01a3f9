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

  // The MSDU being sent, with its retry counters.
  struct Exchange {
    Packet packet;
    NodeId next_hop;
    std::uint16_t sequence;
    bool use_rts;
    std::uint32_t short_retries = 0;  // failed attempts counted against short_retry_limit
    std::uint32_t long_retries = 0;   // failed data attempts after a CTS (long_retry_limit)
    bool retry = false;
  };

  void start_exchange_if_needed(bool fresh_arrival);
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
  bool report_every_drop_;  // link_failure_reports: every_drop (ns-3) or retry_limit

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
