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

The five burst messages are handed down within 100 ns of one another: SwarmNet injects a
message at its step's start plus an offset hashed from the seed and its id
(core/src/protocol/step_data.hpp, injection_offset), so the burst takes five ids whose offsets
nearly coincide. SwarmNet's packet trace has no ARP frame, so its jitter is inferred from the
first message's delay; ns-3's is read from its frame trace. Python standard library only.
"""
import argparse
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_runner as vr  # noqa: E402

SEED = 1  # small.yaml's seed; the replay's --seed (ns-3's RngRun)
STEP_NS = 10_000_000  # step_s 0.01
PAYLOAD_BYTES = 512
MS = 1_000_000
JITTER_MS_MAX = 10  # ARP: a whole number of ms in 0..9; ns-3's AODV broadcast jitter: 0..10 ms
SAME_NS = 5_000  # later messages: equal delays, to a few microseconds
BACKOFF_NS = 15 * 9_000 + 5_000  # one 802.11a backoff, CWmin 15 slots of 9 us, and a margin
SKIP = 77

# ---- SwarmNet's injection offset (core/include/swarmnet/random.hpp, protocol/step_data.hpp) ----
MASK = (1 << 64) - 1


def _mix64(x):
    x = (x + 0x9E3779B97F4A7C15) & MASK
    x = ((x ^ (x >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    x = ((x ^ (x >> 27)) * 0x94D049BB133111EB) & MASK
    return x ^ (x >> 31)


def _derive_seed(seed, keys):
    h = _mix64(seed)
    for k in keys:
        h = _mix64(h ^ _mix64((k + 0x632BE59BD9B4E019) & MASK))
    return h


def _hash_name(text):
    h = 0xCBF29CE484222325
    for byte in text.encode():
        h = ((h ^ byte) * 0x100000001B3) & MASK
    return h


_INJECT = _hash_name("inject")


def injection_offset_ns(message_id):
    return _derive_seed(SEED, [_INJECT, message_id]) % STEP_NS


def burst_ids(count=5, search=20000):
    """`count` message ids whose injection offsets are closest together, ascending."""
    ranked = sorted((injection_offset_ns(i), i) for i in range(search))
    start = min(range(len(ranked) - count + 1),
                key=lambda k: ranked[k + count - 1][0] - ranked[k][0])
    return sorted(i for _, i in ranked[start:start + count])


SINGLE_IDS = 30000  # later single messages: ids from here (above every burst id)

# ---- the scenario -------------------------------------------------------------------------------
ROBOT_RADIUS_M = 1.0
POCKET_HALF_M = 1.3  # a robot's centre lands within 0.3 m of the pocket's centre in x
ARENA_HEIGHT_M = 3.9  # obstacles 2 m tall: no robot fits above one, and one robot per pocket


def pocket_arena(xs):
    """An arena whose obstacles leave one pocket per robot, centred at xs (m)."""
    width = xs[-1] + 50.0
    obstacles, left = [], 0.0
    for x in xs:
        obstacles.append({"x_min_m": left, "y_min_m": 0, "x_max_m": x - POCKET_HALF_M,
                          "y_max_m": 2.0})
        left = x + POCKET_HALF_M
    obstacles.append({"x_min_m": left, "y_min_m": 0, "x_max_m": width, "y_max_m": 2.0})
    return {"width_m": width, "height_m": ARENA_HEIGHT_M, "obstacles": obstacles}


class Case:
    """One case run on both sides: what each side did to every message, and ARP's figures."""

    def __init__(self, name, routing):
        self.name = name
        self.routing = routing
        self.sn = {}  # message id -> {"inject": ns, "deliver": ns, "drop": reason}
        self.ns3 = {}  # message id -> {"inject": ns, "deliver": ns or None}
        self.ns3_arp_frames = []  # (time_ns, node, receiver)
        self.summary = None
        self.replay = None
        self.order = []  # node ids from left to right
        self.burst = []
        self.singles = []


