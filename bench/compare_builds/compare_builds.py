#!/usr/bin/env python3
"""Side-by-side network-half cost of two SwarmNet builds on the same scenarios.

    python3 bench/compare_builds/compare_builds.py BEFORE_BUILD AFTER_BUILD
        [--workloads paper200,paper400,paper400-feedback] [--repeats 3] [--sim-s 10]
        [--out compare.json]

Runs every workload with both builds, alternating (before, after, before, ...) so that load on a
shared machine hits both alike, and reports the median network CPU seconds per simulated second
(`cpu_s.network` of summary.json), the events run, and after/before; and the same for the robot
half's CPU (`cpu_s.robot`) and the run's wall time, for changes that touch the robot half. It also checks that both
builds reported the same packets, delivery ratio, delays, hops, MAC and routing counters: a
speed-up that changes results is reported as such (compare packet traces with `cmp` for byte
identity). Writes a JSON file with every run when --out is given.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAPER = os.path.join(ROOT, "configs", "paper", "evaluation.yaml")


def paper(robots, feedback):
    side = 500.0 * (robots / 50.0) ** 0.5
    sets = [f"robots.count={robots}", f"arena.width_m={side:.1f}", f"arena.height_m={side:.1f}"]
    if not feedback:
        # As in the comparison with ns-3 (docs/validation.md): the replay's AODV has no L2 feedback.
        sets.append("network.routing.params.link_layer_feedback=false")
    return PAPER, sets


WORKLOADS = {
    "paper100": paper(100, False),
    "paper200": paper(200, False),
    "paper400": paper(400, False),
    "paper400-feedback": paper(400, True),
    # Issue 13's large sizes with layer-2 feedback on (the paper defaults), in process as every
    # workload here; use a short --sim-s.
    "paper1600-feedback": paper(1600, True),
    "paper3200-feedback": paper(3200, True),
    "wireless": (os.path.join(ROOT, "configs", "wireless.yaml"), []),
}


RESULT_KEYS = ("packets", "pdr", "delay_s", "hops_mean", "mac", "routing")


def run_once(build, scenario, sets, sim_s, out_dir):
    # Each run starts from an empty directory (builds since --overwrite refuse an earlier run's;
    # older builds know no --overwrite flag).
    shutil.rmtree(out_dir, ignore_errors=True)
    command = [os.path.join(build, "bin", "swarmnet"), "run", scenario, "--transport", "inproc",
               "--set", f"duration_s={sim_s}", "--out", out_dir]
    for item in sets:
        command += ["--set", item]
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          check=False)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}): {done.stderr.strip()}")
    with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    # Everything the run reports about the network, for the same-results check.
    outcome = {key: summary.get(key) for key in RESULT_KEYS}
    return {"cpu_network_s": summary["cpu_s"]["network"], "cpu_robot_s": summary["cpu_s"]["robot"],
            "wall_s": summary["wall_s"], "events": summary.get("events"),
            "pdr": summary["pdr"], "mac_tx_frames": summary["mac"]["tx_frames"],
            "outcome": outcome}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("before", help="build directory of the reference")
    parser.add_argument("after", help="build directory of the change")
    parser.add_argument("--workloads", default="paper200,paper400,paper400-feedback",
                        help=f"comma-separated, from {', '.join(WORKLOADS)}")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--sim-s", type=float, default=10.0, help="simulated seconds per run")
    parser.add_argument("--out", help="JSON file for every run and the medians")
    args = parser.parse_args()
    names = [name for name in args.workloads.split(",") if name]
    unknown = [name for name in names if name not in WORKLOADS]
    if unknown:
        parser.error(f"unknown workload(s) {', '.join(unknown)}; known: {', '.join(WORKLOADS)}")
    for build in (args.before, args.after):
        if not os.path.exists(os.path.join(build, "bin", "swarmnet")):
            parser.error(f"{build}: no bin/swarmnet (is it a SwarmNet build directory?)")

    results = {}
    with tempfile.TemporaryDirectory(prefix="swarmnet-compare-") as scratch:
        for name in names:
            scenario, sets = WORKLOADS[name]
            runs = {"before": [], "after": []}
            for repeat in range(args.repeats):
                for label, build in (("before", args.before), ("after", args.after)):
                    out_dir = os.path.join(scratch, f"{name}-{label}-{repeat}")
                    runs[label].append(run_once(build, scenario, sets, args.sim_s, out_dir))
                    print(f"{name} {label} {repeat + 1}/{args.repeats}: "
                          f"{runs[label][-1]['cpu_network_s']:.3f} CPU-s", file=sys.stderr)
            def median(key, label):
                return statistics.median(r[key] for r in runs[label]) / args.sim_s
            medians = {label: median("cpu_network_s", label) for label in runs}
            robot = {label: median("cpu_robot_s", label) for label in runs}
            wall = {label: median("wall_s", label) for label in runs}
            same = runs["before"][0]["outcome"] == runs["after"][0]["outcome"]
            results[name] = {"runs": runs, "cpu_per_sim_s": medians,
                             "after_over_before": medians["after"] / medians["before"],
                             "robot_cpu_per_sim_s": robot,
                             "robot_after_over_before": robot["after"] / robot["before"],
                             "wall_per_sim_s": wall,
                             "wall_after_over_before": wall["after"] / wall["before"],
                             "same_results": same}

    print(f"| workload | network before (CPU-s per sim-s) | after | after/before | "
          f"robot after/before | wall after/before | events before | events after | "
          f"same results |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, result in results.items():
        medians = result["cpu_per_sim_s"]
        print(f"| {name} | {medians['before']:.4f} | {medians['after']:.4f} | "
              f"{result['after_over_before']:.2f} | {result['robot_after_over_before']:.2f} | "
              f"{result['wall_after_over_before']:.2f} | {result['runs']['before'][0]['events']} | "
              f"{result['runs']['after'][0]['events']} | {'yes' if result['same_results'] else 'NO'} |")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({"sim_s": args.sim_s, "repeats": args.repeats, "results": results}, f,
                      indent=2)
    return 0 if all(r["same_results"] for r in results.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
