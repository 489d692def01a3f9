#!/usr/bin/env python3
"""The validation grid: SwarmNet and ns-3.37 side by side on densities from sparse to dense and
loads from light to saturated, one row at a time (never two simulators at once), with the CPU
time of both network halves measured on every row.

    python3 tests/validation/run_grid.py --build build [--full] [--duration-s 20]
        [--routing flooding,direct,aodv] [--seed 1 | --seeds 1-8] [--set KEY=VALUE ...]
        [--ns3-run N] [--setup default|aligned|static_arp] [--extra-rows issue19]
        [--row N,SIDE_M,RATE_HZ,PAYLOAD_B,SENDERS ...]
        [--extra-only] [--frame-traces] [--pdr-points P] [--delay-pct D] [--mac-pct M]
        [--control-pct C] [--out build/validation-grid] [--doc docs/validation.md]

Both sides run as ns-3 users run ns-3 by default: ARP by request and reply (SwarmNet
`network.arp: ns3`, the replay's default) and AODV with layer-2 feedback (SwarmNet
`link_layer_feedback: true`); AODV keeps ns-3.37's sequence-number and control-message rules
(validation_runner.NS3_AODV_RULES) and dcf80211 ns-3.37's MPDU lifetime and station retry
counts (scripts/ns3_dcf80211_rules.py) either way. --setup aligned (or --aligned) runs the setup the
grid was aligned in before issue 19: no ARP frame (SwarmNet `network.arp: static`, the replay's
--aligned) and no layer-2 feedback; --setup static_arp the default stack with every address
resolved beforehand on both sides (no ARP frame, layer-2 feedback kept), to tell what of a row's
difference ARP makes (validation_runner.SETUPS).

Every row sets its robots, arena side, messages per second per sender, payload and share of
senders explicitly; the table shows all five. --extra-rows issue19 adds, for each protocol of
--routing, the three rows of issue 19's table (other densities, loads and payloads, chosen without
tuning to them; EXTRA_ROWS); --row adds a row of one's own.

Writes OUT/results.json and OUT/table.md, and with --doc replaces the table between the
'<!-- validation-grid:begin -->' and '<!-- validation-grid:end -->' lines of the doc. Exits 1 if
a row misses a target. Default stack (issue 19's targets): delivery ratio within 3 points, mean
delay within 20%, MAC frames within 10%, AODV control packets per delivered packet within 20%,
SwarmNet at least 10x faster on rows of 100 nodes or more; static_arp is held to the same.
--aligned keeps the targets that setup was judged on: mean delay within 15%, MAC frames reported
only. --pdr-points, --delay-pct, --mac-pct and --control-pct override a tolerance (a negative
value: not checked).
With --seeds every row runs once per seed and is judged on the aggregate over the seeds
(compare.pool: sums of messages, deliveries, control packets, frames and CPU seconds; the table's
delivery difference also gives the per-seed range).
"""
import argparse
import itertools
import json
import os
import platform
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import compare  # noqa: E402
import validation_runner as vr  # noqa: E402
from seed_interval import student_interval  # noqa: E402

STUDY_DENSITY = 200.0  # robots per km^2: 50 robots in 500 x 500 m
DENSE_DENSITY = 800.0  # four times denser: 50 robots in 250 x 250 m
DENSITIES = {"study": STUDY_DENSITY, "dense": DENSE_DENSITY}
RATES_HZ = (1.0, 5.0, 20.0)
SIZES = (50, 100, 200)

# The default grid: every density x load corner for flooding, the one-hop baseline, AODV.
DEFAULT_ROWS = {
    "flooding": [(50, "study", 1), (50, "study", 5), (50, "study", 20), (100, "study", 5),
                 (200, "study", 1), (200, "study", 5), (50, "dense", 5), (100, "dense", 1),
                 (100, "dense", 20)],
    "direct": [(50, "study", 5), (100, "study", 20), (200, "study", 5), (200, "dense", 20)],
    "aodv": [(50, "study", 5), (100, "study", 5), (200, "study", 5), (100, "dense", 5)],
}

# The grid's traffic (configs/validation/grid.yaml): a fifth of the robots send 512-byte messages.
GRID_PAYLOAD_BYTES = 512
GRID_SENDERS = 0.2

