#!/usr/bin/env python3
"""The reference study's task allocation (section VI, Fig. 5) under six communication models.

Runs the sweep configs/sweeps/task-allocation.yaml (20, 30 and 40 robots x 5, 10, 15 and 20 events
x the models all, p50, p75, p100, 80211a and ns3 x 25 seeds = 1800 runs) with `swarmnet sweep`, which is
resumable (run it again after an interruption: finished runs are skipped), then writes into the
output folder (default: the sweep's directory):
  completion.png   the study's Fig. 5: one panel per robot count (20, 30, 40, top to bottom), mean
                   task completion time against the number of events, one series per model, 95%
                   confidence intervals as error bars
  table.md/.csv    per (robots, events, model): runs finished / runs, mean completion time and its
                   95% CI, messages sent per type (S, G, C, H, A) and robots out of energy per run
  welch.md/.csv    Welch's t-test of the completion time between every pair of models in each
                   (robots, events) cell
  claims.json      the study's three claims about Fig. 5, evaluated on these runs
  runs.csv         one row per finished run with the values above (what `swarmnet stats` reads)

  python3 scripts/reproduce_task_allocation.py --build build -j 2
  python3 scripts/reproduce_task_allocation.py --results runs/sweeps/task-allocation/results.csv

Unfinished runs. A run ends when every event is serviced or at the sweep's cap (duration_s): a run
that reached the cap has no completion time. It is never dropped: it counts at the time it ended
(the cap), a lower bound of its completion time, so a mean that includes one is a lower bound too
(the figure marks such points and says how many runs they hold). Failed runs (no summary) have no
data at all; they are counted and listed.

Statistics (means, Student intervals, Welch's tests) come from `swarmnet stats`
(docs/experiments.md) on runs.csv, so --results needs the built swarmnet too (--build or
--swarmnet). Needs matplotlib (Debian: python3-matplotlib); run under a python3 without it, it
restarts itself under /usr/bin/python3 when that one has it (figure_python.py).
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess
import sys
import textwrap
from collections import defaultdict

from figure_python import require_matplotlib
from swarmnet_stats import grouped_stats

MODELS = ["all", "p50", "p75", "p100", "80211a", "ns3"]  # the sweep's order; others appended
MESSAGE_TYPES = ["S", "G", "C", "H", "A"]           # the study's five messages; others appended
ALPHA = 0.1                                         # the study's "p-values less than 0.1"
CONFIDENCE = 0.95

# results.csv columns (docs/experiments.md: grid keys by key path, summary.json flattened with '.')
ROBOTS = "robots.count"
EVENTS = "world.0.params.events"
MODEL = "name"                                       # the linked axis `model`'s first key
COMPLETION_COUNT = "world.completion_time_s.count"
COMPLETION = "world.completion_time_s.mean"          # one observation: the run's completion time
ENDED_BY = "ended.by"
ENDED_AT = "ended.at_s"
CAP = "duration_s"                              # the scenario's duration_s: the cap
OUT_OF_ENERGY = "world.out_of_energy.count"          # one observation per robot that ran flat
DISTANCE = "world.distance_m.mean"                   # one observation per robot
SENT_PREFIX, SENT_SUFFIX = "controllers.sent.", ".count"


def say(text):
    print(f"reproduce_task_allocation: {text}", file=sys.stderr, flush=True)


def number(text):
    return float(text) if text not in (None, "") else None


def ordered(values, preferred):
    values = set(values)
    return [v for v in preferred if v in values] + sorted(values - set(preferred))


def read_runs(path):
    """Every row of results.csv as a run: its cell, whether it finished, its completion time (the
    cap when unfinished), messages per type, robots out of energy, distance per robot."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        columns = reader.fieldnames or []
        rows = list(reader)
    missing = [c for c in ("status", ROBOTS, EVENTS, MODEL) if c not in columns]
    if missing:
        sys.exit(f"{path}: no column {', '.join(missing)}: not results.csv of "
                 f"configs/sweeps/task-allocation.yaml")
    if not any(c in columns for c in (COMPLETION_COUNT, ENDED_BY)):
        sys.exit(f"{path}: neither {COMPLETION_COUNT} nor {ENDED_BY}: the runs' summary.json has "
                 "no task_events fields (world, ended); were task_events and task_allocation "
                 "built?")
    types = [c[len(SENT_PREFIX):-len(SENT_SUFFIX)] for c in columns
             if c.startswith(SENT_PREFIX) and c.endswith(SENT_SUFFIX)]
    types = ordered(types, MESSAGE_TYPES)
    if not types:
        say(f"warning: no {SENT_PREFIX}<type>{SENT_SUFFIX} columns: messages are not counted")
    runs, failed = [], []
    for line, row in enumerate(rows, start=2):
        cell = (int(row[ROBOTS]), int(row[EVENTS]), row[MODEL])
        if row["status"] != "ok":
            failed.append({"run_id": row.get("run_id", ""), "status": row["status"], "cell": cell})
            continue
        count = number(row.get(COMPLETION_COUNT)) or 0
        ended_by = row.get(ENDED_BY) or None
        finished = count >= 1
        if ended_by is not None and (ended_by == "task_done") != finished:
            say(f"warning: {path}:{line} ({row.get('run_id')}): ended.by is {ended_by} but "
                f"{COMPLETION_COUNT} is {count:g}; going by the completion time")
        if ended_by is None and not row.get(COMPLETION_COUNT):
            sys.exit(f"{path}:{line} ({row.get('run_id')}): an ok run without {ENDED_BY} or "
                     f"{COMPLETION_COUNT}: its summary.json has no task_events fields")
        cap = number(row.get(CAP))  # the scenario's duration_s
        if finished:
            if count > 1:
                say(f"warning: {path}:{line}: {count:g} completion times; using their mean")
            time = float(row[COMPLETION])
        else:
            time = number(row.get(ENDED_AT))
            time = time if time is not None else cap
            if time is None:
                sys.exit(f"{path}:{line}: an unfinished run without {ENDED_AT} or {CAP}")
        runs.append({
            "run_id": row.get("run_id", ""), "seed": row.get("seed", ""), "cell": cell,
            "finished": finished, "time": time, "cap": cap,
            "sent": {t: number(row.get(SENT_PREFIX + t + SENT_SUFFIX)) or 0.0 for t in types},
            "out_of_energy": number(row.get(OUT_OF_ENERGY)) or 0.0,
            "distance": number(row.get(DISTANCE)),
        })
    return runs, failed, types


