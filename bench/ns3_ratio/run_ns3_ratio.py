#!/usr/bin/env python3
"""The network half against ns-3.37 on the same traces (docs/performance.md, "Far signals").

    python3 bench/ns3_ratio/run_ns3_ratio.py BUILD [BUILD ...] [--robots 200,400] [--sim-s 10]
        [--seed 1] [--out runs/ns3-ratio]

For each robot count, the study's scenario (configs/paper/evaluation.yaml: 802.11a DCF, sinr PHY,
AODV, ARP, 20% of robots sending 5 msg/s) at its constant density (side sqrt(N x 5000) m) runs
once per build, in process (`--transport inproc`, so `cpu_s.network` is the network half
alone). Then `swarmnet_ns3_replay` (of the first build) replays the first build's mobility and
traffic in ns-3.37 as its users run it (ARP, AODV with layer-2 feedback). Mobility and traffic
do not depend on the network, so every build's run has the same traces; the script checks that.

Writes OUT/ns3_ratio.json (every run) and prints a table: CPU seconds of each side, how many
times faster each build's network half is than ns-3, and delivery ratios. Standard library only.
"""
import argparse
import hashlib
import json
import math
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAPER = ROOT / "configs" / "paper" / "evaluation.yaml"


def digest(path: pathlib.Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def run_swarmnet(build: pathlib.Path, robots: int, sim_s: float, seed: int, out: pathlib.Path):
    side = math.sqrt(robots * 5000.0)
    command = [str(build / "bin" / "swarmnet"), "run", str(PAPER), "--transport", "inproc",
               "--quiet", "--overwrite", "--seed", str(seed), "--out", str(out),
               "--set", f"robots.count={robots}", "--set", f"arena.width_m={side:.1f}",
               "--set", f"arena.height_m={side:.1f}", "--set", f"duration_s={sim_s}"]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(f"run_ns3_ratio: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    summary = json.loads((out / "summary.json").read_text())
    return {"cpu_network_s": summary["cpu_s"]["network"], "pdr": summary["pdr"],
            "events": summary.get("events"), "traces": digest(out / "mobility.ns2") +
            digest(out / "traffic.csv")}


def run_ns3(build: pathlib.Path, run_dir: pathlib.Path, seed: int, out: pathlib.Path):
    command = [str(build / "bin" / "swarmnet_ns3_replay"), str(run_dir), "--routing", "aodv",
               "--seed", str(seed), "-o", str(out)]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(f"run_ns3_ratio: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    result = json.loads(out.read_text())
    return {"cpu_network_s": result["cpu_s"]["network"], "pdr": result["pdr"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("builds", nargs="+", type=pathlib.Path)
    parser.add_argument("--robots", default="200,400")
    parser.add_argument("--sim-s", type=float, default=10.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "runs" / "ns3-ratio")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for robots in (int(n) for n in args.robots.split(",")):
        runs = []
        for i, build in enumerate(args.builds):
            runs.append(run_swarmnet(build.resolve(), robots, args.sim_s, args.seed,
                                     args.out / f"n{robots}-build{i}"))
            print(f"n={robots} build {build}: {runs[-1]['cpu_network_s']:.2f} CPU-s, "
                  f"pdr {runs[-1]['pdr']:.3f}", flush=True)
        if len({r["traces"] for r in runs}) != 1:
            sys.exit(f"run_ns3_ratio: the builds' traces differ at {robots} robots")
        ns3 = run_ns3(args.builds[0].resolve(), args.out / f"n{robots}-build0", args.seed,
                      args.out / f"n{robots}-ns3.json")
        print(f"n={robots} ns-3: {ns3['cpu_network_s']:.2f} CPU-s, pdr {ns3['pdr']:.3f}",
              flush=True)
        rows.append({"robots": robots, "sim_s": args.sim_s, "seed": args.seed, "ns3": ns3,
                     "swarmnet": [dict(r, build=str(b), faster=ns3["cpu_network_s"] /
                                       r["cpu_network_s"]) for r, b in zip(runs, args.builds)]})
    (args.out / "ns3_ratio.json").write_text(json.dumps(rows, indent=2) + "\n")
    print("| robots | ns-3 CPU s | ns-3 PDR | " +
          " | ".join(f"build {i} CPU s | faster | PDR" for i in range(len(args.builds))) + " |")
    for row in rows:
        cells = [str(row["robots"]), f"{row['ns3']['cpu_network_s']:.1f}",
                 f"{row['ns3']['pdr']:.3f}"]
        for run in row["swarmnet"]:
            cells += [f"{run['cpu_network_s']:.2f}", f"{run['faster']:.1f}x", f"{run['pdr']:.3f}"]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
