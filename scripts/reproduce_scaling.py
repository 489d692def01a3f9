#!/usr/bin/env python3
"""The reference study's scaling experiment (section V-A, Fig. 4) with SwarmNet.

Runs the sweep configs/sweeps/paper-scaling.yaml (configs/paper/evaluation.yaml for 25 to 6400
robots at constant density; the arena's side and the simulated duration are linked to the robot
count) with `swarmnet sweep`, which is resumable, then writes into the sweep's directory:
  scaling.png  CPU seconds per simulated second of each half, and the real-time factor, against
               the number of robots (log scales), with the study's ARGoS/ns-3 and ARGoS/ns-2
               figures (its Tables II and I, 200 simulated seconds) beside ours
  table.md     the same numbers as a Markdown table

  python3 scripts/reproduce_scaling.py --build build
  python3 scripts/reproduce_scaling.py --results runs/sweeps/paper-scaling/results.csv  # draw only

Durations differ between sizes (the sweep file says which), so sizes are compared per simulated
second. Needs matplotlib (Debian: python3-matplotlib); run under a python3 without it, it restarts
itself under /usr/bin/python3 when that one has it (figure_python.py).
"""
import argparse
import csv
import pathlib
import subprocess
import sys
from collections import defaultdict

from figure_python import require_matplotlib
from reproduce_overhead import TABLE_I_NS2, TABLE_II_NS3

# The study's CPU seconds for 200 simulated seconds, integrated runs: (robot simulator, network
# simulator), the first two columns of its Tables II (ARGoS with ns-3) and I (ARGoS with ns-2).
STUDY_NS3 = {n: row[:2] for n, row in TABLE_II_NS3.items()}
STUDY_NS2 = {n: row[:2] for n, row in TABLE_I_NS2.items()}
STUDY_DURATION_S = 200.0

FIELDS = ["arena.width_m", "duration_s", "cpu_s.robot", "cpu_s.network", "cpu_s.transport",
          "cpu_s.total", "wall_s", "realtime_factor", "pdr"]


def read_results(path):
    """Mean of each field over the seeds of each robot count, from the sweep's results.csv."""
    groups = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] == "ok":
                groups[int(row["robots.count"])].append(row)
    means = {}
    for n, rows in sorted(groups.items()):
        means[n] = {field: sum(float(r[field]) for r in rows) / len(rows) for field in FIELDS}
        means[n]["seeds"] = len(rows)
    return means


def table(means):
    lines = ["| robots | arena (m) | simulated s | CPU s: robot + network + transport = total "
             "| CPU s per simulated s: robot / network | study, CPU s per simulated s: ARGoS / "
             "ns-3 (ns-2) | wall s | real-time factor | delivery ratio |",
             "|---|---|---|---|---|---|---|---|---|"]
    for n, m in means.items():
        d = m["duration_s"]
        study = "-"
        if n in STUDY_NS3:
            (a3, n3), (a2, n2) = STUDY_NS3[n], STUDY_NS2[n]
            study = (f"{a3 / STUDY_DURATION_S:.3f} / {n3 / STUDY_DURATION_S:.3f} "
                     f"({n2 / STUDY_DURATION_S:.3f})")
        lines.append(
            f"| {n} | {m['arena.width_m']:g} | {d:g} | {m['cpu_s.robot']:.2f} + "
            f"{m['cpu_s.network']:.2f} + {m['cpu_s.transport']:.2f} = {m['cpu_s.total']:.2f} | "
            f"{m['cpu_s.robot'] / d:.4f} / {m['cpu_s.network'] / d:.4f} | {study} | "
            f"{m['wall_s']:.1f} | {m['realtime_factor']:.2f} | {m['pdr']:.3f} |")
    return "\n".join(lines) + "\n"