# --extra-rows: further rows of other densities, loads and payloads, (robots, arena side m,
# messages per second per sender, payload bytes, share of senders). issue19: the three scenarios
# of issue 19's table, where ns-3's default stack was first compared with SwarmNet; chosen
# without tuning to them. Their densities: 417, 99 and 200 robots per km^2.
EXTRA_ROWS = {
    "issue19": [(150, 600.0, 10.0, 128, 0.2), (80, 900.0, 5.0, 1024, 0.3),
                (100, 707.0, 2.0, 64, 0.5)],
}

HEADER = ("| routing | N | arena (m) | msg/s per sender | payload (B) | senders "
          + compare.HEADER[len("| N | routing "):])
COLUMNS = HEADER.count(" |")
BEGIN = "<!-- validation-grid:begin -->"
END = "<!-- validation-grid:end -->"


def plugin_available(build, name):
    return os.path.exists(os.path.join(build, "plugins", f"swarmnet_{name}.so"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build", help="SwarmNet build directory")
    parser.add_argument("--out", help="results directory (default BUILD/validation-grid)")
    parser.add_argument("--doc", help="Markdown file whose grid table to replace")
    parser.add_argument("--full", action="store_true",
                        help="every N x density x rate for each routing (slow: hours of ns-3)")
    parser.add_argument("--routing", default="flooding,direct,aodv",
                        help="comma-separated protocols (aodv is skipped if SwarmNet lacks it)")
    parser.add_argument("--duration-s", type=float, default=20.0, help="simulated seconds per row")
    seeds = parser.add_mutually_exclusive_group()
    seeds.add_argument("--seed", type=int, default=1)
    seeds.add_argument("--seeds", type=seed_list, help="seeds to pool, e.g. 1-8 or 1,2,5")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a further SwarmNet override for every row, e.g. "
                             "network.routing.params.increment_seqno_on_break=false")
    parser.add_argument("--frame-traces", action="store_true",
                        help="both sides write every frame they put on the air (SEED_DIR/"
                             "swarmnet/frames.csv and SEED_DIR/ns3-frames.csv, about 40 bytes a "
                             "frame), for frame_agreement.py; not with --ns3-from")
    parser.add_argument("--max-robots", type=int, default=100000, help="skip larger rows")
    parser.add_argument("--stack", choices=["auto", "80211", "disk"], default="auto")
    parser.add_argument("--resume", action="store_true",
                        help="read back every seed's pair that already ran to the end in OUT with "
                             "the same commands (its commands.json) instead of running it again; "
                             "a pair's directory copied from another grid counts as run there")
    parser.add_argument("--ns3-from", metavar="EARLIER_OUT",
                        help="run only SwarmNet: take each pair's ns-3 result from an earlier "
                             "grid's directory (same rows, seeds and ns-3 options), after checking "
                             "that SwarmNet left the very same traces; for re-validating a change "
                             "to SwarmNet's network half")
    parser.add_argument("--ns3-run", type=int, metavar="N",
                        help="ns-3's run number (the replay's --seed, RngRun) for every trace; "
                             "default: each trace's own seed. A grid with another run number "
                             "re-draws ns-3's side over the very same traces (SwarmNet's side is "
                             "unchanged): the spread over such grids is ns-3's own noise")
    vr.add_setup_arguments(
        parser,
        "default: ns-3's default stack on both sides (ARP, AODV with "
        "layer-2 feedback); aligned: the setup aligned before issue 19 (no "
        "ARP frame on either side: SwarmNet network.arp: static, the "
        "replay's --aligned; AODV without layer-2 feedback); static_arp: "
        "the default stack with every address resolved beforehand "
        "(SwarmNet network.arp: static, replay --arp-entries permanent), "
        "layer-2 feedback kept")
    parser.add_argument("--extra-rows", choices=sorted(EXTRA_ROWS), action="append", default=[],
                        help="add a named set of further rows for each protocol of --routing "
                             "(issue19: 150 robots / 600 m / 10 msg/s / 128 B / 20%% senders, "
                             "80 / 900 m / 5 / 1024 B / 30%%, 100 / 707 m / 2 / 64 B / 50%%)")
    parser.add_argument("--row", type=row_spec, action="append", default=[],
                        metavar="N,SIDE_M,RATE_HZ,PAYLOAD_B,SENDERS",
                        help="add a row for each protocol of --routing, e.g. 150,600,10,128,0.2 "
                             "(SENDERS: share of the robots that send, 0-1)")
    parser.add_argument("--extra-only", action="store_true",
                        help="run only the rows of --extra-rows and --row, not the grid's")
    parser.add_argument("--pdr-points", type=float,
                        help="delivery-ratio tolerance, points (default 3)")
    parser.add_argument("--delay-pct", type=float,
                        help="mean-delay tolerance, %% (default 20; --aligned: 15)")
    parser.add_argument("--mac-pct", type=float,
                        help="MAC-frames tolerance, %% (default 10; --aligned: not checked)")
    parser.add_argument("--control-pct", type=float,
                        help="AODV control packets per delivery tolerance, %% (default 20)")
    parser.add_argument("--from-results", metavar="RESULTS_JSON",
                        help="run nothing: rewrite the table (and --doc) from an earlier run")
    args = parser.parse_args()
    setup = vr.setup_from_arguments(parser, args)
    if args.frame_traces and args.ns3_from:
        parser.error("--frame-traces needs ns-3 to run again: give it without --ns3-from")
    args.seeds = args.seeds or [args.seed]
    if args.from_results:
        with open(args.from_results, encoding="utf-8") as f:
            earlier = json.load(f)
        table = markdown_table(earlier["rows"], earlier["meta"])
        print(table)
        if args.doc:
            replace_table(args.doc, table)
        return 0

    build = os.path.abspath(args.build)
    swarmnet = os.path.join(build, "bin", "swarmnet")
    ns3 = os.path.join(build, "bin", "swarmnet_ns3_replay")
    for program in (swarmnet, ns3):
        if not os.path.exists(program):
            sys.exit(f"run_grid.py: {program} not found: build the targets swarmnet, "
                     f"swarmnet_plugins and swarmnet_ns3_replay (ns-3 must be installed)")
    out = os.path.abspath(args.out or os.path.join(build, "validation-grid"))
    scenario = os.path.join(vr.SOURCE_DIR, "configs", "validation", "grid.yaml")
    stack, reason = args.stack, ""
    if stack == "auto":
        stack, reason = vr.detect_stack(swarmnet, scenario)
    if stack == "disk":
        print("SwarmNet's 802.11 stack is not available; the SwarmNet side runs the 120 m unit "
              "disk with the ideal MAC" + (":\n  " + reason.replace("\n", "\n  ") if reason else ""))

    print(f"setup: {setup} ({describe_setup(setup)})")
    rows_wanted = []
    extra = [spec for name in args.extra_rows for spec in EXTRA_ROWS[name]] + args.row
    for routing in args.routing.split(","):
        if routing == "aodv" and not plugin_available(build, "aodv"):
            print("skipping aodv: SwarmNet's aodv plugin is not built")
            continue
        cases = []
        if not args.extra_only:
            grid = (itertools.product(SIZES, DENSITIES, RATES_HZ) if args.full
                    else DEFAULT_ROWS[routing])
            cases = [grid_case(n, d, r) for n, d, r in grid]
        cases += [extra_case(*spec) for spec in extra]
        rows_wanted += [dict(case, routing=routing) for case in cases
                        if case["robots"] <= args.max_robots]

    base_tolerances = dict(vr.TOLERANCES[setup])
    for key in ("pdr_points", "delay_pct", "mac_pct"):
        if getattr(args, key) is not None:
            base_tolerances[key] = getattr(args, key)
    control_pct = 20.0 if args.control_pct is None else args.control_pct
    results = []
    for i, case in enumerate(rows_wanted, 1):
        routing, robots, side, rate = (case["routing"], case["robots"], case["arena_side_m"],
                                       case["rate_hz"])
        payload, senders = case["payload_bytes"], case["senders"]
        name = f"{routing}-{case['label']}"
        print(f"[{i}/{len(rows_wanted)}] {name}: {robots} robots in {side:g} x {side:g} m, "
              f"{rate:g} msg/s per sender, {payload} B, {100 * senders:g}% senders", flush=True)
        overrides = [f"robots.count={robots}", f"arena.width_m={side:g}",
                     f"arena.height_m={side:g}",
                     f"robots.controllers.1.params.rate_hz={rate:g}",
                     f"robots.controllers.1.params.payload_bytes={payload}",
                     f"robots.controllers.1.params.fraction={senders:g}",
                     f"duration_s={args.duration_s:g}"] + args.set
        tolerances = dict(base_tolerances,
                          min_speedup=10.0 if robots >= 100 else None,
                          control_pct=control_pct if routing == "aodv" else None)
        started = time.monotonic()
        try:
            row = run_row(swarmnet, ns3, scenario, os.path.join(out, name), routing, stack,
                          overrides, args.seeds, tolerances, setup, args.resume,
                          os.path.join(args.ns3_from, name) if args.ns3_from else None,
                          args.ns3_run, args.frame_traces)
        except RuntimeError as error:
            print(f"  failed: {error}", flush=True)
            row = {"robots": robots, "routing": routing, "error": str(error), "pass": False}
        row.update({"name": name, "density": case["density"], "arena_side_m": side,
                    "rate_hz": rate, "payload_bytes": payload, "senders": senders,
                    "extra": case["extra"], "wall_s": time.monotonic() - started})
        if "error" not in row:
            print("  " + compare.text_report(row).replace("\n", "\n  "), flush=True)
        results.append(row)

    os.makedirs(out, exist_ok=True)
    meta = {"stack": stack, "setup": setup,
            "tolerances": dict(base_tolerances, control_pct=control_pct),
            "duration_s": args.duration_s, "seeds": args.seeds, "set": args.set,
            "ns3_run": args.ns3_run,
            "machine": platform.machine(), "cpus": os.cpu_count(),
            "date": time.strftime("%Y-%m-%d")}
    with open(os.path.join(out, "results.json"), "w", encoding="utf-8") as f:
        json.dump({"meta": meta, "rows": results}, f, indent=2)
    table = markdown_table(results, meta)
    with open(os.path.join(out, "table.md"), "w", encoding="utf-8") as f:
        f.write(table)
    print(table)
    if args.doc:
        replace_table(args.doc, table)
    return 0 if all(r["pass"] for r in results) else 1


def grid_case(robots, density, rate):
    """A row of the grid: the grid's payload and share of senders at a named density."""
    return {"label": f"n{robots}-{density}-r{rate:g}", "robots": robots, "density": density,
            "arena_side_m": vr.arena_side_m(robots, DENSITIES[density]), "rate_hz": rate,
            "payload_bytes": GRID_PAYLOAD_BYTES, "senders": GRID_SENDERS, "extra": False}


def extra_case(robots, side, rate, payload, senders):
    """A row of --extra-rows or --row."""
    return {"label": f"n{robots}-s{side:g}-r{rate:g}-p{payload}-f{senders:g}", "robots": robots,
            "density": round(robots / (side / 1000.0) ** 2, 1), "arena_side_m": side,
            "rate_hz": rate, "payload_bytes": payload, "senders": senders, "extra": True}


def row_spec(text):
    """'N,SIDE_M,RATE_HZ,PAYLOAD_B,SENDERS' -> (robots, side, rate, payload, senders)."""
    parts = text.split(",")
    try:
        if len(parts) != 5:
            raise ValueError
        spec = (int(parts[0]), float(parts[1]), float(parts[2]), int(parts[3]), float(parts[4]))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"{text!r}: expected N,SIDE_M,RATE_HZ,PAYLOAD_B,SENDERS, e.g. 150,600,10,128,0.2")
    if spec[0] < 2 or spec[1] <= 0 or spec[2] <= 0 or spec[3] < 4 or not 0 < spec[4] <= 1:
        raise argparse.ArgumentTypeError(f"{text!r}: needs N >= 2, SIDE_M > 0, RATE_HZ > 0, "
                                         f"PAYLOAD_B >= 4 (the replay's message index) and "
                                         f"0 < SENDERS <= 1")
    return spec


