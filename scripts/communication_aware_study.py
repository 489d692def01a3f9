#!/usr/bin/env python3
"""The communication-aware study (docs/communication-aware.md): does a controller that senses its
links do better than one that does not, on 802.11a with SINR and AODV or flooding?

Runs two sweeps with `swarmnet sweep` (resumable: run it again after an interruption, finished
runs are skipped), then writes into the report folder (default runs/studies/communication-aware):

  Experiment 1, a relay chain (configs/sweeps/relay-chain.yaml, 360 runs):
  relay_chain.png      per shadowing (columns) the fraction of time the leader has a route to the
                       base, the delivery ratio of its reports and the distance it reached,
                       against the number of relays, one series per mode, 95% intervals
  relay_chain.md/.csv  per (relays, shadowing, mode): runs, and each metric's mean and interval
  relay_chain_welch.md/.csv  Welch's t-test between the modes in each (relays, shadowing) cell,
                       p-values Holm-adjusted over all of a metric's comparisons

  Experiment 2, the reference study's task allocation (configs/sweeps/task-allocation-aware.yaml,
  1200 runs):
  task_allocation.png  per (robots, events) panel the mean completion time per model, the paper's
                       controller beside the communication-aware one, 95% intervals
  task_allocation.md/.csv  per (robots, events, model, controller): runs, unfinished runs,
                       completion time, messages and beacons sent
  task_allocation_welch.md/.csv  aware against paper in each (robots, events, model) cell, Holm
  study.json           every figure above, and the gap between 802.11a and `all` per
                       controller (what section VI measured and experiment 2 asks to close)

  python3 scripts/communication_aware_study.py --build build -j 2
  python3 scripts/communication_aware_study.py --analyse-only    # the sweeps' results.csv as they are
  python3 scripts/communication_aware_study.py --relay-results A.csv --task-results B.csv

Statistics (means, intervals, Welch's tests, Holm) come from `swarmnet stats`
(docs/experiments.md) on the runs.csv files this script writes beside the tables. A task
allocation run that reached the cap counts at the cap, a lower bound of its completion time, as in
scripts/reproduce_task_allocation.py, whose reading of results.csv this script shares.
"""
import argparse
import csv
import json
import pathlib
import subprocess
import sys

from figure_python import require_matplotlib
from reproduce_task_allocation import fmt, fmt_p, read_runs
from swarmnet_stats import grouped_stats

RELAY_SWEEP = "configs/sweeps/relay-chain.yaml"
RELAY_OUT = "runs/sweeps/relay-chain"
TASK_SWEEP = "configs/sweeps/task-allocation-aware.yaml"
TASK_OUT = "runs/sweeps/task-allocation-aware"
REPORT = "runs/studies/communication-aware"

MODES = ["none", "geometric", "link_aware"]
MODELS = ["all", "p50", "p75", "p100", "80211a"]
CONTROLLERS = ["paper", "aware"]
ALPHA = 0.05

# results.csv columns of the relay chain (grid keys, and summary.json flattened)
RELAY_COLUMNS = {
    "robots": "robots.count",
    "sigma_db": "network.propagation.1.params.sigma_db",
    "mode": "robots.controllers.0.params.mode",
}
# metric name in runs.csv -> (results.csv column, what it is)
RELAY_METRICS = {
    "route_ratio": ("controllers.route_to_base.mean",
                    "share of steps the leader's AODV held a valid route to the base"),
    "pdr": ("pdr", "delivery ratio of the leader's reports to the base"),
    "reach_m": ("controllers.distance_m.max", "farthest the leader got (m)"),
    "connected_reach_m": ("controllers.connected_distance_m.max",
                          "farthest the leader got while holding a route (m)"),
}
AWARE_FLAG = "robots.controllers.0.params.reannounce_on_encounter"


def say(text):
    print(f"communication_aware_study: {text}", file=sys.stderr, flush=True)


def number(text):
    return float(text) if text not in (None, "") else None


