#!/usr/bin/env python3
"""What no far-signal scheme can beat (docs/performance.md, issue 13).

A far signal is one too weak to be detected (below cca_threshold_dbm, -82 dBm). Issue 13 asks
that such signals cost nothing unless a node needs them. The cheapest any such scheme can be is
a run in which they do not exist at all: `network.phy.interference_floor_db` at
cca_threshold_dbm minus the noise floor (11.9897 dB with the defaults) ignores every signal below
the detection threshold, so the network half does only the work that detectable frames cause
(preambles, receptions, the MAC, ARP, AODV). That run is not the same model: distant
transmitters no longer add up, so more frames get through and the traffic changes. Its cost per
frame, at the default model's frames, estimates the network half's cost if far signals cost
nothing (an estimate, not a strict floor: the cost per frame depends on the traffic too).

For each robot count N (constant density, side sqrt(N x 5000 m^2)) and seed, the study's scenario
(configs/paper/evaluation.yaml) runs in process twice in turn, with the default floor and with
the detection floor (the order swapped every seed), and the summaries' network-half CPU (the
thread's own clock), frames, events, delivery and mean delay are kept. Writes JSON (every run;
per N the medians, and the per-seed ratio and estimate's median and range) and prints a table.

Usage: run_far_signal_bound.py BUILD_DIR [--robots 200,400,3200] [--seeds 1-3]
         [--sim-s 20] [--sim-s-for 3200=5] [--out far_signal_bound.json]
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIO = os.path.join(ROOT, "configs", "paper", "evaluation.yaml")


def floors():
    """The default floor, and the one at the scenario's detection threshold (the noise floor and
    the threshold read from the scenario, with docs/scenario.md's defaults where it is silent)."""
    with open(SCENARIO) as f:
        phy = yaml.safe_load(f)["network"]["phy"]
    noise_dbm = (-174.0 + 10.0 * math.log10(phy.get("bandwidth_hz", 20.0e6)) +
                 phy.get("noise_figure_db", 7.0))
    return {"default": phy.get("interference_floor_db", -10.0),
            "detection": round(phy.get("cca_threshold_dbm", -82.0) - noise_dbm, 4)}


def seeds(text):
    if "-" in text:
        first, last = (int(x) for x in text.split("-"))
        return list(range(first, last + 1))
    return [int(x) for x in text.split(",")]


