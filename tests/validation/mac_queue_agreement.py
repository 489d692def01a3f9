#!/usr/bin/env python3
"""The MAC queue's drops in SwarmNet and ns-3 on the same tiny traces (issue 19's test).

Two nodes in range (tiny_traces.py's pockets, 100 m apart), `direct` routing. A first message
resolves ARP; 0.3 s later a burst of 40 messages is handed down within microseconds of one
another, faster than the MAC can send them. SwarmNet's dcf80211 and ns-3.37's WifiMacQueue are
set alike on both sides (`queue_limit` / `--queue-packets`, `queue_max_delay_s` /
`--queue-max-delay-s`):

  full     a queue of 10 packets and no queue discipline above ns-3's MAC (`--queue-disc
           none`, as in SwarmNet): the 10 first of the burst are queued and delivered, the 30
           others dropped at a full queue, the same messages on both sides. (SwarmNet:
           queue_full. ns-3: the traffic-control layer's TcDrop, since the device stops taking
           packets while its MAC queue is full; WifiMacQueue's own DropBeforeEnqueue is counted
           too.)
  in_flight the same, with one message handed down 0.3 to 0.5 ms before the burst, whose
           frame and ACK are still on the air when the burst comes: ns-3.37 keeps that MPDU in
           the queue until its exchange ends, so 9 of the burst find a place, and SwarmNet does
           the same. (A broadcast gives its place up as it goes on the air, in both; SwarmNet's
           unit test Dcf80211LinkFeedback.ABroadcastGivesItsPlaceUpAsItGoesOnTheAir.)
  expired  ns-3's 500 packets and a MaxDelay of 15 ms: the queue holds the whole burst, the MAC
           sends about one 512-byte frame (with its ACK) a millisecond, and what has waited
           longer than 15 ms when it reaches the head is dropped (SwarmNet: buffer_timeout;
           ns-3: the queue's Expired trace). The counts agree within one: each side draws its
           backoffs from its own stream, and a frame may cross the 15 ms line on one side only.

With ns-3's default queue discipline (fq_codel, which Ipv4AddressHelper installs) the burst
would wait above the MAC instead of being dropped: that is ns-3 as users run it, and SwarmNet has
no queue discipline (docs/validation.md). These cases are what lets the validation grid read
ns-3's `queue_drops` beside SwarmNet's drop reasons (the saturated dense flooding row:
docs/history/validation-journal.md, "Where ns-3's discards go, traced", under "The one-hop and
flooding rows on the default stack"). Python standard library only.
"""
import functools
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tiny_traces as tt  # noqa: E402

BURST = 40
RESOLVE_ID = tt.SINGLE_IDS  # the message that resolves ARP before the burst


def burst_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = tt.burst_ids(BURST)
    case.singles = [RESOLVE_ID]
    return ([(RESOLVE_ID, 20, source, destination)] +  # t = 0.2 s
            [(m, 50, source, destination) for m in case.burst])  # t = 0.5 s


def lead_id(burst):
    """A message id injected 0.3 to 0.5 ms before the burst's first (in the same step): its
    frame (0.83 ms with its ACK at 6 Mbit/s) is still on the air when the burst comes."""
    start = min(tt.injection_offset_ns(m) for m in burst)
    found = next((i for i in range(tt.SINGLE_IDS + 1, tt.SINGLE_IDS + 1_000_000)
                  if start - 500_000 < tt.injection_offset_ns(i) < start - 300_000), None)
    if found is None:
        raise RuntimeError(f"no message id is injected 0.3 to 0.5 ms before the burst (at "
                           f"{start} ns into its step)")
    return found


def in_flight_traffic(case):
    rows = burst_traffic(case)
    source, destination = case.order[0], case.order[-1]
    return rows + [(lead_id(case.burst), 50, source, destination)]


def queue_figures(case):
    """(SwarmNet's, ns-3's) queue drops of the burst, named alike."""
    dropped = case.summary["packets"]["dropped"]
    ns3 = case.replay["mac"]["queue_drops"]
    return ({"full": dropped.get("queue_full"), "expired": dropped.get("buffer_timeout")},
            {"full": ns3["full"] + ns3["traffic_control"], "expired": ns3["expired"]})


