#!/usr/bin/env python3
"""ARP's delay and drops in SwarmNet and ns-3 on the same tiny traces (issue 19's test).

Three cases, each a static scenario (configs/validation/small.yaml's radio and 802.11a stack, the
robots held in pockets between obstacles, about 100 m apart) whose traffic is written here, run
through SwarmNet's network half (`swarmnet replay`, network.arp: ns3) and through ns-3.37
(`swarmnet_ns3_replay`, its default stack with real ARP) on the same mobility and traffic:

  two   2 nodes in range, `direct`: a burst of 5 messages to the unresolved neighbour, then single
        messages. Both sides: one ARP request and one reply, 3 messages delivered after the
        exchange and the 2 last dropped for ARP's full pending queue (arp_queue_full); delays
        within ARP's request jitter (a whole number of ms, 0-9, that each simulator draws from its
        own stream) and, once the jitter is taken off, within one backoff; the later messages
        with no ARP frame and the same delay to a few microseconds.
  line  4 nodes on a line, `aodv` (ns-3's variant, validation_runner.routing_choice): a burst
        from one end to the other, then single messages. Equal ARP requests, replies and drops
        by reason; delays within 10 ms per jittered send (ARP requests and AODV RREQs) of each
        other; later messages to a few microseconds.
  far   2 nodes 200 m apart (out of range), `direct`: 4 requests (1 + 3 retries a second apart
        from the first lookup) and every message dropped, for the full pending queue or as
        unresolved (ns-3: retries exhausted, then the entry dead), equally on both sides.

In every case the messages ARP dropped, and why, are the same on both sides message by message
(ns-3's from the replay's --ip-trace: arp_drop events, their reason as the JSON counts it).

The five burst messages are handed down within 100 ns of one another: SwarmNet injects a
message at its step's start plus an offset hashed from the seed and its id
(core/src/protocol/step_data.hpp, injection_offset), so the burst takes five ids whose offsets
nearly coincide. SwarmNet's packet trace has no ARP frame, so its jitter is inferred from the
first message's delay; ns-3's is read from its frame trace. Python standard library only.
"""
import functools
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tiny_traces as tt  # noqa: E402
from loss_by_reason import NS3_ARP_AS  # noqa: E402

JITTER_MS_MAX = 10  # ARP: a whole number of ms in 0..9; ns-3's AODV broadcast jitter: 0..10 ms
SAME_NS = 5_000  # later messages: equal delays, to a few microseconds
BACKOFF_NS = 15 * 9_000 + 5_000  # one 802.11a backoff, CWmin 15 slots of 9 us, and a margin

# ---- what both sides must agree on ---------------------------------------------------------------


def arp_figures(case):
    """(SwarmNet's, ns-3's) ARP figures, named alike."""
    sn_arp = case.summary.get("arp", {})
    dropped = case.summary["packets"]["dropped"]
    ns_arp = case.replay["arp"]
    drops = ns_arp["drops"]
    sn = {"requests": sn_arp.get("requests_sent"), "replies": sn_arp.get("replies_sent"),
          "queue_full": dropped.get("arp_queue_full"), "unresolved": dropped.get("arp_unresolved")}
    ns3 = {"requests": ns_arp["requests_sent"], "replies": ns_arp["replies_sent"],
           "queue_full": drops["queue_full"],
           "unresolved": drops["dead_entry"] + drops["retries_exhausted"]}
    return sn, ns3


def common_problems(case, expected=None):
    """ARP's counts and drops equal on both sides (and as expected), and the same messages
    delivered."""
    problems = []
    sn, ns3 = arp_figures(case)
    print(f"  ARP          SwarmNet {sn}\n               ns-3     {ns3}")
    if sn != ns3:
        problems.append(f"ARP figures differ: SwarmNet {sn}, ns-3 {ns3}")
    if expected is not None and ns3 != expected:
        problems.append(f"ns-3's ARP figures {ns3}, expected {expected}")
    if expected is not None and sn != expected:
        problems.append(f"SwarmNet's ARP figures {sn}, expected {expected}")
    ambiguous = case.replay["arp"]["drops"]["queue_full_or_dead_entry"]
    if ambiguous:
        problems.append(f"ns-3: {ambiguous} ARP drops it could not put down to a reason")
    frames = case.replay["arp"]["request_frames"]
    if frames != ns3["requests"]:
        problems.append(f"ns-3: {ns3['requests']} requests but {frames} request frames")
    problems += arp_drop_problems(case)
    sn_delivered = sorted(m for m in case.sn if tt.delay_ns(case.sn, m) is not None)
    ns3_delivered = sorted(m for m in case.ns3 if case.ns3[m]["deliver"] is not None)
    if sn_delivered != ns3_delivered:
        problems.append(f"delivered: SwarmNet {sn_delivered}, ns-3 {ns3_delivered}")
    for message_id, entry in case.ns3.items():
        sn_inject = case.sn.get(message_id, {}).get("inject")
        if sn_inject != entry["inject"]:
            problems.append(f"message {message_id}: injected at {sn_inject} ns in SwarmNet, "
                            f"{entry['inject']} ns in ns-3")
    return problems