def write_runs_csv(runs, types, path):
    """One row per run, simple column names, for `swarmnet stats`."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run_id", "seed", "robots", "events", "model", "finished", "completion_time_s",
                    "finished_completion_time_s", "out_of_energy", "distance_m",
                    *[f"sent_{t}" for t in types], "sent_total"])
        for r in runs:
            robots, events, model = r["cell"]
            w.writerow([r["run_id"], r["seed"], robots, events, model, int(r["finished"]),
                        repr(r["time"]), repr(r["time"]) if r["finished"] else "",
                        repr(r["out_of_energy"]),
                        "" if r["distance"] is None else repr(r["distance"]),
                        *[repr(r["sent"][t]) for t in types], repr(sum(r["sent"].values()))])


def swarmnet_stats(binary, runs_csv, metrics):
    """`swarmnet stats --json` by (robots, events, model), models compared within each cell;
    groups keyed by (robots, events, model) with the counts as integers."""
    def cell(key):
        return (int(key[0]), int(key[1]), key[2])
    out = {}
    for metric, result in grouped_stats(binary, runs_csv, ["robots", "events", "model"], "model",
                                        metrics).items():
        out[metric] = {"groups": {cell(k): g for k, g in result["groups"].items()},
                       "welch": [dict(t, a=cell(t["a"]), b=cell(t["b"]))
                                 for t in result["welch"]]}
    return out


def fmt(value, digits=1):
    return "-" if value is None else f"{value:.{digits}f}"


def fmt_p(p):
    return "-" if p is None else (f"{p:.2g}" if p < 0.001 else f"{p:.4f}")


def build_table(cells, runs, failed, stats, types):
    counts = defaultdict(lambda: {"finished": 0, "unfinished": 0, "failed": 0})
    for r in runs:
        counts[r["cell"]]["finished" if r["finished"] else "unfinished"] += 1
    for r in failed:
        counts[r["cell"]]["failed"] += 1
    rows = []
    for cell in cells:
        c = counts[cell]
        row = {"robots": cell[0], "events": cell[1], "model": cell[2],
               "finished": c["finished"], "runs": c["finished"] + c["unfinished"],
               "failed": c["failed"]}
        g = stats["completion_time_s"]["groups"].get(cell)
        row["completion_mean_s"] = g and g["mean"]
        row["completion_ci_low_s"] = g and g["ci_low"]
        row["completion_ci_high_s"] = g and g["ci_high"]
        g = stats["finished_completion_time_s"]["groups"].get(cell)
        row["finished_mean_s"] = g["mean"] if g and g["n"] > 0 else None
        for metric, name in ([(f"sent_{t}", f"sent_{t}") for t in types] +
                             [("sent_total", "sent_total"), ("out_of_energy", "out_of_energy"),
                              ("distance_m", "distance_m")]):
            g = stats[metric]["groups"].get(cell)
            row[f"{name}_mean"] = g["mean"] if g and g["n"] > 0 else None
            if metric in ("sent_total", "out_of_energy"):
                row[f"{name}_ci_low"] = g and g["ci_low"]
                row[f"{name}_ci_high"] = g and g["ci_high"]
        rows.append(row)
    return rows


def write_table(rows, types, folder, cap_text):
    fields = list(rows[0].keys()) if rows else []
    with open(folder / "table.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if v is None else v) for k, v in row.items()})
    lines = [
        "# Task allocation: completion time by communication model",
        "",
        f"Mean over the runs of each cell with its {CONFIDENCE:.0%} confidence interval (Student). "
        f"Unfinished runs (not every event serviced by the cap, {cap_text}) count at the cap, a "
        "lower bound: a mean over a cell with any is a lower bound (marked *). \"finished only\" "
        "is the mean over the finished runs. Messages: sent per run, all robots together; out of "
        "energy: robots that ran flat per run.",
        "",
        "| robots | events | model | finished / runs | completion s, mean [95% CI] | finished only "
        "| " + " | ".join(f"{t} msgs" for t in types) + " | all msgs [95% CI] "
        "| out of energy [95% CI] | distance per robot m |",
        "|---|---|---|---|---|---|" + "---|" * len(types) + "---|---|---|",
    ]
    for r in rows:
        star = "*" if r["finished"] < r["runs"] else ""
        failed = f" ({r['failed']} failed)" if r["failed"] else ""
        lines.append(
            f"| {r['robots']} | {r['events']} | {r['model']} | "
            f"{r['finished']} / {r['runs']}{failed} | {fmt(r['completion_mean_s'])}{star} "
            f"[{fmt(r['completion_ci_low_s'])}, {fmt(r['completion_ci_high_s'])}] | "
            f"{fmt(r['finished_mean_s'])} | "
            + " | ".join(fmt(r[f"sent_{t}_mean"]) for t in types)
            + f" | {fmt(r['sent_total_mean'])} [{fmt(r['sent_total_ci_low'])}, "
            f"{fmt(r['sent_total_ci_high'])}] | {fmt(r['out_of_energy_mean'], 2)} "
            f"[{fmt(r['out_of_energy_ci_low'], 2)}, {fmt(r['out_of_energy_ci_high'], 2)}] "
            f"| {fmt(r['distance_m_mean'])} |")
    (folder / "table.md").write_text("\n".join(lines) + "\n")


def write_welch(tests, groups, folder):
    """Every pair of models in each cell; p as `swarmnet stats` gives it, and Holm-adjusted over
    all the comparisons."""
    fields = ["robots", "events", "model_a", "model_b", "mean_a_s", "mean_b_s", "t", "df", "p",
              "p_holm"]
    rows = []
    for t in tests:
        a, b = t["a"], t["b"]
        rows.append({"robots": a[0], "events": a[1], "model_a": a[2], "model_b": b[2],
                     "mean_a_s": groups[a]["mean"], "mean_b_s": groups[b]["mean"],
                     "t": t["t"], "df": t["df"], "p": t["p"], "p_holm": t.get("p_holm")})
    with open(folder / "welch.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if v is None else v) for k, v in row.items()})
    lines = [
        "# Welch's t-tests of the completion time between models",
        "",
        f"Two-sided, every pair of models within each (robots, events) cell: {len(rows)} tests. "
        f"p is per test, as the study reads it (p < {ALPHA}); p (Holm) is corrected for all "
        f"{len(rows)}. Unfinished runs count at the cap. '-': undefined (no spread in either "
        "group, or fewer than two runs).",
        "",
        "| robots | events | A | B | mean A s | mean B s | t | df | p | p (Holm) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(f"| {r['robots']} | {r['events']} | {r['model_a']} | {r['model_b']} | "
                     f"{fmt(r['mean_a_s'])} | {fmt(r['mean_b_s'])} | {fmt(r['t'], 3)} | "
                     f"{fmt(r['df'], 2)} | {fmt_p(r['p'])} | {fmt_p(r['p_holm'])} |")
    (folder / "welch.md").write_text("\n".join(lines) + "\n")
    return rows


def evaluate_claims(welch_rows, groups, counts, events_values):
    """The study's claims about Fig. 5 (section VI-B), each per events value, on the completion
    times with unfinished runs at the cap."""
    test = {}
    for r in welch_rows:
        test[(r["robots"], r["events"], r["model_a"], r["model_b"])] = r
        test[(r["robots"], r["events"], r["model_b"], r["model_a"])] = r

    def compare(robots, events, model, other):
        """model against other in one cell: means, ratio, Welch's p (None when not available)."""
        a, b = groups.get((robots, events, model)), groups.get((robots, events, other))
        if a is None or b is None:
            return None
        t = test.get((robots, events, model, other))
        ratio = a["mean"] / b["mean"] if a["mean"] is not None and b["mean"] else None
        return {"mean_s": a["mean"], "other_mean_s": b["mean"], "ratio": ratio,
                "p": t["p"] if t else None,
                "unfinished": counts[(robots, events, model)] + counts[(robots, events, other)]}

    def verdict(flags):
        if any(f is None for f in flags):
            return None
        return all(flags)

    # (a) 20 robots: 80211a takes more than 50% longer than all.
    per_events = {}
    for e in events_values:
        c = compare(20, e, "80211a", "all")
        if c is None:
            continue
        c["more_than_50pct_longer"] = None if c["ratio"] is None else c["ratio"] > 1.5
        c["significant"] = None if c["p"] is None else c["p"] < ALPHA
        c["holds"] = verdict([c["more_than_50pct_longer"], c["significant"]])
        per_events[str(e)] = c
    holding = [e for e, c in per_events.items() if c["holds"]]
    claim_a = {
        "statement": "For 20 robots, the average task completion time of the realistic model "
                     "(802.11a) can be more than 50% longer than with the ideal model (all).",
        "criterion": f"for some events value: mean(80211a) / mean(all) > 1.5 and Welch p < {ALPHA}",
        "per_events": per_events,
        "holds_for_events": [int(e) for e in holding],
        "holds": (len(holding) > 0) if per_events else None,
    }

    # (b) 40 robots: no significant difference between any two models.
    cells = {}
    for e in events_values:
        rows = [r for r in welch_rows if r["robots"] == 40 and r["events"] == e]
        if not rows:
            continue
        pairs = {f"{r['model_a']} vs {r['model_b']}": r["p"] for r in rows}
        significant = [k for k, p in pairs.items() if p is not None and p < ALPHA]
        cells[str(e)] = {"p": pairs, "significant_pairs": significant,
                         "undefined_pairs": [k for k, p in pairs.items() if p is None],
                         "holds": not significant}
    claim_b = {
        "statement": "For 40 robots there is no statistically significant difference between "
                     "the models.",
        "criterion": f"every pair of models in every events value: Welch p >= {ALPHA}",
        "per_events": cells,
        "holds": all(c["holds"] for c in cells.values()) if cells else None,
    }

    # (c) 30 robots: 80211a close to p75 and p100, better than p50, worse than all.
    per_events = {}
    for e in events_values:
        parts = {m: compare(30, e, "80211a", m) for m in ("p75", "p100", "p50", "all")}
        if any(v is None for v in parts.values()):
            continue
        for m in ("p75", "p100"):
            parts[m]["close"] = None if parts[m]["p"] is None else parts[m]["p"] >= ALPHA
        p50, best = parts["p50"], parts["all"]
        p50["significantly_better"] = (None if p50["p"] is None else
                                       p50["p"] < ALPHA and p50["mean_s"] < p50["other_mean_s"])
        best["significantly_worse"] = (None if best["p"] is None else
                                       best["p"] < ALPHA and best["mean_s"] > best["other_mean_s"])
        holds = verdict([parts["p75"]["close"], parts["p100"]["close"],
                         p50["significantly_better"], best["significantly_worse"]])
        per_events[str(e)] = {"vs": parts, "holds": holds}
    holding = [e for e, c in per_events.items() if c["holds"]]
    claim_c = {
        "statement": "For 30 robots the realistic model (802.11a) gives results similar to p75 "
                     "and p100, significantly better than p50 and significantly worse than all "
                     "(p-values less than 0.1).",
        "criterion": f"per events value: Welch p >= {ALPHA} against p75 and p100; against p50 "
                     f"p < {ALPHA} with a lower mean; against all p < {ALPHA} with a higher mean",
        "per_events": per_events,
        "holds_for_events": [int(e) for e in holding],
        "holds": (len(holding) == len(per_events)) if per_events else None,
    }
    return {"alpha": ALPHA, "completion_time": "mean over runs; an unfinished run counts at the "
            "cap (a lower bound)", "a_20_robots": claim_a, "b_40_robots": claim_b,
            "c_30_robots": claim_c}