def run_case(args, name, xs, routing, duration_s, traffic, sets=(), ns3_options=()):
    """Runs the geometry in SwarmNet (no traffic), writes traffic(order) into its traffic.csv,
    then replays it in SwarmNet's network half and in ns-3. `sets` are further `--set`
    overrides of the scenario, `ns3_options` further options of the ns-3 replay."""
    case = Case(name, routing)
    work = os.path.join(args.work, name)
    run_dir = os.path.join(work, "run")
    os.makedirs(work, exist_ok=True)
    robots = {"count": len(xs), "radius_m": ROBOT_RADIUS_M,
              "controllers": [{"plugin": "cbr", "params": {"fraction": 0.0}}]}
    _run([args.swarmnet, "run", args.scenario, "--seed", str(SEED), "--out", run_dir,
          "--overwrite", "--quiet",
          "--set", "arena=" + json.dumps(pocket_arena(xs)),
          "--set", "robots=" + json.dumps(robots),
          "--set", f"duration_s={duration_s}", "--set", f"step_s={STEP_NS / 1e9}",
          "--set", "output.packet_trace=false", "--set", "output.mobility_trace=true",
          "--set", "network.routing=" + json.dumps(vr.routing_choice(routing)),
          "--set", "network.arp=ns3", *[a for o in sets for a in ("--set", o)]],
         work, "swarmnet-run")
    case.order = _left_to_right(os.path.join(run_dir, "mobility.ns2"))
    rows = traffic(case)
    with open(os.path.join(run_dir, "traffic.csv"), "w", encoding="utf-8") as f:
        f.write("message_id,step,inject_ns,source,destination,payload_bytes\n")
        for message_id, step, source, destination in rows:
            inject = step * STEP_NS + injection_offset_ns(message_id)
            f.write(f"{message_id},{step},{inject},{source},{destination},{PAYLOAD_BYTES}\n")

    sn_dir = os.path.join(work, "swarmnet")
    _run([args.swarmnet, "replay", run_dir, "--out", sn_dir, "--quiet"], work, "swarmnet-replay")
    ns3_json = os.path.join(work, "ns3.json")
    deliveries = os.path.join(work, "ns3-deliveries.csv")
    frames = os.path.join(work, "ns3-frames.csv")
    _run([args.ns3, run_dir, "--routing", routing, "--seed", str(SEED), "-o", ns3_json,
          "--delivery-trace", deliveries, "--frame-trace", frames] + vr.NS3_RADIO +
         list(ns3_options), work, "ns3")

    with open(os.path.join(sn_dir, "summary.json"), encoding="utf-8") as f:
        case.summary = json.load(f)
    with open(ns3_json, encoding="utf-8") as f:
        case.replay = json.load(f)
    with open(os.path.join(sn_dir, "packets.csv"), encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["message_id"] in ("", "-1"):
                continue
            entry = case.sn.setdefault(int(row["message_id"]), {})
            time_ns = int(row["time_ns"])
            if row["event"] == "send" and row["node"] == row["source"]:
                entry.setdefault("inject", time_ns)
            elif row["event"] == "deliver" and row["node"] == row["destination"]:
                entry.setdefault("deliver", time_ns)
            elif row["event"] == "drop":
                entry.setdefault("drop", row["detail"])
                entry.setdefault("drop_at", time_ns)
    with open(deliveries, encoding="utf-8") as f:
        for row in csv.DictReader(f):
            delivered = int(row["delivered_ns"])
            case.ns3[int(row["message_id"])] = {"inject": int(row["inject_ns"]),
                                                "deliver": delivered if delivered >= 0 else None}
    with open(frames, encoding="utf-8") as f:
        case.ns3_arp_frames = [(int(r["time_ns"]), int(r["node"]), int(r["receiver"]))
                               for r in csv.DictReader(f) if r["kind"] == "arp"]
    return case


def _left_to_right(mobility_path):
    xs = {}
    with open(mobility_path, encoding="utf-8") as f:
        for line in f:
            parts = line.split()
            if len(parts) == 4 and parts[2] == "X_":
                xs[int(parts[0][len("$node_("):-1])] = float(parts[3])
    return [node for node, _ in sorted(xs.items(), key=lambda item: item[1])]


def _run(command, work, label):
    output = os.path.join(work, label + ".out")
    with open(output, "w", encoding="utf-8") as out:
        result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, check=False)
    if result.returncode != 0:
        with open(output, encoding="utf-8") as f:
            tail = f.read()[-2000:]
        raise RuntimeError(f"{' '.join(command)}\nexited with {result.returncode}:\n{tail}")


