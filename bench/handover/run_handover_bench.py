#!/usr/bin/env python3
"""The strict hand-over's cost in whole runs (issue 61), two builds side by side.

For each scenario, runs it alone and two at once with each build, the builds taking turns, and
reports medians of the transport's share of the run's CPU and of wall time over the halves' CPU.
Then a sweep of --sweep-runs runs (seeds 1..N) at -j 2, 4 and 8 with each build, reporting each
width's wall time over -j 2's. Writes everything, every run included, to --out as JSON.

  python3 bench/handover/run_handover_bench.py --before OLD/bin/swarmnet --after build/bin/swarmnet
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import tempfile
import time

SCENARIOS = {
    "task-allocation": ["configs/paper/task-allocation.yaml", "--seed", "1"],
    "quickstart": ["configs/quickstart.yaml"],
    "aodv": ["configs/aodv.yaml"],
}


def run(binary, args, out):
    subprocess.run([binary, "run", *args, "--out", out, "--overwrite", "--quiet"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    c = s["cpu_s"]
    halves = c["robot"] + c["network"]
    return {"wall_s": s["wall_s"], "robot": c["robot"], "network": c["network"],
            "transport": c["transport"], "transport_share": c["transport"] / (halves + c["transport"]),
            "wall_over_halves": s["wall_s"] / halves}


def at_once(binary, args, width, work):
    with concurrent.futures.ThreadPoolExecutor(width) as pool:
        jobs = [pool.submit(run, binary, args, os.path.join(work, f"r{i}")) for i in range(width)]
        return [j.result() for j in jobs]


def sweep(binary, args, runs, width, work):
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(width) as pool:
        jobs = [pool.submit(run, binary, [*args, "--seed", str(seed)], os.path.join(work, f"s{seed}"))
                for seed in range(1, runs + 1)]
        results = [j.result() for j in jobs]
    return {"wall_s": time.monotonic() - start,
            "cpu_s": sum(r["robot"] + r["network"] + r["transport"] for r in results)}


def median(rows, key):
    return statistics.median(r[key] for r in rows)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--before", required=True)
    p.add_argument("--after", required=True)
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--scenarios", default=",".join(SCENARIOS))
    p.add_argument("--sweep-runs", type=int, default=16)
    p.add_argument("--out", default="handover.json")
    a = p.parse_args()
    builds = {"before": a.before, "after": a.after}
    report = {"repeats": a.repeats, "scenarios": {}, "sweep": {}}
    with tempfile.TemporaryDirectory() as work:
        for name in a.scenarios.split(","):
            rows = {b: {"alone": [], "two_at_once": []} for b in builds}
            for _ in range(a.repeats):
                for b, binary in builds.items():  # interleaved
                    rows[b]["alone"].append(run(binary, SCENARIOS[name], os.path.join(work, "a")))
                    rows[b]["two_at_once"].extend(at_once(binary, SCENARIOS[name], 2, work))
            summary = {}
            for b in builds:
                summary[b] = {
                    "alone_transport_share": median(rows[b]["alone"], "transport_share"),
                    "alone_wall_s": median(rows[b]["alone"], "wall_s"),
                    "alone_transport_cpu_s": median(rows[b]["alone"], "transport"),
                    "two_at_once_wall_over_halves": median(rows[b]["two_at_once"], "wall_over_halves"),
                    "two_at_once_wall_s": median(rows[b]["two_at_once"], "wall_s"),
                }
            report["scenarios"][name] = {"median": summary, "runs": rows}
            print(name, json.dumps(summary, indent=1))
        if a.sweep_runs > 0:
            rows = {b: {str(w): [] for w in (2, 4, 8)} for b in builds}
            for _ in range(max(1, a.repeats // 2)):
                for b, binary in builds.items():
                    for w in (2, 4, 8):
                        rows[b][str(w)].append(sweep(binary, SCENARIOS["task-allocation"][:1],
                                                     a.sweep_runs, w, work))
            summary = {b: {f"j{w}_wall_s": median(rows[b][str(w)], "wall_s") for w in (2, 4, 8)}
                       for b in builds}
            for b in builds:
                summary[b]["j4_over_j2"] = summary[b]["j4_wall_s"] / summary[b]["j2_wall_s"]
                summary[b]["j8_over_j2"] = summary[b]["j8_wall_s"] / summary[b]["j2_wall_s"]
                summary[b]["cpu_s_per_run_j2"] = median(rows[b]["2"], "cpu_s") / a.sweep_runs
            report["sweep"] = {"runs": a.sweep_runs, "median": summary, "all": rows}
            print("sweep", json.dumps(summary, indent=1))
    with open(a.out, "w") as f:
        json.dump(report, f, indent=1)


if __name__ == "__main__":
    main()
