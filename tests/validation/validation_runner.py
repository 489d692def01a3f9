"""Runs one validation case: a SwarmNet scenario, then ns-3 on its mobility trace and traffic
schedule (swarmnet_ns3_replay), then compare.py's comparison. Shared by run_small_case.py and
run_grid.py; Python standard library only."""
import filecmp
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import compare  # noqa: E402
from ns3_aodv_rules import NS3_AODV_RULES  # noqa: E402
import ns3_dcf80211_rules  # noqa: E402

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# The radio both simulators model (configs/validation/*.yaml): log-distance path loss, exponent 3,
# 46.6777 dB at 1 m, 27.0531 dBm transmit power, so that the received power at 120 m is -82 dBm,
# the preamble-detection (CCA) threshold; 802.11a at 6 Mbit/s for data and control frames.
NOMINAL_RANGE_M = 120.0
NS3_RADIO = ["--exponent", "3", "--reference-loss-db", "46.6777", "--reference-distance-m", "1",
             "--tx-power-dbm", "27.0531", "--preamble-min-rssi-dbm", "-82",
             "--preamble-threshold-db", "4", "--cca-ed-threshold-dbm", "-62",
             "--noise-figure-db", "7", "--error-model", "nist"]

FLOODING = {"ttl": 32, "jitter_max_s": 0.005}

# Until SwarmNet's 802.11 stack (log_distance, sinr PHY, dcf80211) builds, the SwarmNet side runs
# a 120 m unit disk with the ideal MAC at 6 Mbit/s: same connectivity, no contention.
DISK_NETWORK = {
    "propagation": [{"plugin": "disk", "params": {"range_m": NOMINAL_RANGE_M,
                                                  "probability": 1.0}}],
    "mac": {"plugin": "ideal_mac", "params": {"bitrate_bps": 6.0e6}},
}


# Three configurations (docs/validation.md, "Default stack and aligned setup"):
#
# default     both sides as ns-3 users run ns-3: ARP by request and reply (SwarmNet `network.arp:
#             ns3`; the replay's default, --arp-entries none) and AODV taking layer-2 feedback (a
#             unicast frame dropped at the retry limit, an ARP resolution given up), which ns-3's
#             AODV gets from the MAC's DroppedMpdu trace once ARP has resolved its neighbours.
# aligned     the setup the grid was aligned in before issue 19: no ARP frame on either side
#             (SwarmNet `network.arp: static`, the replay's --aligned: NeighborCacheHelper's
#             auto-generated entries) and no layer-2 feedback (with auto-generated entries
#             ns-3.37's AODV cannot map a neighbour to its MAC address, so no dropped frame
#             reaches it).
# static_arp  the default stack without ARP's frames: every address resolved beforehand on both
#             sides (SwarmNet `network.arp: static`, the replay's --arp-entries permanent, whose
#             permanent entries let ns-3's AODV map neighbours to MAC addresses) and AODV's
#             layer-2 feedback kept. Set beside the default stack, it tells what of a row's
#             difference ARP's own frames and failures make.
#
# In all three, SwarmNet's AODV keeps ns-3.37's rules (scripts/ns3_aodv_rules.py). Its
# sequence-number rules: ns-3.37 keeps a broken or expired route's sequence number where RFC 3561
# 6.11 increments it (docs/history/validation-journal.md, "The aligned grid (before issue 19)": on
# the dense row its re-discoveries draw twice the RREPs), and a RREQ leaves the route to the
# neighbour that sent it without a valid sequence number, so that no node answers for that neighbour
# until its next HELLO (without it SwarmNet's discoveries end a ring earlier: issue 19's delay). Its
# four control-message rules decide how RREPs, RERRs and the buffer move under load
# (docs/history/validation-journal.md, "The saturated rows, and ns-3's control-message rules").
# SwarmNet's AODV is compared like for like: ns-3's variant of the protocol, not SwarmNet's default.
# So is its 802.11 MAC: dcf80211 with ns-3.37's MPDU lifetime and station retry counts
# (scripts/ns3_dcf80211_rules.py), which change a run only where packets wait longer than 500 ms.
# "replay_arp_entries" is what the replay reports for its ARP entries (its JSON's arp.entries) under
# the options of "replay"; ARP frames go on the air only with "none" (nothing resolved beforehand).
SETUPS = {
    "default": {"arp": "ns3", "link_layer_feedback": True, "replay": [],
                "replay_arp_entries": "none"},
    "aligned": {"arp": "static", "link_layer_feedback": False, "replay": ["--aligned"],
                "replay_arp_entries": "auto-generated"},
    "static_arp": {"arp": "static", "link_layer_feedback": True,
                   "replay": ["--arp-entries", "permanent"], "replay_arp_entries": "permanent"},
}

# The targets each configuration is judged on (compare.compare's tolerances; speed-up and control
# overhead are added per row by run_grid.py). The default stack, and static_arp beside it, are
# held to issue 19's targets; the aligned setup keeps the targets it was aligned to (mean delay
# 15%, MAC frames reported only).
TOLERANCES = {
    "default": {"pdr_points": 3.0, "delay_pct": 20.0, "mac_pct": 10.0},
    "aligned": {"pdr_points": 3.0, "delay_pct": 15.0, "mac_pct": None},
    "static_arp": {"pdr_points": 3.0, "delay_pct": 20.0, "mac_pct": 10.0},
}


