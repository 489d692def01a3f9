"""ns-3.37's 802.11 MAC as SwarmNet's `dcf80211` plugin describes it: the parameters that make the
plugin behave as ns-3.37's WifiMacQueue and WifiRemoteStationManager do where the plugin's
defaults do otherwise (docs/plugins.md, dcf80211's link feedback;
docs/history/validation-journal.md, "The 150-robot row with ns-3's MAC rules").

- mpdu_lifetime: ns3. The queue's MaxDelay (500 ms) applies to every MPDU, the one being
  retried included, and expired MPDUs are removed at every arrival, channel access and release
  (WifiMacQueue::WipeAllExpiredMpdus); an expiry is a DroppedMpdu, which AODV takes as a
  broken link. The plugin's default checks a packet's wait only when it reaches the head.
- retry_counters: station. The short and long retry counts are the station's (m_ssrc, m_slrc),
  not the packet's: reset by an ACK, a CTS or a drop at the limit, not by an expiry.

Both rules act only when a packet outlives MaxDelay: in runs whose queues never wait 500 ms the
plugin's result is byte for byte the same with or without them. The validation grid gives them
to SwarmNet's side so that both sides run the same MAC.
"""

NS3_DCF80211_RULES = {
    "mpdu_lifetime": "ns3",
    "retry_counters": "station",
}


def set_arguments(prefix="network.mac.params"):
    """The rules as `swarmnet run` --set arguments."""
    return [arg for name, value in NS3_DCF80211_RULES.items()
            for arg in ("--set", f"{prefix}.{name}={value}")]
