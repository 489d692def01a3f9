#!/usr/bin/env python3
"""The reference study's overhead experiment (section V-B, Tables I and II) with SwarmNet.

For each swarm size, at the study's constant density (500 x 500 m for 50 robots), 200 simulated
seconds of the evaluation scenario (802.11 DCF, AODV, 20% CBR at 5 packets/s):
  integrated   the two-process run: CPU of the robot half, the network half and the transport
  robot alone  the robot half with the study's simplified one-hop model (120 m disk, ideal MAC,
               direct routing) and no traces
  network alone  `swarmnet replay` of the integrated run: the network half from the recorded
               positions and traffic
--config chooses the network and the study's table beside ours:
  ns3  configs/paper/evaluation.yaml: 802.11a at 6 Mbit/s, 120 m range (Table II, ARGoS/ns-3)
  ns2  configs/paper/evaluation-ns2.yaml: ns-2.35's defaults, two-ray ground, 250 m range,
       550 m carrier sense, RTS/CTS (Table I, ARGoS/ns-2)
--engine ns3 runs the integrated and the network-alone runs with ns-3.37 as the network half
(network.engine: ns3, docs/ns3-engine.md): the study's own kind of system, SwarmNet's robot half
with ns-3, beside the study's ARGoS + ns-3.
With --ns2-robots, ns-2.35 itself also runs alone on the integrated run's motion and traffic at
those sizes (scripts/ns2_standalone.py; needs Debian's ns2): the study's standalone ns-2 on this
machine.
Writes OUT/results.json and OUT/table.md.

  python3 scripts/reproduce_overhead.py --build build --out runs/paper-overhead
  python3 scripts/reproduce_overhead.py --build build --config ns2 --out runs/paper-overhead-ns2 \
      --ns2-robots 25,50,75,100
  python3 scripts/reproduce_overhead.py --build build --engine ns3 --robots 200 \
      --out runs/paper-overhead-ns3-engine
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

import ns3_aodv_rules

# The study's tables: ARGoS with the network simulator (ARGoS, network, sum) and standalone
# (ARGoS, network), CPU seconds. Table II is ns-3, Table I ns-2; the standalone ARGoS column is the
# same run in both.
TABLE_II_NS3 = {25: (9.0, 2.9, 11.9, 9.5, 3.4), 50: (17.6, 15.2, 32.8, 18.3, 19.2),
                75: (24.8, 34.9, 59.7, 27.8, 28.6), 100: (30.8, 52.8, 83.6, 40.5, 53.2),
                125: (37.0, 106.7, 143.7, 53.6, 98.7), 150: (42.2, 124.8, 167.0, 68.7, 133.9),
                175: (46.7, 150.3, 197.0, 83.5, 174.9), 200: (52.7, 259.5, 312.2, 103.3, 288.5)}
TABLE_I_NS2 = {25: (9.1, 3.1, 12.2, 9.5, 2.8), 50: (17.9, 16.6, 34.5, 18.3, 16.0),
               75: (26.1, 36.3, 62.4, 27.8, 38.5), 100: (30.2, 76.2, 106.4, 40.5, 81.1),
               125: (35.2, 217.0, 252.2, 53.6, 212.8), 150: (41.3, 284.4, 325.7, 68.7, 329.6),
               175: (46.3, 365.2, 411.5, 83.5, 403.3), 200: (51.9, 393.7, 445.6, 103.3, 567.9)}

# --config: the scenario, the study's network simulator and its table.
CONFIGS = {"ns3": ("evaluation.yaml", "ns-3", TABLE_II_NS3),
           "ns2": ("evaluation-ns2.yaml", "ns-2", TABLE_I_NS2)}

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
    parser.add_argument("--config", choices=sorted(CONFIGS), default="ns3",
                        help="network configuration and the study's table to compare with")
    parser.add_argument("--engine", choices=["native", "ns3"], default="native",
                        help="the network half of the integrated and network-alone runs")
    parser.add_argument("--no-network-alone", action="store_true",
                        help="skip the network-alone replay (it costs as much as the run's network "
                             "half)")
    parser.add_argument("--ns2-robots", default="",
                        help="sizes at which to run ns-2.35 alone too (--config ns2 only)")
    parser.add_argument("--ns2-cpu-limit-s", default="0",
                        help="stop ns-2 after this many CPU seconds (0: no limit)")
    args = parser.parse_args()
    ns2_sizes = {int(x) for x in args.ns2_robots.split(",") if x}
    if ns2_sizes and args.config != "ns2":
        parser.error("--ns2-robots compares with ns-2's defaults: use it with --config ns2")
    root = pathlib.Path(__file__).resolve().parent.parent
    binary = pathlib.Path(args.build).resolve() / "bin" / "swarmnet"
    scenario_file, simulator, study_table = CONFIGS[args.config]
    scenario = root / "configs" / "paper" / scenario_file
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for n in [int(x) for x in args.robots.split(",")]:
        side = round(500 * math.sqrt(n / 50), 1)
        common = ["--set", f"robots.count={n}", "--set", f"arena.width_m={side}",
                  "--set", f"arena.height_m={side}", "--set", f"duration_s={args.duration_s}",
                  "--quiet"]
        integrated, alone, replay = out / f"integrated-{n}", out / f"robot-alone-{n}", out / f"replay-{n}"
        # ns-3.37's AODV's sequence-number and control-message rules (docs/ns3-engine.md):
        # say so.
        engine = (["--set", "network.engine=ns3"] + ns3_aodv_rules.set_arguments()
                  if args.engine == "ns3" else [])
        swarmnet(binary, "run", str(scenario), *common, *engine, "--out", str(integrated),
                 "--overwrite")
        swarmnet(binary, "run", str(scenario), *common, *ONE_HOP, "--out", str(alone), "--overwrite")
        if not args.no_network_alone:
            swarmnet(binary, "replay", str(integrated), "--out", str(replay), "--quiet")
        i, a = summary(integrated), summary(alone)
        r = None if args.no_network_alone else summary(replay)
        rows.append({"config": args.config, "engine": args.engine, "robots": n, "arena_m": side, "integrated": i["cpu_s"],
                     "wall_s": i["wall_s"], "realtime_factor": i["realtime_factor"],
                     "pdr": i["pdr"], "robot_alone_cpu_s": a["cpu_s"]["robot"],
                     "network_alone_cpu_s": r["cpu_s"]["network"] if r else None})
        if n in ns2_sizes:
            ns2 = subprocess.run([sys.executable, str(root / "scripts" / "ns2_standalone.py"),
                                  str(integrated), "--cpu-limit-s", args.ns2_cpu_limit_s],
                                 capture_output=True, text=True)
            if ns2.returncode != 0:
                sys.exit(f"ns-2 on {integrated} failed:\n{ns2.stdout}{ns2.stderr}")
            rows[-1]["ns2_standalone"] = json.loads(ns2.stdout)
        print(f"{n} robots done", file=sys.stderr)
        # Written after every size, so that a long sweep stopped part way keeps what it measured.
        write_outputs(out, rows, simulator, study_table, bool(ns2_sizes), args.engine)
    print((out / "table.md").read_text(), end="")


def ns2_cell(ns2):
    if not ns2:
        return " - |"
    if ns2["stopped"]:
        return f" > {ns2['cpu_s']:.0f} (stopped) |"
    return f" {ns2['cpu_s']:.2f} ({ns2['pdr']:.3f}) |"


def write_outputs(out, rows, simulator, study_table, with_ns2, engine):
    (out / "results.json").write_text(json.dumps(rows, indent=2) + "\n")
    ours = "SwarmNet integrated" if engine == "native" else "SwarmNet + ns-3 engine"
    lines = [f"| robots | arena (m) | study: ARGoS + {simulator} = sum | {ours}: robot + "
             f"network + transport = sum | study standalone: ARGoS / {simulator} | SwarmNet "
             "standalone: robot half (disk) / network half (replay) | SwarmNet wall s (real-time "
             "factor) | delivery ratio |" + (" ns-2.35 alone here: CPU s (delivery ratio) |"
                                            if with_ns2 else ""),
             "|---|---|---|---|---|---|---|---|" + ("---|" if with_ns2 else "")]
    for row in rows:
        c, s = row["integrated"], study_table.get(row["robots"])
        study = f"{s[0]} + {s[1]} = {s[2]}" if s else "-"
        study_alone = f"{s[3]} / {s[4]}" if s else "-"
        lines.append(f"| {row['robots']} | {row['arena_m']:g} | {study} | {c['robot']:.2f} + "
                     f"{c['network']:.2f} + {c['transport']:.2f} = {c['total']:.2f} | {study_alone} | "
                     f"{row['robot_alone_cpu_s']:.2f} / "
                     f"{'-' if row['network_alone_cpu_s'] is None else format(row['network_alone_cpu_s'], '.2f')} | "
                     f"{row['wall_s']:.1f} ({row['realtime_factor']:.1f}x) | {row['pdr']:.3f} |")
        if with_ns2:
            lines[-1] += ns2_cell(row.get("ns2_standalone"))
    (out / "table.md").write_text("\n".join(lines) + "\n")

if __name__ == "__main__":
    main()