def read_csv(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        return reader.fieldnames or [], list(reader)


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def interval(g, digits):
    if g is None or g["mean"] is None:
        return "-"
    if g["ci_low"] is None:
        return fmt(g["mean"], digits)
    return f"{fmt(g['mean'], digits)} [{fmt(g['ci_low'], digits)}, {fmt(g['ci_high'], digits)}]"


def markdown(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


# ---- experiment 1: the relay chain ------------------------------------------------------------

def read_relay_runs(path):
    columns, rows = read_csv(path)
    needed = list(RELAY_COLUMNS.values()) + [c for c, _ in RELAY_METRICS.values()] + ["status"]
    missing = [c for c in needed if c not in columns]
    if missing:
        sys.exit(f"{path}: no column {', '.join(missing)}: not results.csv of {RELAY_SWEEP}")
    runs, failed = [], []
    for line, row in enumerate(rows, start=2):
        if row["status"] != "ok":
            failed.append(row.get("run_id", f"line {line}"))
            continue
        run = {"run_id": row["run_id"], "seed": row["seed"],
               "relays": int(row[RELAY_COLUMNS["robots"]]) - 2,
               "sigma_db": float(row[RELAY_COLUMNS["sigma_db"]]),
               "mode": row[RELAY_COLUMNS["mode"]]}
        for metric, (column, _) in RELAY_METRICS.items():
            value = number(row[column])
            if value is None:
                sys.exit(f"{path}:{line} ({row['run_id']}): {column} is empty in an ok run")
            run[metric] = value
        runs.append(run)
    return runs, failed


def analyse_relay_chain(results, folder, binary):
    runs, failed = read_relay_runs(results)
    if not runs:
        sys.exit(f"{results}: no finished run")
    runs_csv = folder / "relay_chain_runs.csv"
    write_csv(runs_csv, ["run_id", "seed", "relays", "sigma_db", "mode", *RELAY_METRICS],
              [[r["run_id"], r["seed"], r["relays"], f"{r['sigma_db']:g}", r["mode"],
                *[repr(r[m]) for m in RELAY_METRICS]] for r in runs])
    say(f"statistics: {binary} stats {runs_csv} (the modes compared in each cell)")
    stats = grouped_stats(binary, runs_csv, ["relays", "sigma_db", "mode"], "mode",
                           list(RELAY_METRICS))
    relays = sorted({r["relays"] for r in runs})
    sigmas = sorted({r["sigma_db"] for r in runs})
    modes = [m for m in MODES if any(r["mode"] == m for r in runs)]
    digits = {"route_ratio": 3, "pdr": 3, "reach_m": 0, "connected_reach_m": 0}
    header = ["relays", "shadowing (dB)", "mode", "runs"] + list(RELAY_METRICS)
    rows = []
    for k in relays:
        for s in sigmas:
            for m in modes:
                key = (str(k), f"{s:g}", m)
                n = stats["pdr"]["groups"].get(key, {}).get("n", 0)
                rows.append([k, f"{s:g}", m, n] +
                            [interval(stats[x]["groups"].get(key), digits[x])
                             for x in RELAY_METRICS])
    write_csv(folder / "relay_chain.csv", header, rows)
    legend = "".join(f"- `{m}`: {text}; mean [95% interval]\n"
                     for m, (_, text) in RELAY_METRICS.items())
    (folder / "relay_chain.md").write_text(
        f"# Relay chain: {len(runs)} runs ({len(failed)} failed)\n\n{legend}\n" +
        markdown(header, rows))
    welch_rows = []
    for metric in RELAY_METRICS:
        for t in stats[metric]["welch"]:
            a, b = t["a"], t["b"]
            ga, gb = stats[metric]["groups"][a], stats[metric]["groups"][b]
            welch_rows.append([metric, a[0], a[1], a[2], b[2], fmt(ga["mean"], digits[metric]),
                               fmt(gb["mean"], digits[metric]), fmt(t["t"], 2), fmt(t["df"], 1),
                               fmt_p(t["p"]), fmt_p(t["p_holm"])])
    welch_header = ["metric", "relays", "shadowing (dB)", "mode a", "mode b", "mean a", "mean b",
                    "t", "df", "p", "p (Holm)"]
    write_csv(folder / "relay_chain_welch.csv", welch_header, welch_rows)
    (folder / "relay_chain_welch.md").write_text(
        "# Relay chain: Welch's t-tests between modes, per cell\n\nHolm's correction over all "
        "of a metric's comparisons.\n\n" + markdown(welch_header, welch_rows))
    relay_figure(stats, relays, sigmas, modes, folder / "relay_chain.png")
    return {"runs": len(runs), "failed": failed, "cells": {
        ",".join(k): {m: stats[m]["groups"][k] for m in RELAY_METRICS}
        for k in stats["pdr"]["groups"]},
        "welch": {m: stats[m]["welch"] for m in RELAY_METRICS}}


def relay_figure(stats, relays, sigmas, modes, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    colors = {"none": "tab:gray", "geometric": "tab:orange", "link_aware": "tab:blue"}
    panels = [("route_ratio", "time with a route"), ("pdr", "reports delivered"),
              ("connected_reach_m", "farthest with a route (m)")]
    fig, axes = plt.subplots(len(panels), len(sigmas), figsize=(4.2 * len(sigmas), 8.5),
                             sharex=True, sharey="row", squeeze=False)
    for col, s in enumerate(sigmas):
        for row, (metric, label) in enumerate(panels):
            axis = axes[row, col]
            for i, m in enumerate(modes):
                xs, ys, lo, hi = [], [], [], []
                for k in relays:
                    g = stats[metric]["groups"].get((str(k), f"{s:g}", m))
                    if g is None or g["mean"] is None:
                        continue
                    xs.append(k + (i - 1) * 0.25)
                    ys.append(g["mean"])
                    lo.append(g["mean"] - (g["ci_low"] if g["ci_low"] is not None else g["mean"]))
                    hi.append((g["ci_high"] if g["ci_high"] is not None else g["mean"]) - g["mean"])
                axis.errorbar(xs, ys, yerr=[lo, hi], marker="o", capsize=3, label=m,
                              color=colors.get(m))
            if col == 0:
                axis.set_ylabel(label)
            if row == 0:
                axis.set_title("log-distance" if s == 0 else f"log-distance + {s:g} dB shadowing")
            axis.grid(alpha=0.3)
        axes[-1, col].set_xlabel("relays")
        axes[-1, col].set_xticks(relays)
    axes[0, 0].legend()
    fig.suptitle("Relay chain over 802.11a + AODV: mean over seeds, 95% intervals")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


# ---- experiment 2: task allocation --------------------------------------------------------------

def read_task_runs(path):
    runs, failed, types = read_runs(path)
    _, rows = read_csv(path)
    if rows and AWARE_FLAG not in rows[0]:
        sys.exit(f"{path}: no column {AWARE_FLAG}: not results.csv of {TASK_SWEEP}")
    by_id = {r["run_id"]: r for r in rows}
    for run in runs:
        row = by_id[run["run_id"]]
        run["controller"] = "aware" if row[AWARE_FLAG] == "true" else "paper"
        run["beacons"] = number(row.get("controllers.beacons.count")) or 0.0
        run["reannounced"] = number(row.get("controllers.reannounced.count")) or 0.0
    return runs, failed, types


def analyse_task_allocation(results, folder, binary):
    runs, failed, types = read_task_runs(results)
    if not runs:
        sys.exit(f"{results}: no finished run")
    runs_csv = folder / "task_allocation_runs.csv"
    write_csv(runs_csv, ["run_id", "seed", "robots", "events", "model", "controller", "finished",
                         "completion_time_s", "messages", "beacons", "reannounced"],
              [[r["run_id"], r["seed"], *r["cell"], r["controller"], int(r["finished"]),
                repr(r["time"]), repr(sum(r["sent"].values())), repr(r["beacons"]),
                repr(r["reannounced"])] for r in runs])
    by = ["robots", "events", "model", "controller"]
    metrics = ["completion_time_s", "messages", "beacons", "reannounced"]
    say(f"statistics: {binary} stats {runs_csv} (aware against paper in each cell)")
    stats = grouped_stats(binary, runs_csv, by, "controller", metrics, baseline="paper")
    cells = sorted({r["cell"] for r in runs}, key=lambda c: (c[0], c[1], MODELS.index(c[2])
                                                          if c[2] in MODELS else len(MODELS)))
    unfinished = {}
    for r in runs:
        key = (*r["cell"], r["controller"])
        unfinished[key] = unfinished.get(key, 0) + (0 if r["finished"] else 1)
    header = ["robots", "events", "model", "controller", "runs", "unfinished",
              "completion (s)", "messages", "beacons", "re-announcements"]
    rows = []
    for robots, events, model in cells:
        for c in CONTROLLERS:
            key = (str(robots), str(events), model, c)
            g = stats["completion_time_s"]["groups"].get(key)
            if g is None:
                continue
            rows.append([robots, events, model, c, g["n"],
                         unfinished.get((robots, events, model, c), 0),
                         interval(g, 0), interval(stats["messages"]["groups"][key], 0),
                         fmt(stats["beacons"]["groups"][key]["mean"], 0),
                         fmt(stats["reannounced"]["groups"][key]["mean"], 1)])
    write_csv(folder / "task_allocation.csv", header, rows)
    (folder / "task_allocation.md").write_text(
        f"# Task allocation, paper against aware controller: {len(runs)} runs "
        f"({len(failed)} failed)\n\nCompletion time: mean [95% interval] over runs; an "
        "unfinished run counts at the cap (a lower bound). Messages: the study's five, per run "
        "(beacons apart).\n\n" + markdown(header, rows))
    welch_rows = []
    for t in stats["completion_time_s"]["welch"]:
        paper, aware = (t["a"], t["b"]) if t["a"][3] == "paper" else (t["b"], t["a"])
        gp = stats["completion_time_s"]["groups"][paper]
        ga = stats["completion_time_s"]["groups"][aware]
        welch_rows.append([*paper[:3], fmt(gp["mean"], 0), fmt(ga["mean"], 0),
                           fmt(ga["mean"] - gp["mean"], 0), fmt(t["t"], 2), fmt(t["df"], 1),
                           fmt_p(t["p"]), fmt_p(t["p_holm"])])
    welch_header = ["robots", "events", "model", "paper (s)", "aware (s)", "aware - paper (s)",
                    "t", "df", "p", "p (Holm)"]
    write_csv(folder / "task_allocation_welch.csv", welch_header, welch_rows)
    (folder / "task_allocation_welch.md").write_text(
        "# Task allocation: Welch's t-test of the completion time, aware against paper\n\n"
        "Holm's correction over all the cells' comparisons.\n\n" +
        markdown(welch_header, welch_rows))
    gaps = {}
    groups = stats["completion_time_s"]["groups"]
    for robots, events in sorted({(c[0], c[1]) for c in cells}):
        gap = {}
        for c in CONTROLLERS:
            real = groups.get((str(robots), str(events), "80211a", c))
            ideal = groups.get((str(robots), str(events), "all", c))
            if real and ideal:
                gap[c] = real["mean"] - ideal["mean"]
        if len(gap) == 2:
            gap["closed_fraction"] = (1 - gap["aware"] / gap["paper"]) if gap["paper"] else None
        gaps[f"{robots},{events}"] = gap
    task_figure(groups, cells, folder / "task_allocation.png")
    return {"runs": len(runs), "failed": [f["run_id"] for f in failed],
            "cells": {",".join(k): {m: stats[m]["groups"][k] for m in metrics}
                      for k in groups},
            "welch": stats["completion_time_s"]["welch"],
            "gap_80211a_minus_all_s": gaps}


def task_figure(groups, cells, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = sorted({(c[0], c[1]) for c in cells})
    models = [m for m in MODELS if any(c[2] == m for c in cells)]
    fig, axes = plt.subplots(1, len(panels), figsize=(3.6 * len(panels), 4.0), sharey=True,
                             squeeze=False)
    colors = {"paper": "tab:gray", "aware": "tab:blue"}
    for axis, (robots, events) in zip(axes[0], panels):
        for i, c in enumerate(CONTROLLERS):
            xs, ys, lo, hi = [], [], [], []
            for j, m in enumerate(models):
                g = groups.get((str(robots), str(events), m, c))
                if g is None or g["mean"] is None:
                    continue
                xs.append(j + (i - 0.5) * 0.35)
                ys.append(g["mean"])
                lo.append(g["mean"] - (g["ci_low"] if g["ci_low"] is not None else g["mean"]))
                hi.append((g["ci_high"] if g["ci_high"] is not None else g["mean"]) - g["mean"])
            axis.bar(xs, ys, width=0.35, yerr=[lo, hi], capsize=3, color=colors[c], label=c)
        axis.set_xticks(range(len(models)))
        axis.set_xticklabels(models)
        axis.set_title(f"{robots} robots, {events} events")
        axis.grid(axis="y", alpha=0.3)
    axes[0, 0].set_ylabel("task completion time (s)")
    axes[0, 0].legend()
    fig.suptitle("Task allocation: the paper's controller and a communication-aware one")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def run_sweep(binary, sweep, out, jobs):
    say(f"running {sweep} into {out}, {jobs} at a time (resumable: finished runs are skipped)")
    code = subprocess.run([str(binary), "sweep", sweep, "-j", jobs, "--out", out]).returncode
    if code == 1:
        say("some runs failed (listed above); analysing the others, failures counted")
    elif code != 0:
        sys.exit(f"swarmnet sweep {sweep} exited {code}")
    return pathlib.Path(out) / "results.csv"


def main():
    require_matplotlib()  # before the sweeps: the figures at the end need it
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="build directory holding bin/swarmnet")
    parser.add_argument("--swarmnet", help="the swarmnet command (default: BUILD/bin/swarmnet)")
    parser.add_argument("-j", "--jobs", default="2", help="runs at once (swarmnet sweep -j)")
    parser.add_argument("--analyse-only", action="store_true",
                        help="run nothing: analyse the two sweeps' results.csv")
    parser.add_argument("--relay-results", help="with --task-results: analyse these results.csv "
                        "files (of the two sweeps) and run nothing")
    parser.add_argument("--task-results", help="see --relay-results")
    parser.add_argument("--report", default=REPORT, help=f"output folder (default {REPORT})")
    args = parser.parse_args()
    binary = pathlib.Path(args.swarmnet) if args.swarmnet else (
        pathlib.Path(args.build).resolve() / "bin" / "swarmnet")
    if not binary.exists():
        sys.exit(f"{binary}: no swarmnet here (build it, or give --build or --swarmnet)")
    if bool(args.relay_results) != bool(args.task_results):
        sys.exit("--relay-results and --task-results go together")
    if args.relay_results:
        relay_results = pathlib.Path(args.relay_results)
        task_results = pathlib.Path(args.task_results)
        for path in (relay_results, task_results):
            if not path.exists():
                sys.exit(f"{path}: no such file")
    elif args.analyse_only:
        relay_results = pathlib.Path(RELAY_OUT) / "results.csv"
        task_results = pathlib.Path(TASK_OUT) / "results.csv"
        for path in (relay_results, task_results):
            if not path.exists():
                sys.exit(f"{path}: no results yet (run without --analyse-only)")
    else:
        relay_results = run_sweep(binary, RELAY_SWEEP, RELAY_OUT, args.jobs)
        task_results = run_sweep(binary, TASK_SWEEP, TASK_OUT, args.jobs)
    folder = pathlib.Path(args.report)
    folder.mkdir(parents=True, exist_ok=True)
    study = {"relay_chain": analyse_relay_chain(relay_results, folder, binary),
             "task_allocation": analyse_task_allocation(task_results, folder, binary)}
    with open(folder / "study.json.tmp", "w") as f:
        json.dump(study, f, indent=1)
    (folder / "study.json.tmp").replace(folder / "study.json")
    for name in ("relay_chain.png", "relay_chain.md", "relay_chain_welch.md",
                 "task_allocation.png", "task_allocation.md", "task_allocation_welch.md",
                 "study.json"):
        say(f"wrote {folder / name}")


if __name__ == "__main__":
    main()
