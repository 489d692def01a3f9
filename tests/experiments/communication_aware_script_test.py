#!/usr/bin/env python3
"""scripts/communication_aware_study.py on results.csv files of its two sweeps (fixtures: seeds 1-3
of configs/sweeps/relay-chain.yaml, 54 runs, and of configs/sweeps/task-allocation-aware.yaml, 60
runs of which the last is marked failed). Checks the tables' cells against means computed here
from the fixtures, a Welch t against the formula, Holm's adjustment against the raw p-values, the
802.11a-minus-all gap against the means, the figures, and that a results.csv of the wrong sweep
is refused by name. Statistics go through `swarmnet stats` ($SWARMNET_BIN).
Usage: communication_aware_script_test.py SCRIPT RELAY_FIXTURE TASK_FIXTURE. Exit 77 (skipped)
without matplotlib."""
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

script, relay_fixture, task_fixture = sys.argv[1], sys.argv[2], sys.argv[3]
try:
    import matplotlib  # noqa: F401
except ImportError:
    print("SKIPPED: matplotlib is not installed (Debian: apt-get install python3-matplotlib)")
    sys.exit(77)
binary = os.environ.get("SWARMNET_BIN", "")
assert os.access(binary, os.X_OK), f"SWARMNET_BIN={binary!r} is not the built swarmnet"


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(b))


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


relay = [r for r in rows(relay_fixture) if r["status"] == "ok"]
task = [r for r in rows(task_fixture) if r["status"] == "ok"]

with tempfile.TemporaryDirectory() as tmp:
    report = os.path.join(tmp, "report")
    done = subprocess.run([sys.executable, script, "--relay-results", relay_fixture,
                           "--task-results", task_fixture, "--report", report,
                           "--swarmnet", binary], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    study = json.load(open(os.path.join(report, "study.json")))
    for name in ("relay_chain.png", "task_allocation.png"):
        with open(os.path.join(report, name), "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n", f"{name} is not a PNG"

    # Relay chain: 3 relay counts x 2 shadowings x 3 modes; a cell's mean pdr as computed here.
    chain = study["relay_chain"]
    assert chain["runs"] == 54 and chain["failed"] == [], chain["runs"]
    assert len(chain["cells"]) == 18, sorted(chain["cells"])
    cell = [float(r["pdr"]) for r in relay if r["robots.count"] == "12"
            and r["network.propagation.1.params.sigma_db"] == "6"
            and r["robots.controllers.0.params.mode"] == "geometric"]
    assert len(cell) == 3
    got = chain["cells"]["10,6,geometric"]["pdr"]
    assert got["n"] == 3 and close(got["mean"], statistics.mean(cell)), (got, cell)
    reach = [float(r["controllers.connected_distance_m.max"]) for r in relay
             if r["robots.count"] == "7" and r["network.propagation.1.params.sigma_db"] == "6"
             and r["robots.controllers.0.params.mode"] == "link_aware"]
    assert close(chain["cells"]["5,6,link_aware"]["connected_reach_m"]["mean"],
                 statistics.mean(reach))
    # Welch's t between geometric and link_aware pdr in that cell, from the formula.
    aware = [float(r["pdr"]) for r in relay if r["robots.count"] == "12"
             and r["network.propagation.1.params.sigma_db"] == "6"
             and r["robots.controllers.0.params.mode"] == "link_aware"]
    t = (statistics.mean(cell) - statistics.mean(aware)) / math.sqrt(
        statistics.variance(cell) / 3 + statistics.variance(aware) / 3)
    tests = [w for w in chain["welch"]["pdr"]
             if w["a"] == ["10", "6", "geometric"] and w["b"] == ["10", "6", "link_aware"]]
    assert len(tests) == 1, chain["welch"]["pdr"][:3]
    assert close(tests[0]["t"], t, 1e-6), (tests[0], t)
    # Three pairs of modes in each of the six cells; Holm never lowers a p-value.
    assert len(chain["welch"]["pdr"]) == 18
    for w in chain["welch"]["pdr"]:
        assert w["p_holm"] is None or w["p_holm"] >= w["p"] - 1e-15, w
    table = rows(os.path.join(report, "relay_chain.csv"))
    assert len(table) == 18 and table[0]["mode"] == "none", table[0]

    # Task allocation: 2 robot counts x 5 models x 2 controllers, the failed run counted.
    alloc = study["task_allocation"]
    assert alloc["runs"] == 59 and len(alloc["failed"]) == 1, (alloc["runs"], alloc["failed"])
    welch = rows(os.path.join(report, "task_allocation_welch.csv"))
    assert len(welch) == 10, len(welch)

    def completion(robots, model, aware_flag):
        out = []
        for r in task:
            if (r["robots.count"], r["name"],
                    r["robots.controllers.0.params.reannounce_on_encounter"]) != (
                    robots, model, aware_flag):
                continue
            done_count = float(r["world.completion_time_s.count"] or 0)
            out.append(float(r["world.completion_time_s.mean"]) if done_count >= 1
                       else float(r["ended.at_s"]))
        return statistics.mean(out)

    for robots in ("20", "30"):
        gap = alloc["gap_80211a_minus_all_s"][f"{robots},10"]
        for controller, flag in (("paper", "false"), ("aware", "true")):
            expected = completion(robots, "80211a", flag) - completion(robots, "all", flag)
            assert close(gap[controller], expected, 1e-9), (robots, controller, gap, expected)
        assert close(gap["closed_fraction"], 1 - gap["aware"] / gap["paper"])

    # The wrong sweep's results.csv is refused, naming the column it lacks.
    wrong = subprocess.run([sys.executable, script, "--relay-results", task_fixture,
                            "--task-results", task_fixture, "--report", report,
                            "--swarmnet", binary], capture_output=True, text=True)
    assert wrong.returncode != 0 and "not results.csv of configs/sweeps/relay-chain.yaml" in \
        wrong.stderr, wrong.stderr
print("communication_aware_study.py: tables, Welch, Holm, gaps and figures as computed here")