def arp_drop_problems(case):
    """Message by message: the messages ARP dropped, and why, are the same on both sides."""
    problems = []
    for message_id in sorted(set(case.sn) | set(case.ns3)):
        sn_reason = case.sn.get(message_id, {}).get("drop")
        sn_arp = sn_reason if sn_reason in ("arp_queue_full", "arp_unresolved") else None
        ns3_reason = case.ns3.get(message_id, {}).get("arp_drop")
        ns3_arp = NS3_ARP_AS.get(ns3_reason, ns3_reason)
        if sn_arp != ns3_arp:
            problems.append(f"message {message_id}: ARP drop {sn_arp} in SwarmNet, "
                            f"{ns3_reason} in ns-3")
    return problems


def singles_problems(case):
    """Later messages: delivered on both sides with the same delay, and no ARP frame in ns-3."""
    problems = []
    first = min(case.ns3[m]["inject"] for m in case.singles)
    late = [frame for frame in case.ns3_arp_frames if frame[0] >= first]
    if late:
        problems.append(f"ns-3 put ARP frames on the air after the exchange: {late}")
    for message_id in case.singles:
        sn_delay = tt.delay_ns(case.sn, message_id)
        ns3_delay = tt.delay_ns(case.ns3, message_id)
        if sn_delay is None or ns3_delay is None:
            problems.append(f"later message {message_id} not delivered (SwarmNet {sn_delay}, "
                            f"ns-3 {ns3_delay})")
        elif abs(sn_delay - ns3_delay) > SAME_NS:
            problems.append(f"later message {message_id}: delay {sn_delay} ns in SwarmNet, "
                            f"{ns3_delay} ns in ns-3 (more than {SAME_NS} ns apart)")
    return problems


def check_two(case):
    problems = common_problems(case, {"requests": 1, "replies": 1, "queue_full": 2,
                                      "unresolved": 0})
    by_lookup = sorted(case.burst, key=lambda m: (case.ns3[m]["inject"], m))
    for message_id in by_lookup[3:]:
        reason = case.sn.get(message_id, {}).get("drop")
        if reason != "arp_queue_full" or case.ns3[message_id]["deliver"] is not None:
            problems.append(f"burst message {message_id} (4th or 5th handed down): SwarmNet "
                            f"{reason}, ns-3 delivered at {case.ns3[message_id]['deliver']} "
                            f"(expected both: dropped, arp_queue_full)")
    first_inject = case.ns3[by_lookup[0]]["inject"]
    requests = [t for t, node, receiver in case.ns3_arp_frames if receiver == -1]
    if not requests:
        return problems + ["ns-3 sent no ARP request"]
    # ns-3's request leaves after its jitter plus channel access (DIFS, 34 us, on an idle medium).
    ns3_jitter_ms = (requests[0] - first_inject) // tt.MS
    reply_at = max(t for t, node, receiver in case.ns3_arp_frames if receiver != -1)
    for message_id in by_lookup[:3]:
        sn_delay = tt.delay_ns(case.sn, message_id)
        ns3_delay = tt.delay_ns(case.ns3, message_id)
        if sn_delay is None or ns3_delay is None:
            problems.append(f"burst message {message_id} not delivered (SwarmNet {sn_delay}, "
                            f"ns-3 {ns3_delay})")
            continue
        if case.ns3[message_id]["deliver"] <= reply_at:
            problems.append(f"ns-3 delivered burst message {message_id} before the ARP reply")
        if abs(sn_delay - ns3_delay) >= JITTER_MS_MAX * tt.MS:
            problems.append(f"burst message {message_id}: delays {sn_delay} ns (SwarmNet) and "
                            f"{ns3_delay} ns (ns-3) differ by 10 ms or more")
    first = by_lookup[0]
    sn_delay, ns3_delay = tt.delay_ns(case.sn, first), tt.delay_ns(case.ns3, first)
    if sn_delay is not None and ns3_delay is not None:
        exchange_ns3 = ns3_delay - ns3_jitter_ms * tt.MS
        # SwarmNet's jitter: the whole number of ms that brings its delay nearest ns-3's exchange.
        sn_jitter_ms = round((sn_delay - exchange_ns3) / tt.MS)
        exchange_sn = sn_delay - sn_jitter_ms * tt.MS
        print(f"  first message: ns-3 delay {ns3_delay} ns = jitter {ns3_jitter_ms} ms + "
              f"{exchange_ns3} ns; SwarmNet {sn_delay} ns = jitter {sn_jitter_ms} ms (inferred) "
              f"+ {exchange_sn} ns")
        if not 0 <= sn_jitter_ms < JITTER_MS_MAX or abs(exchange_sn - exchange_ns3) > BACKOFF_NS:
            problems.append(f"first message: delay minus jitter {exchange_sn} ns (SwarmNet, jitter "
                            f"{sn_jitter_ms} ms) and {exchange_ns3} ns (ns-3, jitter "
                            f"{ns3_jitter_ms} ms) differ by more than a backoff ({BACKOFF_NS} ns)")
    return problems + singles_problems(case)