def figure(means, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = list(means)
    per_s = {half: [means[k][f"cpu_s.{half}"] / means[k]["duration_s"] for k in n]
             for half in ("robot", "network", "transport")}
    fig, (cpu, rtf) = plt.subplots(1, 2, figsize=(12, 4.8))
    cpu.plot(n, per_s["network"], "o-", color="tab:blue", label="SwarmNet network half")
    cpu.plot(n, per_s["robot"], "s-", color="tab:green", label="SwarmNet robot half")
    cpu.plot(n, per_s["transport"], "^-", color="tab:gray", label="SwarmNet transport")
    sn = sorted(STUDY_NS3)
    cpu.plot(sn, [STUDY_NS3[k][1] / STUDY_DURATION_S for k in sn], "o--", color="tab:red",
             mfc="none", label="study: ns-3 (Table II)")
    cpu.plot(sn, [STUDY_NS2[k][1] / STUDY_DURATION_S for k in sn], "d--", color="tab:orange",
             mfc="none", label="study: ns-2 (Table I)")
    cpu.plot(sn, [STUDY_NS3[k][0] / STUDY_DURATION_S for k in sn], "s--", color="tab:olive",
             mfc="none", label="study: ARGoS (Table II)")

    rtf.plot(n, [means[k]["realtime_factor"] for k in n], "o-", color="tab:blue",
             label="SwarmNet (simulated s / wall s)")
    # The study's halves alternate in lockstep, so its wall time is about the sum of their CPU.
    rtf.plot(sn, [STUDY_DURATION_S / sum(STUDY_NS3[k]) for k in sn], "o--", color="tab:red",
             mfc="none", label="study ARGoS/ns-3: 200 s / CPU sum")
    rtf.plot(sn, [STUDY_DURATION_S / sum(STUDY_NS2[k]) for k in sn], "d--", color="tab:orange",
             mfc="none", label="study ARGoS/ns-2: 200 s / CPU sum")
    rtf.axhline(1.0, color="black", linestyle=":", linewidth=1, label="real time")
    # Sizes simulated for a shorter time than most are marked with their duration.
    durations = [means[k]["duration_s"] for k in n]
    usual = max(set(durations), key=durations.count)
    for k, d in zip(n, durations):
        if d != usual:
            rtf.annotate(f"{d:g} s", (k, means[k]["realtime_factor"]), textcoords="offset points",
                         xytext=(4, 6), fontsize=7)
    rtf.text(0.02, 0.02, f"{usual:g} simulated s unless marked", transform=rtf.transAxes,
             fontsize=7)
    for axis, ylabel, title in ((cpu, "CPU seconds per simulated second", "CPU time of each half"),
                                (rtf, "real-time factor", "Speed against real time")):
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("robots (constant density)")
        axis.set_ylabel(ylabel)
        axis.set_title(title)
        axis.set_xticks(n)
        axis.set_xticklabels([str(k) for k in n], rotation=60, fontsize=7)
        axis.minorticks_off()
        axis.grid(True, which="major", alpha=0.3)
        axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    require_matplotlib()  # before the sweep: the figure at the end needs it
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="build directory holding bin/swarmnet")
    parser.add_argument("--sweep", default="configs/sweeps/paper-scaling.yaml")
    parser.add_argument("--out", default="runs/sweeps/paper-scaling", help="sweep directory")
    parser.add_argument("--jobs", default="1", help="runs at once; 1 measures each run alone")
    parser.add_argument("--results", help="an existing results.csv: draw it, run nothing")
    args = parser.parse_args()
    if args.results:
        results = pathlib.Path(args.results)
    else:
        binary = pathlib.Path(args.build).resolve() / "bin" / "swarmnet"
        code = subprocess.run([str(binary), "sweep", args.sweep, "-j", args.jobs,
                               "--out", args.out]).returncode
        if code != 0:
            sys.exit(f"swarmnet sweep exited {code}")
        results = pathlib.Path(args.out) / "results.csv"
    means = read_results(results)
    if not means:
        sys.exit(f"{results}: no finished runs")
    text = table(means)
    (results.parent / "table.md").write_text(text)
    figure(means, results.parent / "scaling.png")
    print(text, end="")
    print(f"wrote {results.parent / 'table.md'} and {results.parent / 'scaling.png'}",
          file=sys.stderr)


if __name__ == "__main__":
    main()