def add_setup_arguments(parser, setup_help):
    """--setup, and --aligned as its older shorthand; setup_from_arguments reads them."""
    parser.add_argument("--setup", choices=sorted(SETUPS), default="default", help=setup_help)
    parser.add_argument("--aligned", action="store_true", help="the same as --setup aligned")


def setup_from_arguments(parser, args):
    """The setup add_setup_arguments' flags name; refuses --aligned beside another --setup."""
    if args.aligned and args.setup not in ("default", "aligned"):
        parser.error("--aligned is --setup aligned: give one of them")
    return "aligned" if args.aligned else args.setup


def aodv_params(setup="default"):
    return {"link_layer_feedback": SETUPS[setup]["link_layer_feedback"],
            **NS3_AODV_RULES}


def routing_choice(routing, setup="default"):
    if routing == "flooding":
        return {"plugin": "flooding", "params": dict(FLOODING)}
    if routing == "aodv":
        return {"plugin": "aodv", "params": aodv_params(setup)}
    return {"plugin": routing}


def detect_stack(swarmnet, scenario):
    """'80211' if the scenario (which names the 802.11 stack) validates, else 'disk'."""
    result = subprocess.run([swarmnet, "validate", scenario], capture_output=True, text=True,
                            check=False)
    if result.returncode == 0:
        return "80211", ""
    return "disk", (result.stderr or result.stdout).strip()


def swarmnet_overrides(stack, routing, setup="default"):
    """--set arguments that select the stack, ARP and the routing protocol (JSON is YAML flow),
    and on the 802.11 stack ns-3.37's MAC rules (scripts/ns3_dcf80211_rules.py)."""
    arp = SETUPS[setup]["arp"]
    if stack == "disk":
        network = dict(DISK_NETWORK)
        network["routing"] = routing_choice(routing, setup)
        network["arp"] = arp
        return ["--set", "network=" + json.dumps(network)]
    return (["--set", "network.routing=" + json.dumps(routing_choice(routing, setup)),
             "--set", "network.arp=" + arp] + ns3_dcf80211_rules.set_arguments())


def replay_options(setup="default"):
    """The replay's options for the configuration (its default: ns-3's own stack)."""
    return list(SETUPS[setup]["replay"])


def run_case(swarmnet, ns3, scenario, work_dir, routing, stack, overrides=(), seed=1,
             tolerances=None, log=print, setup="default"):
    """Runs both simulators and compares them; returns compare.compare()'s row."""
    summary, replay = run_pair(swarmnet, ns3, scenario, work_dir, routing, stack, overrides, seed,
                               log, setup)
    return compared(summary, replay, routing, stack, tolerances, setup)


def compared(summary, replay, routing, stack, tolerances=None, setup="default"):
    """compare.compare()'s row for SwarmNet's summary and ns-3's replay JSON (or pools of them);
    tolerances default to the configuration's (TOLERANCES)."""
    if tolerances is None:
        tolerances = TOLERANCES[setup]
    row = compare.compare(summary, replay, **tolerances)
    row["routing"] = routing
    row["stack"] = stack
    row["setup"] = setup
    return row