def check_line(case):
    problems = common_problems(case)
    sn, _ = arp_figures(case)
    if sn["requests"] is None or sn["requests"] < len(case.order) - 1:
        problems.append(f"SwarmNet sent {sn['requests']} ARP requests on a "
                        f"{len(case.order) - 1}-hop route")
    sn_routing, ns3_routing = case.summary.get("routing", {}), case.replay.get("routing", {})
    rreqs = max(sn_routing.get("control_rreq", 0), ns3_routing.get("rreq", 0))
    draws = max(sn["requests"] or 0, case.replay["arp"]["requests_sent"]) + rreqs
    bound_ns = draws * JITTER_MS_MAX * tt.MS
    print(f"  burst bound: {draws} jittered sends (ARP requests and RREQs) x 10 ms = "
          f"{bound_ns / tt.MS:.0f} ms")
    for message_id in case.burst:
        sn_delay = tt.delay_ns(case.sn, message_id)
        ns3_delay = tt.delay_ns(case.ns3, message_id)
        if sn_delay is not None and ns3_delay is not None and abs(sn_delay - ns3_delay) > bound_ns:
            problems.append(f"burst message {message_id}: delays {sn_delay} ns (SwarmNet) and "
                            f"{ns3_delay} ns (ns-3) differ by more than {bound_ns} ns")
    return problems + singles_problems(case)


def check_far(case):
    # The burst: 3 queued, 2 dropped for the full queue; the first single arrives while the
    # resolution is still pending (queue full); the requests give up 4 s after the first lookup
    # and drop the 3 queued (ns-3: retries exhausted); later singles find the entry dead.
    problems = common_problems(case, {"requests": 4, "replies": 0, "queue_full": 3,
                                      "unresolved": 3 + 2})
    first_inject = min(case.ns3[m]["inject"] for m in case.burst)
    requests = sorted(t for t, node, receiver in case.ns3_arp_frames if receiver == -1)
    offsets_ms = [(t - first_inject) / tt.MS for t in requests]
    print(f"  ns-3 requests at first lookup + {', '.join(f'{o:.3f}' for o in offsets_ms)} ms")
    # The first request waits its jitter (under 10 ms); retries leave at the cache's timer ticks,
    # 1, 2 and 3 s after the first lookup; channel access adds well under a millisecond.
    expected = [None, 1000, 2000, 3000]
    if len(offsets_ms) != 4 or offsets_ms[0] >= JITTER_MS_MAX or any(
            not e <= o < e + 1 for e, o in zip(expected[1:], offsets_ms[1:])):
        problems.append(f"ns-3's requests at {offsets_ms} ms after the first lookup (expected "
                        "under 10, then 1000, 2000, 3000, each within 1 ms)")
    for message_id in case.burst:
        entry = case.sn.get(message_id, {})
        given_up_at = first_inject + 4000 * tt.MS
        if entry.get("drop") == "arp_unresolved" and entry["drop_at"] != given_up_at:
            problems.append(f"SwarmNet dropped queued message {message_id} as unresolved at "
                            f"{entry['drop_at']} ns, not 4 s after the first lookup")
    if any(case.ns3[m]["deliver"] is not None for m in case.ns3):
        problems.append("ns-3 delivered a message to a node out of range")
    return problems


def two_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = tt.burst_ids()
    case.singles = [tt.SINGLE_IDS + k for k in range(3)]
    return ([(m, 20, source, destination) for m in case.burst] +  # t = 0.2 s
            [(m, 50 + 20 * k, source, destination) for k, m in enumerate(case.singles)])


def line_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = tt.burst_ids()
    case.singles = [tt.SINGLE_IDS + k for k in range(3)]
    return ([(m, 20, source, destination) for m in case.burst] +  # route found by ~0.5 s
            [(m, 100 + 30 * k, source, destination) for k, m in enumerate(case.singles)])


def far_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = tt.burst_ids()
    pending = [tt.SINGLE_IDS]  # t = 1 s, while the resolution is pending
    dead = [tt.SINGLE_IDS + 1, tt.SINGLE_IDS + 2]  # t = 5 and 6 s, the entry dead
    case.singles = pending + dead
    return ([(m, 20, source, destination) for m in case.burst] +
            [(pending[0], 100, source, destination)] +
            [(m, 500 + 100 * k, source, destination) for k, m in enumerate(dead)])


CASES = [
    ("two", [50.0, 150.0], "direct", 1.5, two_traffic, check_two),
    ("line", [50.0, 150.0, 250.0, 350.0], "aodv", 2.0, line_traffic, check_line),
    ("far", [50.0, 250.0], "direct", 6.5, far_traffic, check_far),
]


def main():
    cases = [(name, f"{len(xs)} nodes, routing {routing}",
              functools.partial(tt.run_case, name=name, xs=xs, routing=routing,
                                duration_s=duration_s, traffic=traffic), check)
             for name, xs, routing, duration_s, traffic, check in CASES]
    return tt.run_cases(__doc__.split("\n")[0], cases)


if __name__ == "__main__":
    sys.exit(main())
