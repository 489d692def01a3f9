"""`swarmnet stats --json` from a study script: the one place that runs it and reads its answer.

grouped_stats() runs `swarmnet stats RUNS_CSV --by ... --within ... --holm --json` and returns,
per metric, its groups keyed by the tuple of their --by values (text, as in the CSV), the Welch
tests with those keys in place of the labels, and the kind of interval (docs/experiments.md).
"""
import json
import subprocess
import sys


def grouped_stats(binary, runs_csv, by, within, metrics, baseline=None):
    command = [str(binary), "stats", str(runs_csv), "--by", ",".join(by), "--within", within,
               "--holm", "--json"]
    if baseline:
        command += ["--baseline", baseline]
    for m in metrics:
        command += ["--metric", m]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
    result = json.loads(done.stdout)
    out = {}
    for metric in metrics:
        groups, by_label = {}, {}
        for g in result["metrics"][metric]["groups"]:
            key = tuple(g["group"][c] for c in by)
            groups[key] = g
            by_label[g["label"]] = key
        tests = [dict(t, a=by_label[t["a"]], b=by_label[t["b"]])
                 for t in result["metrics"][metric]["welch"]]
        out[metric] = {"groups": groups, "welch": tests,
                       "interval": result["metrics"][metric]["interval"]}
    return out