def run_pair(swarmnet, ns3, scenario, work_dir, routing, stack, overrides=(), seed=1, log=print,
             setup="default", resume=False, ns3_from=None, ns3_run=None, frame_traces=False):
    """Runs SwarmNet, then ns-3 on its traces; returns (summary.json, the replay's JSON). ns-3's
    run number (RngRun) is `ns3_run`, or the trace's `seed` when None. With `frame_traces` both
    sides write every frame they put on the air (SwarmNet's swarmnet/frames.csv, the replay's
    --frame-trace ns3-frames.csv; frame_agreement.py compares them). With
    `resume`, a pair that WORK_DIR/commands.json says ran to the end with these very commands is
    read back instead of run again. With `ns3_from` (the same pair's directory in an earlier
    grid), ns-3 is not run again: its result is taken from there, which holds only if the replay's
    options are the same and SwarmNet's new run left the very same traces (checked)."""
    run_dir = os.path.join(work_dir, "swarmnet")
    ns3_json = os.path.join(work_dir, "ns3.json")
    os.makedirs(work_dir, exist_ok=True)
    swarmnet_command = [swarmnet, "run", scenario, "--seed", str(seed), "--out", run_dir,
                        "--overwrite"]
    swarmnet_command += swarmnet_overrides(stack, routing, setup)
    for override in overrides:
        swarmnet_command += ["--set", override]
    ns3_command = [ns3, run_dir, "--routing", routing,
                   "--seed", str(seed if ns3_run is None else ns3_run), "-o", ns3_json]
    ns3_command += NS3_RADIO + replay_options(setup)
    if frame_traces:
        if ns3_from:
            raise RuntimeError("frame traces need ns-3 to run again: it cannot reuse a kept run")
        swarmnet_command += ["--set", "output.frame_trace=true"]
        ns3_command += ["--frame-trace", os.path.join(work_dir, "ns3-frames.csv")]
    if routing == "flooding":
        ns3_command += ["--flooding-ttl", str(FLOODING["ttl"]),
                        "--flooding-jitter-max-s", str(FLOODING["jitter_max_s"])]
    record = os.path.join(work_dir, "commands.json")
    planned = {"swarmnet": [str(c) for c in swarmnet_command],
               "ns3": [str(c) for c in ns3_command]}
    if ns3_from:
        planned["ns3_from"] = ns3_from
    if not (resume and _ran(record, planned)):
        if os.path.exists(record):
            os.remove(record)  # a pair half rerun is no longer the recorded one
        _run(swarmnet_command, os.path.join(work_dir, "swarmnet.out"), log)
        if ns3_from:
            _reuse_ns3(ns3_from, ns3_command, run_dir, ns3_json)
        else:
            _run(ns3_command, os.path.join(work_dir, "ns3.out"), log)
        with open(record, "w", encoding="utf-8") as f:
            json.dump(planned, f, indent=1)
    with open(os.path.join(run_dir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    with open(ns3_json, encoding="utf-8") as f:
        replay = json.load(f)
    return summary, replay


def _reuse_ns3(kept_dir, ns3_command, run_dir, ns3_json):
    """Copies the ns-3 result of the pair kept in `kept_dir` to `ns3_json`, after checking that
    it replayed the same traces with the same options (RuntimeError otherwise)."""
    try:
        with open(os.path.join(kept_dir, "commands.json"), encoding="utf-8") as f:
            kept = json.load(f)["ns3"]
        kept_out = _option(kept, "-o")
    except (OSError, ValueError, KeyError) as error:
        raise RuntimeError(f"{kept_dir}: no ns-3 run recorded to reuse ({error})") from error
    # The same options: all but the replay's own path, the run directory and the output file.
    def options(command, run, out):
        return [c for c in command[1:] if c not in (run, out)]
    if options(kept, kept[1], kept_out) != \
            options(ns3_command, run_dir, ns3_json):
        raise RuntimeError(f"{kept_dir}: its ns-3 run had other options: "
                           f"{' '.join(kept[2:])}")
    # The same traces, read from the kept pair's own directory (the path recorded in its
    # commands.json may be where this run now writes); the replay also takes its duration from
    # summary.json.
    kept_run_dir = os.path.join(kept_dir, "swarmnet")
    try:
        for name in ("mobility.ns2", "traffic.csv"):
            if not filecmp.cmp(os.path.join(kept_run_dir, name), os.path.join(run_dir, name),
                               shallow=False):
                raise RuntimeError(f"{run_dir}/{name} differs from {kept_run_dir}/{name}: the "
                                   f"traces changed, so ns-3 must run again")
        durations = []
        for directory in (kept_run_dir, run_dir):
            with open(os.path.join(directory, "summary.json"), encoding="utf-8") as f:
                durations.append(json.load(f)["sim_time_s"])
    except (OSError, ValueError, KeyError) as error:
        raise RuntimeError(f"{kept_dir}: cannot compare its traces with {run_dir}'s "
                           f"({error})") from error
    if durations[0] != durations[1]:
        raise RuntimeError(f"{run_dir}: {durations[1]} simulated s, the kept run "
                           f"{durations[0]}: the traces changed, so ns-3 must run again")
    shutil.copyfile(os.path.join(kept_dir, "ns3.json"), ns3_json)


def _ran(record, planned):
    """Whether `record` (written once both runs of a pair ended) names the `planned` commands.
    A pair's directory copied or moved since keeps the paths it ran under: they are read as the
    directory's new place, so that a grid assembled from earlier grids' pairs is resumed."""
    def moved(text, old_dir, new_dir):
        if text == old_dir or text.startswith(old_dir + os.sep):
            return new_dir + text[len(old_dir):]
        return text
    try:
        with open(record, encoding="utf-8") as f:
            recorded = json.load(f)
        old_dir = os.path.dirname(_option(recorded["swarmnet"], "--out"))
        new_dir = os.path.dirname(record)
        recorded = {key: [moved(c, old_dir, new_dir) for c in value]
                    if key in ("swarmnet", "ns3") else value for key, value in recorded.items()}
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return False  # no record, or not one this code wrote: run the pair again
    return recorded == planned


def _option(command, name):
    """The value after `name` in `command` (ValueError if absent)."""
    return command[command.index(name) + 1]


def _run(command, output_path, log):
    log("  $ " + " ".join(_quote(c) for c in command))
    with open(output_path, "w", encoding="utf-8") as out:
        result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, check=False)
    if result.returncode != 0:
        with open(output_path, encoding="utf-8") as f:
            tail = f.read()[-2000:]
        raise RuntimeError(f"{os.path.basename(command[0])} exited with {result.returncode}:\n"
                           f"{tail}")


def _quote(text):
    return text if all(c.isalnum() or c in "-_./=:," for c in text) else "'" + text + "'"


def arena_side_m(robots, robots_per_km2):
    return round(1000.0 * math.sqrt(robots / robots_per_km2), 1)