def figure(groups, counts, robots_values, events_values, models, cap_text, n_unfinished, n_runs,
           out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    markers = ["o", "s", "^", "D", "v", "P", "X"]
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]
    fig, axes = plt.subplots(len(robots_values), 1, figsize=(7, 3.2 * len(robots_values) + 0.8),
                             sharex=True, squeeze=False)
    width = 0.06 * (min(b - a for a, b in zip(events_values, events_values[1:]))
                    if len(events_values) > 1 else 1)
    for axis, robots in zip(axes[:, 0], robots_values):
        for i, model in enumerate(models):
            offset = (i - (len(models) - 1) / 2) * width
            xs, ys, lo, hi, hollow = [], [], [], [], []
            for e in events_values:
                g = groups.get((robots, e, model))
                if g is None or g["mean"] is None:
                    continue
                xs.append(e + offset)
                ys.append(g["mean"])
                low = g["ci_low"] if g["ci_low"] is not None else g["mean"]
                high = g["ci_high"] if g["ci_high"] is not None else g["mean"]
                lo.append(g["mean"] - low)
                hi.append(high - g["mean"])
                hollow.append(counts[(robots, e, model)] > 0)
            if not xs:
                continue
            color, marker = colors[i % len(colors)], markers[i % len(markers)]
            axis.errorbar(xs, ys, yerr=[lo, hi], color=color, marker=marker, capsize=3,
                          label=model, linewidth=1.2, markersize=5)
            flagged = [(x, y) for x, y, h in zip(xs, ys, hollow) if h]
            if flagged:
                axis.plot([x for x, _ in flagged], [y for _, y in flagged], linestyle="none",
                          marker=marker, markersize=9, mfc="white", mec=color, mew=1.5)
                for (x, y), e in zip(flagged, [e for e, h in zip(events_values, hollow) if h]):
                    k = counts[(robots, e, model)]
                    axis.annotate(f"{k}", (x, y), textcoords="offset points", xytext=(4, 4),
                                  fontsize=7, color=color)
        axis.set_title(f"{robots} robots", fontsize=10)
        axis.set_ylabel("task completion time (s)")
        axis.grid(True, alpha=0.3)
        axis.set_xticks(events_values)
    axes[-1, 0].set_xlabel("events")
    axes[0, 0].legend(title="communication model", fontsize=8, title_fontsize=8, ncol=3)
    caption = textwrap.fill(
        f"Mean over the seeds, {CONFIDENCE:.0%} confidence intervals. Unfinished runs (events "
        f"left at the cap, {cap_text}): {n_unfinished} of {n_runs}. Each counts at the cap, a "
        "lower bound of its completion time, so a hollow marker (number: its unfinished runs) "
        "is a lower bound of the mean.", 110)
    fig.text(0.01, 0.005, caption, fontsize=7, va="bottom")
    fig.suptitle("Average task completion time (study section VI, Fig. 5)", fontsize=11)
    fig.tight_layout(rect=(0, 0.05, 1, 0.98))
    fig.savefig(out, dpi=120)
    plt.close(fig)


