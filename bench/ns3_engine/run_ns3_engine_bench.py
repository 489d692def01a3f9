#!/usr/bin/env python3
"""SwarmNet's own network engine against ns-3 as the network half (docs/ns3-engine.md).

For each swarm size at the study's constant density (500 x 500 m for 50 robots) and each seed,
the reference study's scenario (configs/paper/evaluation.yaml: 802.11a DCF at 6 Mbit/s, SINR
reception with a 120 m range, AODV, 20% of the robots sending 512-byte messages 5 times a
second) runs, interleaved, three ways:
  native   `swarmnet run` with network.engine: native (the default)
  ns3      `swarmnet run` with network.engine: ns3: the same robot half, ns-3.37 as network half
  replay   swarmnet_ns3_replay, ns-3 alone, on the ns3 run's own mobility and traffic, with the
           same stack as the engine (ns-3's ARP, not pre-filled): what the coupling adds is the
           ns3 run's network-half CPU (ns-3 plus the step protocol's transport) over this one
Writes OUT/results.json (every run's measures) and OUT/table.md (two tables: native against
ns3 pooled over the seeds, and the coupling overhead).

  python3 bench/ns3_engine/run_ns3_engine_bench.py --build build --out runs/bench-ns3-engine
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent


def run(command):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(map(str, command))} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def measures(summary):
    """What the comparison reads of one summary.json."""
    packets = summary["packets"]
    delivered = packets["delivered"]
    control = summary["routing"].get("control_packets", 0)
    delay = summary.get("delay_s") or {}
    return {"pdr": summary["pdr"], "delivered": delivered,
            "unicast_sent": packets["sent"] - packets.get("broadcast_sent", 0),
            "delay_mean_s": delay.get("mean"), "control_packets": control,
            "control_per_delivery": control / delivered if delivered else None,
            "mac_tx_frames": summary["mac"]["tx_frames"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="build directory")
    parser.add_argument("--out", default="runs/bench-ns3-engine", help="output directory")
    parser.add_argument("--robots", default="50,100,200")
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--duration-s", type=float, default=20.0)
    args = parser.parse_args()
    build = pathlib.Path(args.build).resolve()
    binary, replay = build / "bin" / "swarmnet", build / "bin" / "swarmnet_ns3_replay"
    scenario = ROOT / "configs" / "paper" / "evaluation.yaml"
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for n in [int(x) for x in args.robots.split(",")]:
        side = round(500 * math.sqrt(n / 50), 1)
        for seed in [int(x) for x in args.seeds.split(",")]:
            common = ["--seed", seed, "--set", f"robots.count={n}", "--set", f"arena.width_m={side}",
                      "--set", f"arena.height_m={side}", "--set", f"duration_s={args.duration_s}",
                      "--quiet", "--overwrite"]
            row = {"robots": n, "arena_m": side, "seed": seed}
            for engine in ("native", "ns3"):
                run_dir = out / f"{engine}-{n}-seed{seed}"
                run([binary, "run", scenario, *common, "--set", f"network.engine={engine}",
                     "--out", run_dir])
                summary = json.loads((run_dir / "summary.json").read_text())
                cpu = summary["cpu_s"]
                row[engine] = {**measures(summary), "cpu_s": cpu,
                               "network_cpu_per_sim_s": cpu["network"] / summary["sim_time_s"],
                               "realtime_factor": summary["realtime_factor"]}
            ns3_dir = out / f"ns3-{n}-seed{seed}"
            alone = json.loads(run([replay, ns3_dir, "--routing", "aodv", "--seed", seed,
                                    "--arp-entries", "none"]))
            row["ns3_alone"] = {"cpu_s": alone["cpu_s"]["network"], "pdr": alone["pdr"]}
            rows.append(row)
            print(f"{n} robots, seed {seed} done", file=sys.stderr)
            write_outputs(out, rows)  # after every run, so that a stopped sweep keeps its rows
    print((out / "table.md").read_text(), end="")


def pooled(rows, engine, key):
    values = [r[engine][key] for r in rows if r[engine][key] is not None]
    return sum(values) / len(values) if values else None


def fmt(value, spec):
    return "-" if value is None else format(value, spec)


def write_outputs(out, rows):
    (out / "results.json").write_text(json.dumps(rows, indent=2) + "\n")
    sizes = sorted({r["robots"] for r in rows})
    lines = ["| robots | seeds | delivery native / ns3 | mean delay ms native / ns3 | control "
             "packets per delivery native / ns3 | network CPU s per simulated s native / ns3 | "
             "real-time factor native / ns3 |", "|---|---|---|---|---|---|---|"]
    for n in sizes:
        group = [r for r in rows if r["robots"] == n]
        pdr = {e: sum(r[e]["delivered"] for r in group) / max(1, sum(r[e]["unicast_sent"]
                                                                   for r in group))
               for e in ("native", "ns3")}
        delay = {e: pooled(group, e, "delay_mean_s") for e in ("native", "ns3")}
        cpd = {e: pooled(group, e, "control_per_delivery") for e in ("native", "ns3")}
        cpu = {e: pooled(group, e, "network_cpu_per_sim_s") for e in ("native", "ns3")}
        rtf = {e: pooled(group, e, "realtime_factor") for e in ("native", "ns3")}
        lines.append(
            f"| {n} | {len(group)} | {pdr['native']:.3f} / {pdr['ns3']:.3f} "
            f"({100 * (pdr['ns3'] - pdr['native']):+.1f} points) | "
            f"{fmt(delay['native'] and delay['native'] * 1e3, '.1f')} / "
            f"{fmt(delay['ns3'] and delay['ns3'] * 1e3, '.1f')} | {fmt(cpd['native'], '.2f')} / "
            f"{fmt(cpd['ns3'], '.2f')} | {cpu['native']:.3f} / {cpu['ns3']:.3f} | "
            f"{rtf['native']:.1f}x / {rtf['ns3']:.1f}x |")
    lines += ["", "| robots | seed | ns3 engine: ns-3 + transport CPU s | ns-3 alone "
              "(swarmnet_ns3_replay) CPU s | coupling adds | delivery engine / alone |",
              "|---|---|---|---|---|---|"]
    for r in rows:
        engine_cpu = r["ns3"]["cpu_s"]["network"] + r["ns3"]["cpu_s"]["transport"]
        alone = r["ns3_alone"]["cpu_s"]
        lines.append(f"| {r['robots']} | {r['seed']} | {engine_cpu:.2f} | {alone:.2f} | "
                     f"{100 * (engine_cpu / alone - 1):+.1f}% | {r['ns3']['pdr']:.3f} / "
                     f"{r['ns3_alone']['pdr']:.3f} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