# ---- what both sides must agree on ---------------------------------------------------------------


def delay_ns(side, message_id):
    entry = side.get(message_id, {})
    if entry.get("deliver") is None or entry.get("inject") is None:
        return None
    return entry["deliver"] - entry["inject"]


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
    sn_delivered = sorted(m for m in case.sn if delay_ns(case.sn, m) is not None)
    ns3_delivered = sorted(m for m in case.ns3 if case.ns3[m]["deliver"] is not None)
    if sn_delivered != ns3_delivered:
        problems.append(f"delivered: SwarmNet {sn_delivered}, ns-3 {ns3_delivered}")
    for message_id, entry in case.ns3.items():
        sn_inject = case.sn.get(message_id, {}).get("inject")
        if sn_inject != entry["inject"]:
            problems.append(f"message {message_id}: injected at {sn_inject} ns in SwarmNet, "
                            f"{entry['inject']} ns in ns-3")
    return problems


def print_messages(case):
    print("  message  inject_ns     SwarmNet delay/drop      ns-3 delay")
    for message_id in sorted(case.ns3, key=lambda m: (case.ns3[m]["inject"], m)):
        sn_delay = delay_ns(case.sn, message_id)
        ns3_delay = delay_ns(case.ns3, message_id)
        sn_text = (f"{sn_delay / 1e6:.6f} ms" if sn_delay is not None
                   else "dropped: " + str(case.sn.get(message_id, {}).get("drop")))
        ns3_text = f"{ns3_delay / 1e6:.6f} ms" if ns3_delay is not None else "not delivered"
        print(f"  {message_id:7d}  {case.ns3[message_id]['inject']:<12d}  {sn_text:23s}  "
              f"{ns3_text}")


def singles_problems(case):
    """Later messages: delivered on both sides with the same delay, and no ARP frame in ns-3."""
    problems = []
    first = min(case.ns3[m]["inject"] for m in case.singles)
    late = [frame for frame in case.ns3_arp_frames if frame[0] >= first]
    if late:
        problems.append(f"ns-3 put ARP frames on the air after the exchange: {late}")
    for message_id in case.singles:
        sn_delay, ns3_delay = delay_ns(case.sn, message_id), delay_ns(case.ns3, message_id)
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
    ns3_jitter_ms = (requests[0] - first_inject) // MS
    reply_at = max(t for t, node, receiver in case.ns3_arp_frames if receiver != -1)
    for message_id in by_lookup[:3]:
        sn_delay, ns3_delay = delay_ns(case.sn, message_id), delay_ns(case.ns3, message_id)
        if sn_delay is None or ns3_delay is None:
            problems.append(f"burst message {message_id} not delivered (SwarmNet {sn_delay}, "
                            f"ns-3 {ns3_delay})")
            continue
        if case.ns3[message_id]["deliver"] <= reply_at:
            problems.append(f"ns-3 delivered burst message {message_id} before the ARP reply")
        if abs(sn_delay - ns3_delay) >= JITTER_MS_MAX * MS:
            problems.append(f"burst message {message_id}: delays {sn_delay} ns (SwarmNet) and "
                            f"{ns3_delay} ns (ns-3) differ by 10 ms or more")
    first = by_lookup[0]
    sn_delay, ns3_delay = delay_ns(case.sn, first), delay_ns(case.ns3, first)
    if sn_delay is not None and ns3_delay is not None:
        exchange_ns3 = ns3_delay - ns3_jitter_ms * MS
        # SwarmNet's jitter: the whole number of ms that brings its delay nearest ns-3's exchange.
        sn_jitter_ms = round((sn_delay - exchange_ns3) / MS)
        exchange_sn = sn_delay - sn_jitter_ms * MS
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
    bound_ns = draws * JITTER_MS_MAX * MS
    print(f"  burst bound: {draws} jittered sends (ARP requests and RREQs) x 10 ms = "
          f"{bound_ns / MS:.0f} ms")
    for message_id in case.burst:
        sn_delay, ns3_delay = delay_ns(case.sn, message_id), delay_ns(case.ns3, message_id)
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
    offsets_ms = [(t - first_inject) / MS for t in requests]
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
        if entry.get("drop") == "arp_unresolved" and entry["drop_at"] != first_inject + 4000 * MS:
            problems.append(f"SwarmNet dropped queued message {message_id} as unresolved at "
                            f"{entry['drop_at']} ns, not 4 s after the first lookup")
    if any(case.ns3[m]["deliver"] is not None for m in case.ns3):
        problems.append("ns-3 delivered a message to a node out of range")
    return problems


