"""Tiny traces run through SwarmNet and ns-3.37 alike: the scenario, the runs and the command line
shared by the agreement tests (arp_agreement.py, mac_queue_agreement.py).

A case is a static scenario (configs/validation/small.yaml's radio and 802.11a stack, the robots
held in pockets between obstacles) whose traffic a test writes, run through SwarmNet's network
half (`swarmnet replay`) and through ns-3.37 (`swarmnet_ns3_replay`, its default stack with real
ARP) on the same mobility and traffic. Python standard library only.
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
        self.ns3 = {}  # message id -> {"inject": ns, "deliver": ns or None, "arp_drop": reason}
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
    ip_events = os.path.join(work, "ns3-ip.csv")
    _run([args.ns3, run_dir, "--routing", routing, "--seed", str(SEED), "-o", ns3_json,
          "--delivery-trace", deliveries, "--frame-trace", frames, "--ip-trace", ip_events] +
         vr.NS3_RADIO + list(ns3_options), work, "ns3")

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
    with open(ip_events, encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["event"] == "arp_drop":
                case.ns3[int(row["message_id"])].setdefault("arp_drop", row["detail"])
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


def delay_ns(side, message_id):
    entry = side.get(message_id, {})
    if entry.get("deliver") is None or entry.get("inject") is None:
        return None
    return entry["deliver"] - entry["inject"]


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