def run(binary, n, seed, sim_s, floor_db, out):
    side = round(math.sqrt(n * 5000.0), 1)
    cmd = [binary, "run", SCENARIO, "--transport", "inproc", "--seed", str(seed),
           "--set", f"robots.count={n}", "--set", f"arena.width_m={side}",
           "--set", f"arena.height_m={side}", "--set", f"duration_s={sim_s}",
           "--set", f"network.phy.interference_floor_db={floor_db}",
           "--set", "output.mobility_trace=false", "--set", "output.traffic_schedule=false",
           "--quiet", "--overwrite", "--out", out]
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"run_far_signal_bound: {' '.join(cmd)} failed ({r.returncode}):\n{r.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    if not s["mac"]["tx_frames"]:
        sys.exit(f"run_far_signal_bound: {' '.join(cmd)} sent no frame; nothing to compare")
    return {"robots": n, "seed": seed, "sim_s": sim_s, "floor_db": floor_db,
            "cpu_network_s": s["cpu_s"]["network"],
            "cpu_network_per_sim_s": s["cpu_s"]["network"] / sim_s,
            "cpu_robot_s": s["cpu_s"]["robot"], "events": s["events"],
            "tx_frames": s["mac"]["tx_frames"], "pdr": s["pdr"],
            "delay_mean_s": s["delay_s"]["mean"],
            "cpu_us_per_frame": 1e6 * s["cpu_s"]["network"] / s["mac"]["tx_frames"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--robots", default="200,400,3200")
    ap.add_argument("--seeds", default="1-3")
    ap.add_argument("--sim-s", type=float, default=20.0)
    ap.add_argument("--sim-s-for", default="3200=5", help="per-N durations, e.g. 3200=5,1600=10")
    ap.add_argument("--out", default="far_signal_bound.json")
    a = ap.parse_args()
    binary = os.path.join(a.build, "bin", "swarmnet")
    if not os.access(binary, os.X_OK):
        sys.exit(f"run_far_signal_bound: no swarmnet binary at {binary}")
    per_n = dict((int(k), float(v)) for k, v in (x.split("=") for x in a.sim_s_for.split(",") if x))
    floor_db = floors()
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(x) for x in a.robots.split(",")):
            for i, seed in enumerate(seeds(a.seeds)):
                # In turn, the order swapped every seed, so that drift hits both alike.
                names = list(floor_db) if i % 2 == 0 else list(reversed(floor_db))
                pair = {}
                for name in names:
                    row = run(binary, n, seed, per_n.get(n, a.sim_s), floor_db[name],
                              os.path.join(tmp, f"{n}-{seed}-{name}"))
                    row["floor"] = name
                    pair[name] = row
                    print(f"  N={n} seed={seed} {name:9s} network {row['cpu_network_s']:.2f} "
                          f"CPU-s, {row['tx_frames']} frames, delivery {row['pdr']:.3f}",
                          file=sys.stderr)
                # This seed's estimate of the network half with far signals at no cost: the
                # no-far run's cost per frame at the default run's frames.
                pair["default"]["estimate_no_far_cpu_network_per_sim_s"] = (
                    pair["detection"]["cpu_us_per_frame"] * 1e-6 * pair["default"]["tx_frames"] /
                    pair["default"]["sim_s"])
                pair["default"]["cpu_ratio_no_far_over_default"] = (
                    pair["detection"]["cpu_network_s"] / pair["default"]["cpu_network_s"])
                runs.extend(pair[name] for name in floor_db)
    groups = []
    for n in sorted({r["robots"] for r in runs}):
        g = {"robots": n}
        for name in floor_db:
            rs = [r for r in runs if r["robots"] == n and r["floor"] == name]
            for key in ("cpu_network_per_sim_s", "tx_frames", "events", "pdr", "cpu_us_per_frame"):
                g[f"{name}_{key}"] = statistics.median(r[key] for r in rs)
        defaults = [r for r in runs if r["robots"] == n and r["floor"] == "default"]
        for key in ("cpu_ratio_no_far_over_default", "estimate_no_far_cpu_network_per_sim_s"):
            values = [r[key] for r in defaults]
            g[key] = statistics.median(values)
            g[key + "_range"] = [min(values), max(values)]
        groups.append(g)
    with open(a.out, "w") as f:
        json.dump({"scenario": "configs/paper/evaluation.yaml", "floors_db": floor_db,
                   "seeds": seeds(a.seeds), "runs": runs, "by_robots": groups}, f, indent=1)
    print("| robots | network CPU-s per sim-s, default | with no far signal | ratio (seeds' range) | "
          "us per frame, default / none | frames, default / none | delivery, default / none | "
          "estimate with far signals at no cost (CPU-s per sim-s; seeds' range) |")
    print("|---|---|---|---|---|---|---|---|")
    for g in groups:
        ratio = g["cpu_ratio_no_far_over_default_range"]
        estimate = g["estimate_no_far_cpu_network_per_sim_s_range"]
        print(f"| {g['robots']} | {g['default_cpu_network_per_sim_s']:.3f} | "
              f"{g['detection_cpu_network_per_sim_s']:.3f} | "
              f"{g['cpu_ratio_no_far_over_default']:.2f} ({ratio[0]:.2f}-{ratio[1]:.2f}) | "
              f"{g['default_cpu_us_per_frame']:.1f} / {g['detection_cpu_us_per_frame']:.1f} | "
              f"{g['default_tx_frames']:.0f} / {g['detection_tx_frames']:.0f} | "
              f"{g['default_pdr']:.3f} / {g['detection_pdr']:.3f} | "
              f"{g['estimate_no_far_cpu_network_per_sim_s']:.3f} "
              f"({estimate[0]:.3f}-{estimate[1]:.3f}) |")


if __name__ == "__main__":
    main()