def describe_setup(setup):
    if setup == "aligned":
        return ("aligned: no ARP frame on either side (SwarmNet network.arp: static, replay "
                "--aligned), AODV without layer-2 feedback (link_layer_feedback: false)")
    if setup == "static_arp":
        return ("static_arp: ns-3's default stack with every address resolved beforehand: no ARP "
                "frame on either side (SwarmNet network.arp: static, replay --arp-entries "
                "permanent), AODV with layer-2 feedback (link_layer_feedback: true)")
    return ("ns-3's default stack on both sides: ARP (SwarmNet network.arp: ns3, replay "
            "--arp-entries none), AODV with layer-2 feedback (link_layer_feedback: true)")


def seed_list(text):
    """'1-8', '1,2,5' or '1-3,7' -> [1, 2, ...]."""
    seeds = []
    for part in text.split(","):
        first, _, last = part.partition("-")
        seeds += range(int(first), int(last or first) + 1)
    if not seeds:
        raise argparse.ArgumentTypeError(f"no seed in {text!r}")
    return seeds


def run_row(swarmnet, ns3, scenario, work_dir, routing, stack, overrides, seeds, tolerances,
            setup="default", resume=False, ns3_from=None, ns3_run=None, frame_traces=False):
    """One row: compare.compare()'s row for one seed; for several, the row of the pooled runs,
    with the range of the per-seed delivery differences and every seed's own row."""
    pairs = []
    for seed in seeds:
        seed_dir = work_dir if len(seeds) == 1 else os.path.join(work_dir, f"seed{seed}")
        kept = None
        if ns3_from:
            kept = ns3_from if len(seeds) == 1 else os.path.join(ns3_from, f"seed{seed}")
        pairs.append(vr.run_pair(swarmnet, ns3, scenario, seed_dir, routing, stack, overrides,
                                 seed, log=lambda s: None, setup=setup, resume=resume,
                                 ns3_from=kept, ns3_run=ns3_run, frame_traces=frame_traces))
    if len(pairs) == 1:
        return vr.compared(*pairs[0], routing, stack, tolerances, setup)
    per_seed = [dict(vr.compared(*pair, routing, stack, tolerances, setup), seed=seed)
                for seed, pair in zip(seeds, pairs)]
    row = vr.compared(compare.pool([p[0] for p in pairs]), compare.pool([p[1] for p in pairs]),
                      routing, stack, tolerances, setup)
    diffs = [r["pdr_diff_points"] for r in per_seed]
    interval = student_interval(swarmnet, diffs)
    row.update(seeds=seeds, pdr_diff_points_range=[min(diffs), max(diffs)],
               pdr_diff_points_interval=[interval["low"], interval["high"]], per_seed=per_seed)
    return row