def by_hand_down(case):
    return sorted(case.burst, key=lambda m: (case.ns3[m]["inject"], m))


def delivered(side, messages):
    return [m for m in messages if tt.delay_ns(side, m) is not None]


def common_problems(case):
    problems = []
    sn, ns3 = queue_figures(case)
    print(f"  queue drops  SwarmNet {sn}\n               ns-3     {ns3}")
    if tt.delay_ns(case.sn, RESOLVE_ID) is None or tt.delay_ns(case.ns3, RESOLVE_ID) is None:
        problems.append("the first message (ARP's resolution) was not delivered on both sides")
    arp_requests = case.replay["arp"]["requests_sent"]
    if arp_requests != 1:
        problems.append(f"ns-3 sent {arp_requests} ARP requests (expected 1, before the burst)")
    return problems, sn, ns3


def full_problems(case, places):
    """The `places` first of the burst delivered on both sides, the others dropped at a full
    queue."""
    problems, sn, ns3 = common_problems(case)
    expected = {"full": BURST - places, "expired": 0}
    if sn != expected or ns3 != expected:
        problems.append(f"queue drops: SwarmNet {sn}, ns-3 {ns3}, expected {expected} on both")
    first = by_hand_down(case)[:places]
    for side_name, side in (("SwarmNet", case.sn), ("ns-3", case.ns3)):
        got = delivered(side, case.burst)
        if sorted(got) != sorted(first):
            problems.append(f"{side_name} delivered {sorted(got)} of the burst, expected the "
                            f"{places} first handed down {sorted(first)}")
    return problems


def check_full(case):
    return full_problems(case, 10)


def check_in_flight(case):
    problems = full_problems(case, 9)
    lead = lead_id(case.burst)
    if tt.delay_ns(case.sn, lead) is None or tt.delay_ns(case.ns3, lead) is None:
        problems.append(f"the lead message {lead} was not delivered on both sides")
    elif case.ns3[lead]["deliver"] <= min(case.ns3[m]["inject"] for m in case.burst):
        problems.append("ns-3 delivered the lead message before the burst came: nothing was "
                        "in flight, the case tests nothing")
    return problems


def check_expired(case):
    problems, sn, ns3 = common_problems(case)
    if sn["full"] != 0 or ns3["full"] != 0:
        problems.append(f"a queue of 500 packets was full: SwarmNet {sn}, ns-3 {ns3}")
    if not 10 <= ns3["expired"] <= BURST - 10:
        problems.append(f"ns-3 dropped {ns3['expired']} of {BURST} as expired: the burst did not "
                        "outlast the 15 ms wait, the case tests nothing")
    if abs(sn["expired"] - ns3["expired"]) > 1:
        problems.append(f"expired: SwarmNet {sn['expired']}, ns-3 {ns3['expired']} (more than one "
                        "apart)")
    for side_name, side, figures in (("SwarmNet", case.sn, sn), ("ns-3", case.ns3, ns3)):
        got = delivered(side, case.burst)
        if len(got) + figures["expired"] != BURST:
            problems.append(f"{side_name}: {len(got)} of the burst delivered and "
                            f"{figures['expired']} expired, of {BURST}")
    return problems


XS = [50.0, 150.0]
QUEUE_OF_10 = (["network.mac.params.queue_limit=10"],
               ["--queue-packets", "10", "--queue-disc", "none"])
CASES = [
    ("full", *QUEUE_OF_10, burst_traffic, check_full),
    ("in_flight", *QUEUE_OF_10, in_flight_traffic, check_in_flight),
    ("expired", ["network.mac.params.queue_max_delay_s=0.015"], ["--queue-max-delay-s", "0.015"],
     burst_traffic, check_expired),
]


def main():
    cases = [(name, f"2 nodes, routing direct, a burst of {BURST}",
              functools.partial(tt.run_case, name=name, xs=XS, routing="direct", duration_s=1.0,
                                traffic=traffic, sets=sets, ns3_options=ns3_options), check)
             for name, sets, ns3_options, traffic, check in CASES]
    return tt.run_cases(__doc__.split("\n")[0], cases)


if __name__ == "__main__":
    sys.exit(main())