def two_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = burst_ids()
    case.singles = [SINGLE_IDS + k for k in range(3)]
    return ([(m, 20, source, destination) for m in case.burst] +  # t = 0.2 s
            [(m, 50 + 20 * k, source, destination) for k, m in enumerate(case.singles)])


def line_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = burst_ids()
    case.singles = [SINGLE_IDS + k for k in range(3)]
    return ([(m, 20, source, destination) for m in case.burst] +  # route found by ~0.5 s
            [(m, 100 + 30 * k, source, destination) for k, m in enumerate(case.singles)])


def far_traffic(case):
    source, destination = case.order[0], case.order[-1]
    case.burst = burst_ids()
    pending = [SINGLE_IDS]  # t = 1 s, while the resolution is pending
    dead = [SINGLE_IDS + 1, SINGLE_IDS + 2]  # t = 5 and 6 s, the entry dead
    case.singles = pending + dead
    return ([(m, 20, source, destination) for m in case.burst] +
            [(pending[0], 100, source, destination)] +
            [(m, 500 + 100 * k, source, destination) for k, m in enumerate(dead)])


CASES = [
    ("two", [50.0, 150.0], "direct", 1.5, two_traffic, check_two),
    ("line", [50.0, 150.0, 250.0, 350.0], "aodv", 2.0, line_traffic, check_line),
    ("far", [50.0, 250.0], "direct", 6.5, far_traffic, check_far),
]


def run_cases(description, cases):
    """The command line of a tiny-trace agreement test: runs `cases`, each (name, title,
    run(args) -> Case, check(Case) -> problems), and returns the exit status (SKIP without
    SwarmNet's 802.11 stack)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--swarmnet", required=True, help="the swarmnet command")
    parser.add_argument("--ns3", required=True, help="the swarmnet_ns3_replay program")
    parser.add_argument("--work", required=True, help="directory for the runs")
    parser.add_argument("--scenario", default=os.path.join(vr.SOURCE_DIR, "configs", "validation",
                                                            "small.yaml"))
    parser.add_argument("--case", choices=[c[0] for c in cases], action="append",
                        help="run only this case (repeatable)")
    args = parser.parse_args()
    stack, reason = vr.detect_stack(args.swarmnet, args.scenario)
    if stack != "80211":
        print("skipped: SwarmNet's 802.11 stack is not available:\n  " + reason)
        return SKIP
    failed = False
    for name, title, run, check in cases:
        if args.case and name not in args.case:
            continue
        print(f"{name}: {title}")
        case = run(args)
        print_messages(case)
        problems = check(case)
        for problem in problems:
            print("  MISMATCH: " + problem)
        print(f"  {'FAIL' if problems else 'pass'}")
        failed = failed or bool(problems)
    return 1 if failed else 0


def main():
    cases = [(name, f"{len(xs)} nodes, routing {routing}",
              lambda args, name=name, xs=xs, routing=routing, duration_s=duration_s,
              traffic=traffic: run_case(args, name, xs, routing, duration_s, traffic), check)
             for name, xs, routing, duration_s, traffic, check in CASES]
    return run_cases(__doc__.split("\n")[0], cases)


if __name__ == "__main__":
    sys.exit(main())
