#!/usr/bin/env python3
"""SwarmNet's own network engine against ns-3 as the network half (docs/ns3-engine.md).

For each swarm size at the study's constant density (500 x 500 m for 50 robots) and each seed,
the reference study's scenario (configs/paper/evaluation.yaml: 802.11a DCF at 6 Mbit/s, SINR
reception with a 120 m range, AODV, 20% of the robots sending 512-byte messages 5 times a
second) runs, interleaved, in two pairs:
  native-static  `swarmnet run` with network.engine: native and network.arp: static (every
                 address known before the run, no ARP frame)
  ns3-static     the same with network.engine: ns3: ns-3.37 as the network half, with the
                 models corresponding to SwarmNet's
  native         `swarmnet run` with network.engine: native and ARP (network.arp: ns3, the
                 default; docs/arp.md)
  ns3            the same with network.engine: ns3: ns-3 as its users run it
Each ns-3 variant's delivery is compared with its native pair's.
and, on the ns3 run's own recorded motion and messages, ns-3 alone twice:
  replay       swarmnet_ns3_replay (an independent ns-3 program: ns-2 mobility, the same stack,
               ARP not pre-filled)
  engine-alone `swarmnet replay`: the ns-3 engine without the robot half and the transport
What the coupling adds is the ns3 run's network-half CPU (ns-3, the adapter and the step
protocol's transport) over each of them.
Writes OUT/results.json (every run's measures) and OUT/table.md (two tables: the engines pooled
over the seeds, and the coupling overhead).

  python3 bench/ns3_engine/run_ns3_engine_bench.py --build build --out runs/bench-ns3-engine-arp
With --resume, the measures already in OUT/results.json are kept for every run whose directory
is still there, and only what is missing runs (delete a variant's directories to run it again);
sizes and seeds of OUT/results.json that this sweep does not name stay in the tables.
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import ns3_aodv_rules  # noqa: E402
from seed_interval import student_interval  # noqa: E402
# Every variant: ns-3.37's AODV's sequence-number rules (a broken route's number is not
# incremented; a RREQ leaves the route to its sender without a valid number) and its four
# control-message rules, which the native engine is told to follow, so that the models correspond
# (docs/ns3-engine.md).
ALIGNED = ns3_aodv_rules.set_arguments()
VARIANTS = {"native_static": ["--set", "network.engine=native", "--set", "network.arp=static"],
            "ns3_static": ["--set", "network.engine=ns3", "--set", "network.arp=static"],
            "native": ["--set", "network.engine=native"],
            "ns3": ["--set", "network.engine=ns3"]}
# The native run each ns-3 variant is compared with (same ARP setting).
BASELINE = {"ns3_static": "native_static", "ns3": "native"}


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
    parser.add_argument("--out", default="runs/bench-ns3-engine-arp", help="output directory")
    parser.add_argument("--robots", default="50,100,200")
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--duration-s", type=float, default=20.0)
    parser.add_argument("--resume", action="store_true",
                        help="keep OUT/results.json's measures of runs whose directory exists")
    args = parser.parse_args()
    build = pathlib.Path(args.build).resolve()
    binary, replay = build / "bin" / "swarmnet", build / "bin" / "swarmnet_ns3_replay"
    scenario = ROOT / "configs" / "paper" / "evaluation.yaml"
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    previous = {}
    if args.resume and (out / "results.json").exists():
        previous = {(r["robots"], r["seed"]): r
                    for r in json.loads((out / "results.json").read_text())}
    rows = []
    for n in [int(x) for x in args.robots.split(",")]:
        side = round(500 * math.sqrt(n / 50), 1)
        for seed in [int(x) for x in args.seeds.split(",")]:
            common = ["--seed", seed, "--set", f"robots.count={n}", "--set", f"arena.width_m={side}",
                      "--set", f"arena.height_m={side}", "--set", f"duration_s={args.duration_s}",
                      "--quiet", "--overwrite"]
            row = {"robots": n, "arena_m": side, "seed": seed}
            kept = previous.get((n, seed), {})
            for variant, settings in VARIANTS.items():
                run_dir = out / f"{variant}-{n}-seed{seed}"
                if variant in kept and (run_dir / "summary.json").exists():
                    row[variant] = kept[variant]
                    continue
                run([binary, "run", scenario, *common, *ALIGNED, *settings, "--out", run_dir])
                summary = json.loads((run_dir / "summary.json").read_text())
                cpu = summary["cpu_s"]
                row[variant] = {**measures(summary), "cpu_s": cpu,
                               "network_cpu_per_sim_s": cpu["network"] / summary["sim_time_s"],
                               "realtime_factor": summary["realtime_factor"]}
            ns3_dir = out / f"ns3-{n}-seed{seed}"
            engine_alone = out / f"engine-alone-{n}-seed{seed}"
            if "ns3" in kept and "ns3_alone" in kept and "engine_alone" in kept and \
                    (engine_alone / "summary.json").exists():
                row["ns3_alone"], row["engine_alone"] = kept["ns3_alone"], kept["engine_alone"]
            else:
                alone = json.loads(run([replay, ns3_dir, "--routing", "aodv", "--seed", seed,
                                        "--arp-entries", "none"]))
                row["ns3_alone"] = {"cpu_s": alone["cpu_s"]["network"], "pdr": alone["pdr"]}
                run([binary, "replay", ns3_dir, "--out", engine_alone, "--quiet"])
                summary = json.loads((engine_alone / "summary.json").read_text())
                row["engine_alone"] = {"cpu_s": summary["cpu_s"]["network"],
                                       "pdr": summary["pdr"]}
            rows.append(row)
            print(f"{n} robots, seed {seed} done", file=sys.stderr)
            write_outputs(out, with_earlier(rows, previous), binary)  # a stopped sweep keeps its rows
    print((out / "table.md").read_text(), end="")


def with_earlier(rows, previous):
    """`rows`, plus the earlier results (--resume) of sizes and seeds this sweep did not run."""
    done = {(r["robots"], r["seed"]) for r in rows}
    kept = [r for key, r in previous.items() if key not in done]
    return sorted(rows + kept, key=lambda r: (r["robots"], r["seed"]))


def pooled(rows, engine, key):
    values = [r[engine][key] for r in rows if r[engine][key] is not None]
    return sum(values) / len(values) if values else None


def fmt(value, spec):
    return "-" if value is None else format(value, spec)


def delivery_delta(group, variant, base, binary):
    """The pooled delivery of `variant` minus its native pair's, in points, and with several seeds
    the 95% Student-t interval of the mean per-seed difference (`swarmnet stats`)."""
    def ratio(runs, name):
        return (sum(r[name]["delivered"] for r in runs) /
                max(1, sum(r[name]["unicast_sent"] for r in runs)))
    text = f"{100 * (ratio(group, variant) - ratio(group, base)):+.1f}"
    interval = student_interval(binary, [100 * (r[variant]["pdr"] - r[base]["pdr"])
                                         for r in group])
    if interval is not None:
        text += f"; 95% CI {interval['low']:+.1f} to {interval['high']:+.1f}"
    return f" ({text})"


def write_outputs(out, rows, binary):
    (out / "results.json").write_text(json.dumps(rows, indent=2) + "\n")
    sizes = sorted({r["robots"] for r in rows})
    names = {"native_static": "native, static ARP", "ns3_static": "ns-3, static ARP",
             "native": "native, ARP", "ns3": "ns-3, ARP"}
    lines = ["| robots | runs | engine | delivery | mean delay ms | control packets per delivery | "
             "MAC frames | network CPU s per simulated s | real-time factor |",
             "|---|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        group = [r for r in rows if r["robots"] == n]
        for variant in VARIANTS:
            delivered = sum(r[variant]["delivered"] for r in group)
            pdr = delivered / max(1, sum(r[variant]["unicast_sent"] for r in group))
            base = BASELINE.get(variant)
            delta = "" if base is None else delivery_delta(group, variant, base, binary)
            delay = pooled(group, variant, "delay_mean_s")
            control = sum(r[variant]["control_packets"] for r in group)
            frames = sum(r[variant]["mac_tx_frames"] for r in group) / len(group)
            lines.append(
                f"| {n} | {len(group)} | {names[variant]} | {pdr:.3f}{delta} | "
                f"{fmt(delay and delay * 1e3, '.1f')} | {fmt(control / delivered if delivered else None, '.2f')} | "
                f"{frames:.0f} | {pooled(group, variant, 'network_cpu_per_sim_s'):.3f} | "
                f"{pooled(group, variant, 'realtime_factor'):.1f}x |")
    lines += ["", "| robots | seed | ns-3 engine in the run: ns-3 + transport CPU s | "
              "swarmnet_ns3_replay CPU s (coupling adds) | swarmnet replay, engine alone CPU s "
              "(coupling adds) | delivery: run / replay / engine alone |",
              "|---|---|---|---|---|---|"]
    def coupling_row(label, runs):
        engine_cpu = sum(r["ns3"]["cpu_s"]["network"] + r["ns3"]["cpu_s"]["transport"]
                         for r in runs)
        alone = sum(r["ns3_alone"]["cpu_s"] for r in runs)
        engine_alone = sum(r["engine_alone"]["cpu_s"] for r in runs)
        return (f"| {runs[0]['robots']} | {label} | {engine_cpu:.2f} | {alone:.2f} "
                f"({100 * (engine_cpu / alone - 1):+.1f}%) | {engine_alone:.2f} "
                f"({100 * (engine_cpu / engine_alone - 1):+.1f}%) | "
                + " / ".join(f"{sum(r[k]['pdr'] for r in runs) / len(runs):.3f}"
                             for k in ("ns3", "ns3_alone", "engine_alone")) + " |")
    for n in sizes:
        group = [r for r in rows if r["robots"] == n]
        lines += [coupling_row(str(r["seed"]), [r]) for r in group]
        if len(group) > 1:  # CPU summed over the seeds: the figure; single runs are noisy
            lines.append(coupling_row(f"all {len(group)}, summed", group))
    (out / "table.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