def analyse(results, folder, binary):
    say(f"reading {results}")
    runs, failed, types = read_runs(results)
    if not runs:
        sys.exit(f"{results}: no finished runs")
    folder.mkdir(parents=True, exist_ok=True)
    n_unfinished = sum(not r["finished"] for r in runs)
    caps = sorted({r["cap"] for r in runs if r["cap"] is not None})
    cap_text = (f"{caps[0]:g} s" if len(caps) == 1 else
                "; ".join(f"{c:g} s" for c in caps) if caps else "duration_s")
    say(f"{len(runs)} runs with a summary ({len(runs) - n_unfinished} finished, {n_unfinished} "
        f"unfinished at the cap), {len(failed)} failed or not run")
    for r in failed:
        say(f"  {r['status']}: {r['run_id']}")

    runs_csv = folder / "runs.csv"
    write_runs_csv(runs, types, runs_csv)
    metrics = (["completion_time_s", "finished_completion_time_s", "out_of_energy", "distance_m"]
               + [f"sent_{t}" for t in types] + ["sent_total"])
    say(f"statistics: {binary} stats {runs_csv} (every pair of models in each cell)")
    stats = swarmnet_stats(binary, runs_csv, metrics)

    cells_seen = {r["cell"] for r in runs} | {r["cell"] for r in failed}
    robots_values = sorted({c[0] for c in cells_seen})
    events_values = sorted({c[1] for c in cells_seen})
    models = ordered({c[2] for c in cells_seen}, MODELS)
    cells = [(n, e, m) for n in robots_values for e in events_values for m in models
             if (n, e, m) in cells_seen]
    unfinished = defaultdict(int)
    for r in runs:
        unfinished[r["cell"]] += 0 if r["finished"] else 1

    rows = build_table(cells, runs, failed, stats, types)
    write_table(rows, types, folder, cap_text)
    groups = stats["completion_time_s"]["groups"]
    welch_rows = write_welch(stats["completion_time_s"]["welch"], groups, folder)
    claims = evaluate_claims(welch_rows, groups, unfinished, events_values)
    claims["runs"] = {"with_summary": len(runs), "finished": len(runs) - n_unfinished,
                      "unfinished_at_cap": n_unfinished, "failed_or_not_run": len(failed),
                      "cap": cap_text}
    (folder / "claims.json").write_text(json.dumps(claims, indent=2) + "\n")
    say("drawing the figure")
    figure(groups, unfinished, robots_values, events_values, models, cap_text, n_unfinished,
           len(runs), folder / "completion.png")
    for name in ("completion.png", "table.md", "table.csv", "welch.md", "welch.csv",
                 "claims.json", "runs.csv"):
        say(f"wrote {folder / name}")
    for key in ("a_20_robots", "b_40_robots", "c_30_robots"):
        say(f"claim {key}: holds = {claims[key]['holds']}")