def describe_seeds(seeds):
    if len(seeds) == 1:
        return f"seed {seeds[0]}"
    span = (f"{seeds[0]}-{seeds[-1]}" if seeds == list(range(seeds[0], seeds[-1] + 1))
            else ",".join(map(str, seeds)))
    return (f"seeds {span} pooled (delivery difference: pooled, then the per-seed range and the "
            f"95% Student-t interval of the mean per-seed difference; p95 is not pooled)")


def markdown_table(results, meta):
    stack = ("SwarmNet: log_distance + sinr PHY + dcf80211" if meta["stack"] == "80211" else
             "SwarmNet: 120 m disk + ideal_mac (its 802.11 stack was not available)")
    settings = "".join(f"`--set {o}`, " for o in meta.get("set", []))
    if meta.get("ns3_run") is not None:
        settings += f"ns-3 run number {meta['ns3_run']} on every trace, "
    # results.json from before issue 19 have no setup: those grids ran the aligned one.
    setup = meta.get("setup", "aligned")
    tolerances = meta.get("tolerances")
    targets = ""
    if tolerances:
        mac = tolerances.get("mac_pct")
        targets = (f" Targets: delivery within {tolerances['pdr_points']:g} points, mean delay "
                   f"within {tolerances['delay_pct']:g}%, MAC frames "
                   + (f"within {mac:g}%" if mac is not None and mac >= 0 else "reported only")
                   + f", AODV control packets per delivery within "
                     f"{tolerances.get('control_pct', 20.0):g}%, SwarmNet 10x faster from 100 "
                     f"nodes.")
    lines = [f"{stack}; ns-3.37: YansWifi 802.11a 6 Mbit/s, log-distance; setup "
             f"{describe_setup(setup)}; "
             f"{meta['duration_s']:g} simulated s per row, "
             f"{describe_seeds(meta.get('seeds') or [meta['seed']])}, {settings}"
             f"{meta['cpus']} CPUs, {meta['date']}. CPU: network half only, seconds.{targets}",
             "", HEADER, "|" + "---|" * COLUMNS]
    for row in results:
        lead = [row["routing"], str(row["robots"]), f"{row['arena_side_m']:g}",
                f"{row['rate_hz']:g}", str(row.get("payload_bytes", GRID_PAYLOAD_BYTES)),
                f"{100 * row.get('senders', GRID_SENDERS):g}%"]
        if "error" in row:
            lines.append("| " + " | ".join(lead + ["error: " + row["error"].splitlines()[0]]
                                           + [""] * (COLUMNS - len(lead) - 1)) + " |")
        else:
            lines.append("| " + " | ".join(lead + compare.markdown_cells(row)) + " |")
    return "\n".join(lines) + "\n"


def replace_table(doc, table):
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    if BEGIN not in text or END not in text:
        sys.exit(f"run_grid.py: {doc} has no '{BEGIN}' ... '{END}' block")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(doc, "w", encoding="utf-8") as f:
        f.write(head + BEGIN + "\n" + table + END + tail)


if __name__ == "__main__":
    sys.exit(main())
