#include "dcf80211.hpp"

#include <utility>

#include "frame_format.hpp"

namespace swarmnet::dcf80211 {

PluginInfo Dcf80211::info() {
  return PluginInfo{
      "dcf80211",
      "1.0.0",
      "IEEE 802.11a DCF: CSMA/CA with binary exponential backoff, ACKs, retries, RTS/CTS, NAV",
      "The 802.11 Distributed Coordination Function over 802.11a OFDM timing, with the defaults "
      "of ns-3.37's 802.11a ad hoc MAC (AdhocWifiMac, ConstantRateWifiManager at 6 Mbit/s).\n"
      "Timing: slot 9 us, SIFS 16 us, DIFS = SIFS + 2 slots (34 us), EIFS = SIFS + ACK at the "
      "control rate + DIFS (94 us at 6 Mbit/s). Frame durations: 16 us preamble + 4 us PLCP "
      "header + 4 us symbols carrying 16 + 8 * bytes + 6 bits.\n"
      "Access (as ns-3.37's ChannelAccessManager): a packet arriving at an idle station whose "
      "backoff is 0 while the medium is idle is sent once the medium has stayed idle for DIFS "
      "from its arrival (and for DIFS, EIFS after a failed reception, from the last busy "
      "period); if the medium is busy at its arrival the station backs off a uniform number of "
      "slots in [0, CW], counted only in idle slots after DIFS/"
      "EIFS and frozen while the medium is busy (physically, or virtually by the NAV from other "
      "stations' duration fields). CW starts at cw_min, becomes 2 (CW + 1) - 1 up to cw_max after "
      "each failure and is reset after a success or a drop; a new backoff is drawn after every "
      "exchange (post-backoff) and at start.\n"
      "Unicast data is acknowledged after SIFS; if no ACK has started within the ACK timeout "
      "(SIFS + slot + 20 us), the attempt failed (mac.ack_timeouts). Data frames larger than "
      "rts_threshold_bytes (MPDU bytes) are preceded by RTS/CTS (CTS timeout likewise). "
      "Failed RTS and data sent without RTS count against short_retry_limit, data after a CTS "
      "against long_retry_limit (attempts, as ns-3's MaxSsrc/MaxSlrc); at the limit the packet "
      "is dropped (retry_limit). With retry_counters: per_packet (the default) each packet "
      "starts from zero; with station the counts belong to the station, as ns-3.37's "
      "WifiRemoteStationManager keeps them: reset by an ACK, a CTS or a drop at the limit, but "
      "not when a packet expires, so the next packet has only the attempts that remain. Broadcasts "
      "are sent once, without RTS or ACK. Duplicates "
      "(retries of an already received sequence number) are acknowledged but not delivered "
      "twice.\n"
      "Queue: a FIFO of queue_limit places, taken by the waiting packets and by the packet of the "
      "exchange under way until it is acknowledged or dropped (a broadcast: until it goes on the "
      "air), as in ns-3's WifiMacQueue. A packet that waited longer than queue_max_delay_s "
      "is dropped (buffer_timeout). With mpdu_lifetime: at_head (the default) this is checked "
      "as a packet reaches the head, and the packet being sent never expires. With ns3 it is "
      "checked as ns-3.37 does, at every arrival, channel access and release, for the packet "
      "being sent too: one that expires while it waits for access gives the access to the next "
      "packet (same backoff, same contention window); one that expires during an attempt is "
      "reported then and not sent again. A packet arriving at a full queue first has "
      "the expired packets removed, then is dropped (queue_full) if the queue is still full, "
      "like ns-3's WifiMacQueue (500 packets, 500 ms).\n"
      "Link feedback: routing hears of a dropped unicast packet through link_failed(packet, "
      "next_hop) (\"the MAC dropped a unicast MPDU to next_hop\"), ARP packets included. With "
      "link_failure_reports: every_drop (the default) every such drop is reported, at the retry "
      "limit, at a full queue and at an expired wait, as ns-3.37's WifiMac DroppedMpdu trace "
      "(which ns-3's AODV listens to) fires for all three; retry_limit reports only the retry "
      "limit (SwarmNet's rule before, an unacknowledged frame only). Broadcast drops are never "
      "reported.\n"
      "Frames: data frames carry header_bytes (MAC header 24 + FCS 4 + LLC/SNAP 8 = 36, as ns-3) "
      "above the packet; ACK and CTS are 14 bytes, RTS 20, sent at control_rate_bps.\n"
      "Counters: retries, ack_timeouts, cts_timeouts, rts, cts, acks (frames sent), duplicates; "
      "the kernel adds tx_frames, tx_bytes and collisions (frames lost to interference).",
      {
          real_param("data_rate_bps", 6.0e6, "bit/s",
                     "rate of data frames: 6, 9, 12, 18, 24, 36, 48 or 54 Mbit/s", 6.0e6, 54.0e6),
          real_param("control_rate_bps", 6.0e6, "bit/s", "rate of ACK, RTS and CTS frames", 6.0e6,
                     54.0e6),
          real_param("slot_s", 9e-6, "s", "slot time", 1e-9, 1.0),
          real_param("sifs_s", 16e-6, "s", "short interframe space", 1e-9, 1.0),
          integer_param("cw_min", 15, "slots", "initial contention window", 0, 65535),
          integer_param("cw_max", 1023, "slots", "largest contention window", 0, 65535),
          integer_param("short_retry_limit", 7, "attempts",
                        "attempts of an RTS, or of data sent without RTS", 1, 255),
          integer_param("long_retry_limit", 4, "attempts", "attempts of data sent after a CTS", 1,
                        255),
          integer_param("rts_threshold_bytes", 65535, "B",
                        "data MPDUs larger than this use RTS/CTS (65535: never, ns-3's default)", 0,
                        65535),
          integer_param("queue_limit", 500, "packets", "interface queue capacity", 1, 10000000),
          real_param("queue_max_delay_s", 0.5, "s", "longest wait in the queue", 0.0, 1.0e9),
          text_param("mpdu_lifetime", "at_head",
                     "when queue_max_delay_s is applied: ns3 (ns-3.37's WifiMacQueue: expired "
                     "packets are removed at every arrival, channel access and release, the one "
                     "being sent included) or at_head (only as a packet reaches the head of the "
                     "queue or meets a full queue; the packet being sent never expires)",
                     {"ns3", "at_head"}),
          text_param("retry_counters", "per_packet",
                     "what the retry limits count: station (ns-3.37's SSRC/SLRC: one short and "
                     "one long count per station, reset by an ACK, a CTS or a drop at the limit "
                     "but not by an expiry) or per_packet (each packet starts from zero)",
                     {"station", "per_packet"}),
          text_param("link_failure_reports", "every_drop",
                     "which drops of a unicast packet routing hears of (link_failed): every_drop "
                     "(retry limit, full queue, expired wait: ns-3's DroppedMpdu) or retry_limit "
                     "(only after the retries)",
                     {"every_drop", "retry_limit"}),
          integer_param("header_bytes", 36, "B",
                        "bytes a data frame adds to the packet (MAC header, FCS, LLC/SNAP)", 0,
                        65535),
      }};
}

Dcf80211::Dcf80211(const PluginArgs& args)
    : timing_(from_seconds(args.params.real("slot_s")), from_seconds(args.params.real("sifs_s")),
              args.params.real("data_rate_bps"), args.params.real("control_rate_bps")),
      access_(timing_),
      cw_(static_cast<std::uint32_t>(args.params.integer("cw_min")),
          static_cast<std::uint32_t>(args.params.integer("cw_max"))),
      queue_(static_cast<std::size_t>(args.params.integer("queue_limit")),
             from_seconds(args.params.real("queue_max_delay_s"))),
      random_(args.seed),
      header_bytes_(static_cast<std::uint32_t>(args.params.integer("header_bytes"))),
      rts_threshold_bytes_(static_cast<std::uint32_t>(args.params.integer("rts_threshold_bytes"))),
      short_retry_limit_(static_cast<std::uint32_t>(args.params.integer("short_retry_limit"))),
      long_retry_limit_(static_cast<std::uint32_t>(args.params.integer("long_retry_limit"))),
      report_every_drop_(args.params.text("link_failure_reports") == "every_drop"),
      ns3_lifetime_(args.params.text("mpdu_lifetime") == "ns3"),
      station_retry_counts_(args.params.text("retry_counters") == "station") {}

void Dcf80211::attach(MacContext& context) {
  context_ = &context;
  new_backoff();  // like ns-3's Txop, a backoff is drawn at start
}

void Dcf80211::new_backoff() { access_.set_backoff(now(), cw_.draw(random_)); }

void Dcf80211::drop_mpdu(const Packet& packet, NodeId next_hop, DropReason reason) {
  context_->drop(packet, reason);
  if (next_hop == kBroadcast) return;
  if (report_every_drop_ || reason == DropReason::retry_limit) {
    context_->link_failed(packet, next_hop);
  }
}

void Dcf80211::drop_expired(const std::vector<InterfaceQueue::Item>& expired) {
  for (const InterfaceQueue::Item& item : expired) {
    drop_mpdu(item.packet, item.next_hop, DropReason::buffer_timeout);
  }
}

Dcf80211::RetryCounts& Dcf80211::retry_counts() {
  return station_retry_counts_ ? station_retries_ : exchange_->retries;
}

std::vector<InterfaceQueue::Item> Dcf80211::wipe_expired() {
  std::vector<InterfaceQueue::Item> expired;
  // The exchange is still queued while it holds its place: a broadcast gives it up as it goes on
  // the air, an exchange that expired during its attempt when it expired.
  if (exchange_ && queue_.holds_place() && queue_.outlived(exchange_->enqueued_at, now())) {
    expired.push_back(
        InterfaceQueue::Item{exchange_->packet, exchange_->next_hop, exchange_->enqueued_at});
    queue_.release();
    if (exchange_->in_progress) {
      exchange_->expired = true;
    } else {
      exchange_.reset();
    }
  }
  for (InterfaceQueue::Item& item : queue_.take_expired(now())) expired.push_back(std::move(item));
  // ns-3 sends whatever heads the queue when access comes: the access under way (if any) now
  // serves the next packet, with the backoff and contention window as they are.
  if (!exchange_) take_next_exchange(expired);
  return expired;
}

// Reports to routing may come back at once as new packets (a RERR): the queue's reports are made
// once the MAC's own state is settled.
void Dcf80211::enqueue(Packet packet, NodeId next_hop) {
  std::vector<InterfaceQueue::Item> expired;
  if (ns3_lifetime_) {
    // ns-3.37's Txop::Queue looks for frames to send, wiping expired ones, before it queues the
    // arrival; their drops are reported first, so that a RERR they cause is queued first.
    drop_expired(wipe_expired());
  } else if (queue_.full()) {
    // ns-3's WifiMacQueue::Insert: a full queue first drops its expired packets.
    expired = queue_.take_expired(now());
  }
  if (queue_.full()) {
    drop_expired(expired);
    drop_mpdu(packet, next_hop, DropReason::queue_full);
    return;
  }
  const bool idle_station = queue_.empty() && !exchange_;
  queue_.push(std::move(packet), next_hop, now());
  if (idle_station) start_exchange_if_needed(true);
  drop_expired(expired);
}

bool Dcf80211::take_next_exchange(std::vector<InterfaceQueue::Item>& expired) {
  auto item =
      queue_.pop(now(), [&expired](const InterfaceQueue::Item& old) { expired.push_back(old); });
  if (!item) return false;
  const std::uint32_t mpdu_bytes = header_bytes_ + item->packet.size_bytes();
  const bool use_rts = item->next_hop != kBroadcast && mpdu_bytes > rts_threshold_bytes_;
  exchange_ = Exchange{.packet = std::move(item->packet),
                       .next_hop = item->next_hop,
                       .enqueued_at = item->enqueued_at,
                       .sequence = next_sequence_++,
                       .use_rts = use_rts};
  return true;
}

void Dcf80211::start_exchange_if_needed(bool fresh_arrival) {
  if (exchange_) return;
  std::vector<InterfaceQueue::Item> expired;
  if (!take_next_exchange(expired)) {
    drop_expired(expired);
    return;
  }
  // 802.11-2016 10.3.4.2 as ns-3.37 applies it (ChannelAccessManager::NeedBackoffUponAccess):
  // a packet reaching an idle station whose backoff is 0 is sent without backoff if the medium
  // (physical or NAV) is idle now, after it stays idle for DIFS from now (and DIFS/EIFS after
  // the last busy period); if the medium is busy now, the station backs off.
  if (fresh_arrival && access_.backoff_slots(now()) == 0) {
    if (access_.busy() || access_.nav_end() > now()) {
      new_backoff();
    } else {
      access_.defer_until(now() + timing_.difs);
    }
  }
  access_requested_ = true;
  schedule_access();
  drop_expired(expired);
}

void Dcf80211::schedule_access() {
  if (access_timer_ != kNoTimer) {
    context_->cancel(access_timer_);
    access_timer_ = kNoTimer;
  }
  if (!access_requested_ || transmitting_ || awaiting_ != Await::none || sifs_timer_ != kNoTimer) {
    return;
  }
  const SimTime grant = access_.grant_time(now());
  if (grant == kTimeNever) return;
  access_timer_ = context_->schedule(grant - now(), [this] {
    access_timer_ = kNoTimer;
    access_granted();
  });
}

void Dcf80211::access_granted() {
  access_requested_ = false;
  // ns-3.37's FrameExchangeManager::StartTransmission wipes the expired packets first, then
  // sends the head of the queue; with none left it releases the channel with a new backoff.
  std::vector<InterfaceQueue::Item> expired;
  if (ns3_lifetime_) {
    expired = wipe_expired();
    if (!exchange_) new_backoff();
  }
  if (exchange_) {
    exchange_->in_progress = true;
    if (exchange_->use_rts) {
      context_->count("rts");
      transmit(
          make_rts(exchange_->next_hop, header_bytes_ + exchange_->packet.size_bytes(), timing_),
          TxKind::rts);
    } else {
      send_data();
    }
  }
  drop_expired(expired);
}

void Dcf80211::send_data() {
  // ns-3 dequeues a group-addressed MPDU as it goes on the air (no acknowledgment to wait for).
  if (exchange_->next_hop == kBroadcast) queue_.release();
  transmit(make_data(exchange_->packet, exchange_->next_hop, header_bytes_, exchange_->sequence,
                     exchange_->retry, timing_),
           TxKind::data);
}

void Dcf80211::transmit(Frame frame, TxKind kind) {
  const SimTime duration = airtime(frame, timing_);
  transmitting_ = true;
  tx_kind_ = kind;
  access_.medium_busy(now());
  context_->transmit(std::move(frame), duration);
}

void Dcf80211::send_after_sifs(Frame frame, TxKind kind) {
  if (sifs_timer_ != kNoTimer) return;  // one response at a time
  sifs_timer_ = context_->schedule(timing_.sifs, [this, frame = std::move(frame), kind]() mutable {
    sifs_timer_ = kNoTimer;
    if (transmitting_) return;
    transmit(std::move(frame), kind);
  });
  schedule_access();
}

void Dcf80211::on_transmit_end() {
  transmitting_ = false;
  if (!context_->medium_busy()) access_.medium_idle(now());
  if (tx_kind_ == TxKind::rts) {
    awaiting_ = Await::cts;
    timeout_timer_ = context_->schedule(timing_.cts_timeout, [this] { response_timeout(); });
  } else if (tx_kind_ == TxKind::data && exchange_) {
    if (exchange_->next_hop == kBroadcast) {
      exchange_finished();
      return;
    }
    awaiting_ = Await::ack;
    timeout_timer_ = context_->schedule(timing_.ack_timeout, [this] { response_timeout(); });
  }
  schedule_access();
}

void Dcf80211::response_timeout() {
  timeout_timer_ = kNoTimer;
  if (context_->medium_busy()) {
    // A frame is arriving: it may be the response. Decide when it ends.
    timeout_pending_busy_ = true;
    return;
  }
  exchange_failed();
}

void Dcf80211::resolve_late_timeout() {
  if (timeout_pending_busy_ && awaiting_ != Await::none) exchange_failed();
}

void Dcf80211::exchange_failed() {
  const Await stage = awaiting_;
  awaiting_ = Await::none;
  timeout_pending_busy_ = false;
  if (timeout_timer_ != kNoTimer) context_->cancel(timeout_timer_);
  timeout_timer_ = kNoTimer;
  context_->count(stage == Await::cts ? "cts_timeouts" : "ack_timeouts");
  ++exchange_->failed_attempts;
  access_.busy_until(now());
  RetryCounts& counts = retry_counts();
  const bool long_count = stage == Await::ack && exchange_->use_rts;
  std::uint32_t& count = long_count ? counts.long_count : counts.short_count;
  if (++count >= (long_count ? long_retry_limit_ : short_retry_limit_)) {
    count = 0;  // ns-3.37's ReportFinalDataFailed / ReportFinalRtsFailed
    // Routing hears of it while the exchange still stands, so that a packet it sends at once
    // (a RERR) queues behind the ones waiting; the dropped packet still holds its place then, as
    // ns-3 reports DroppedMpdu before it dequeues the MPDU.
    const Packet packet = exchange_->packet;
    const NodeId next_hop = exchange_->next_hop;
    context_->gave_up(packet, next_hop, exchange_->failed_attempts);
    if (exchange_->expired) {
      // Counted as dropped when it expired; ns-3's DroppedMpdu fires again at the limit.
      context_->link_failed(packet, next_hop);
    } else {
      drop_mpdu(packet, next_hop, DropReason::retry_limit);
    }
    exchange_finished();
    return;
  }
  context_->count("retries");
  cw_.failed();
  new_backoff();
  exchange_->retry = true;
  exchange_->in_progress = false;
  std::vector<InterfaceQueue::Item> expired;
  if (ns3_lifetime_) {
    // ns-3.37's Txop::NotifyChannelReleased: the backoff is drawn, then the expired packets are
    // wiped; access is requested only if a packet is left. An exchange that expired during the
    // attempt is not sent again: the next packet inherits the contention window.
    if (exchange_->expired) exchange_.reset();
    expired = wipe_expired();
  }
  if (exchange_) {
    access_requested_ = true;
    schedule_access();
  }
  drop_expired(expired);
}

void Dcf80211::exchange_finished() {
  exchange_.reset();
  queue_.release();
  awaiting_ = Await::none;
  timeout_pending_busy_ = false;
  cw_.reset();
  new_backoff();
  start_exchange_if_needed(false);
  schedule_access();
}

void Dcf80211::on_receive(const Frame& frame, const RxInfo& /*info*/) {
  access_.reception_ended(now(), true);
  const NodeId self = context_->node();
  if (frame.receiver != self) {
    if (frame.receiver == kBroadcast) {
      if (frame.type == FrameType::data && frame.packet) {
        context_->deliver(*frame.packet, frame.transmitter);
      }
    } else if (frame.nav > kTimeZero) {
      access_.set_nav(now(), now() + frame.nav);
    }
    resolve_late_timeout();
    schedule_access();
    return;
  }
  switch (frame.type) {
    case FrameType::data: {
      context_->count("acks");
      send_after_sifs(make_ack(frame.transmitter, timing_), TxKind::response);
      const auto last = last_sequence_.find(frame.transmitter);
      const bool duplicate =
          frame.retry && last != last_sequence_.end() && last->second == frame.sequence;
      last_sequence_[frame.transmitter] = frame.sequence;
      if (duplicate) {
        context_->count("duplicates");
      } else if (frame.packet) {
        context_->deliver(*frame.packet, frame.transmitter);
      }
      break;
    }
    case FrameType::rts:
      if (access_.nav_end() <= now() && !transmitting_ && sifs_timer_ == kNoTimer) {
        context_->count("cts");
        send_after_sifs(make_cts(frame, timing_), TxKind::response);
      }
      break;
    case FrameType::cts:
      if (awaiting_ == Await::cts && exchange_) {
        awaiting_ = Await::none;
        timeout_pending_busy_ = false;
        if (timeout_timer_ != kNoTimer) context_->cancel(timeout_timer_);
        timeout_timer_ = kNoTimer;
        if (station_retry_counts_) station_retries_.short_count = 0;  // ns-3's ReportRtsOk
        send_after_sifs(make_data(exchange_->packet, exchange_->next_hop, header_bytes_,
                                  exchange_->sequence, exchange_->retry, timing_),
                        TxKind::data);
      }
      break;
    case FrameType::ack:
      if (awaiting_ == Await::ack && exchange_) {
        if (timeout_timer_ != kNoTimer) context_->cancel(timeout_timer_);
        timeout_timer_ = kNoTimer;
        if (station_retry_counts_) {  // ns-3's ReportDataOk
          (exchange_->use_rts ? station_retries_.long_count : station_retries_.short_count) = 0;
        }
        context_->acknowledged(exchange_->packet, exchange_->next_hop,
                               exchange_->failed_attempts + 1);
        exchange_finished();
        return;
      }
      break;
  }
  resolve_late_timeout();
  schedule_access();
}

void Dcf80211::on_receive_error() {
  access_.reception_ended(now(), false);
  resolve_late_timeout();
  schedule_access();
}

void Dcf80211::on_medium_busy() {
  access_.medium_busy(now());
  schedule_access();
}

void Dcf80211::on_medium_idle() {
  access_.medium_idle(now());
  if (timeout_pending_busy_) {
    // The frame that ended may be the response; on_receive() follows at once if it was decoded.
    context_->schedule(kTimeZero, [this] { resolve_late_timeout(); });
  }
  schedule_access();
}

}  // namespace swarmnet::dcf80211

SWARMNET_PLUGIN(swarmnet::dcf80211::Dcf80211)