def main():
    require_matplotlib()  # before the sweep: the figure at the end needs it
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="build directory holding bin/swarmnet")
    parser.add_argument("--swarmnet", help="the swarmnet command (default: BUILD/bin/swarmnet)")
    parser.add_argument("--sweep", default="configs/sweeps/task-allocation.yaml")
    parser.add_argument("--out", default="runs/sweeps/task-allocation", help="sweep directory")
    parser.add_argument("-j", "--jobs", default="2", help="runs at once (swarmnet sweep -j)")
    parser.add_argument("--results", help="an existing results.csv: analyse it, run nothing")
    parser.add_argument("--report", help="output folder (default: the folder of results.csv)")
    args = parser.parse_args()
    binary = pathlib.Path(args.swarmnet) if args.swarmnet else (
        pathlib.Path(args.build).resolve() / "bin" / "swarmnet")
    if not binary.exists():
        sys.exit(f"{binary}: no swarmnet here (build it, or give --build or --swarmnet)")
    if args.results:
        results = pathlib.Path(args.results)
    else:
        say(f"running the sweep {args.sweep} into {args.out}, {args.jobs} at a time "
            "(resumable: finished runs are skipped)")
        code = subprocess.run([str(binary), "sweep", args.sweep, "-j", args.jobs,
                               "--out", args.out]).returncode
        if code == 1:
            say("some runs failed (listed above); analysing the others, failures counted")
        elif code != 0:
            sys.exit(f"swarmnet sweep exited {code}")
        results = pathlib.Path(args.out) / "results.csv"
    analyse(results, pathlib.Path(args.report) if args.report else results.parent, binary)


if __name__ == "__main__":
    main()
