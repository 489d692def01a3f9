#!/usr/bin/env python3
"""The reference study's overhead experiment (section V-B, Tables I and II) with SwarmNet.

For each swarm size, at the study's constant density (500 x 500 m for 50 robots), 200 simulated
seconds of configs/paper/evaluation.yaml (802.11a DCF, AODV, 20% CBR at 5 packets/s):
  integrated   the two-process run: CPU of the robot half, the network half and the transport
  robot alone  the robot half with the study's simplified one-hop model (120 m disk, ideal MAC,
               direct routing) and no traces
  network alone  `swarmnet replay` of the integrated run: the network half from the recorded
               positions and traffic
Writes OUT/results.json and OUT/table.md, with the study's ns-3 figures beside ours.

  python3 scripts/reproduce_overhead.py --build build --out runs/paper-overhead
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

# Table II of the study: ARGoS with ns-3 (ARGoS, ns-3, sum) and standalone (ARGoS, ns-3), CPU s.
STUDY = {25: (9.0, 2.9, 11.9, 9.5, 3.4), 50: (17.6, 15.2, 32.8, 18.3, 19.2),
         75: (24.8, 34.9, 59.7, 27.8, 28.6), 100: (30.8, 52.8, 83.6, 40.5, 53.2),
         125: (37.0, 106.7, 143.7, 53.6, 98.7), 150: (42.2, 124.8, 167.0, 68.7, 133.9),
         175: (46.7, 150.3, 197.0, 83.5, 174.9), 200: (52.7, 259.5, 312.2, 103.3, 288.5)}

ONE_HOP = ["--set", "network.propagation=[{plugin: disk, params: {range_m: 120}}]",
           "--set", "network.phy.model=threshold", "--set", "network.mac={plugin: ideal_mac}",
           "--set", "network.routing={plugin: direct}", "--set", "output.mobility_trace=false",
           "--set", "output.traffic_schedule=false"]


def swarmnet(binary, *args):
    result = subprocess.run([str(binary), *args], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"swarmnet {' '.join(args)} failed:\n{result.stdout}{result.stderr}")


def summary(path):
    return json.loads((path / "summary.json").read_text())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="build directory")
    parser.add_argument("--out", default="runs/paper-overhead", help="output directory")
    parser.add_argument("--robots", default="25,50,75,100,125,150,175,200")
    parser.add_argument("--duration-s", type=float, default=200.0)
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parent.parent
    binary = pathlib.Path(args.build).resolve() / "bin" / "swarmnet"
    scenario = root / "configs" / "paper" / "evaluation.yaml"
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for n in [int(x) for x in args.robots.split(",")]:
        side = round(500 * math.sqrt(n / 50), 1)
        common = ["--set", f"robots.count={n}", "--set", f"arena.width_m={side}",
                  "--set", f"arena.height_m={side}", "--set", f"duration_s={args.duration_s}",
                  "--quiet"]
        integrated, alone, replay = out / f"integrated-{n}", out / f"robot-alone-{n}", out / f"replay-{n}"
        swarmnet(binary, "run", str(scenario), *common, "--out", str(integrated))
        swarmnet(binary, "run", str(scenario), *common, *ONE_HOP, "--out", str(alone))
        swarmnet(binary, "replay", str(integrated), "--out", str(replay), "--quiet")
        i, a, r = summary(integrated), summary(alone), summary(replay)
        rows.append({"robots": n, "arena_m": side, "integrated": i["cpu_s"], "wall_s": i["wall_s"],
                     "realtime_factor": i["realtime_factor"], "pdr": i["pdr"],
                     "robot_alone_cpu_s": a["cpu_s"]["robot"],
                     "network_alone_cpu_s": r["cpu_s"]["network"]})
        print(f"{n} robots done", file=sys.stderr)
    (out / "results.json").write_text(json.dumps(rows, indent=2) + "\n")
    lines = ["| robots | arena (m) | study: ARGoS + ns-3 = sum | SwarmNet integrated: robot + network "
             "+ transport = sum | study standalone: ARGoS / ns-3 | SwarmNet standalone: robot half "
             "(disk) / network half (replay) | SwarmNet wall s (real-time factor) | delivery ratio |",
             "|---|---|---|---|---|---|---|---|"]
    for row in rows:
        c, s = row["integrated"], STUDY.get(row["robots"])
        study = f"{s[0]} + {s[1]} = {s[2]}" if s else "-"
        study_alone = f"{s[3]} / {s[4]}" if s else "-"
        lines.append(f"| {row['robots']} | {row['arena_m']:g} | {study} | {c['robot']:.2f} + "
                     f"{c['network']:.2f} + {c['transport']:.2f} = {c['total']:.2f} | {study_alone} | "
                     f"{row['robot_alone_cpu_s']:.2f} / {row['network_alone_cpu_s']:.2f} | "
                     f"{row['wall_s']:.1f} ({row['realtime_factor']:.1f}x) | {row['pdr']:.3f} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
