#!/usr/bin/env python3
"""scripts/reproduce_task_allocation.py --results on a hand-made results.csv
(fixtures/task_allocation_results.csv: 20, 30 and 40 robots, 5 models, 3 seeds per cell, one
run unfinished at the 400 s cap, one failed run). Checks the table (counts, a mean with a
cap-bounded run and its interval, messages, robots out of energy), a Welch p-value against one
computed independently (numerical integration of Student's density with mpmath, 30 digits), the
claims JSON and the PNG. Statistics go through `swarmnet stats` ($SWARMNET_BIN).
Usage: task_allocation_script_test.py SCRIPT FIXTURE. Exit 77 (skipped) without matplotlib."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

script, fixture = sys.argv[1], sys.argv[2]
try:
    import matplotlib  # noqa: F401
except ImportError:
    print("SKIPPED: matplotlib is not installed (Debian: apt-get install python3-matplotlib)")
    sys.exit(77)
binary = os.environ.get("SWARMNET_BIN", "")
assert os.access(binary, os.X_OK), f"SWARMNET_BIN={binary!r} is not the built swarmnet"


def close(a, b, tol=1e-6):
    return a is not None and abs(a - b) <= tol * max(1.0, abs(b))


with tempfile.TemporaryDirectory() as tmp:
    results = os.path.join(tmp, "results.csv")
    shutil.copy(fixture, results)
    report = os.path.join(tmp, "report")
    done = subprocess.run([sys.executable, script, "--results", results, "--report", report,
                           "--swarmnet", binary], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "1 failed or not run" in done.stderr, done.stderr
    assert "1 unfinished at the cap" in done.stderr, done.stderr

    # The table: one row per (robots, events, model) cell.
    with open(os.path.join(report, "table.csv"), newline="") as f:
        table = {(int(r["robots"]), int(r["events"]), r["model"]): r for r in csv.DictReader(f)}
    assert len(table) == 4 * 5, sorted(table)
    p50 = table[(20, 5, "p50")]
    # 200, 220 and one run unfinished at the 400 s cap, counted at 400: mean 273.33,
    # t(0.975, 2) = 4.30265 (closed form for df 2), sd 110.15.
    assert (p50["finished"], p50["runs"], p50["failed"]) == ("2", "3", "0"), p50
    assert close(float(p50["completion_mean_s"]), 273.3333333333333), p50
    assert close(float(p50["completion_ci_low_s"]), -0.2979405994429311), p50
    assert close(float(p50["completion_ci_high_s"]), 546.9646072661096), p50
    assert close(float(p50["finished_mean_s"]), 210.0), p50
    assert close(float(p50["out_of_energy_mean"]), 1.0), p50      # 3, 0, 0 robots ran flat
    assert close(float(p50["sent_S_mean"]), 40.0), p50             # 30, 40, 50
    assert close(float(p50["sent_A_mean"]), 2 / 3), p50            # none, 1, 1
    assert close(float(p50["sent_total_mean"]), (38 + 50 + 61) / 3), p50
    assert close(float(p50["distance_m_mean"]), 320.0), p50
    wifi = table[(20, 5, "80211a")]
    assert (wifi["finished"], wifi["runs"], wifi["failed"]) == ("3", "3", "1"), wifi
    assert close(float(wifi["completion_mean_s"]), 180.0), wifi
    with open(os.path.join(report, "table.md")) as f:
        md = f.read()
    assert "| 20 | 5 | p50 | 2 / 3 | 273.3* [-0.3, 547.0] | 210.0 |" in md, md
    assert "| 20 | 5 | 80211a | 3 / 3 (1 failed) | 180.0 [" in md, md

    # Welch's tests: 10 pairs of models in each of the 4 cells.
    with open(os.path.join(report, "welch.csv"), newline="") as f:
        welch = {(int(r["robots"]), int(r["events"]), frozenset((r["model_a"], r["model_b"]))): r
                 for r in csv.DictReader(f)}
    assert len(welch) == 4 * 10, len(welch)
    w = welch[(30, 5, frozenset(("80211a", "p100")))]
    # 195, 200, 205 against 185, 195, 205: t = +-0.774597, df = 2.941176, and p computed
    # independently by integrating Student's density (mpmath, 30 digits): 0.49605537445852055.
    assert close(abs(float(w["t"])), 0.7745966692414834), w
    assert close(float(w["df"]), 2.9411764705882355), w
    assert close(float(w["p"]), 0.49605537445852055, 1e-5), w
    w = welch[(30, 5, frozenset(("80211a", "p50")))]
    assert close(float(w["p"]), 0.00645118312999366, 1e-5), w

    # The claims.
    with open(os.path.join(report, "claims.json")) as f:
        claims = json.load(f)
    assert claims["alpha"] == 0.1, claims
    a = claims["a_20_robots"]
    assert a["holds"] is True and a["holds_for_events"] == [5], a
    assert close(a["per_events"]["5"]["ratio"], 180 / 110), a
    assert close(a["per_events"]["5"]["p"], 0.0010166626172891213, 1e-5), a
    assert a["per_events"]["10"]["more_than_50pct_longer"] is False, a   # 260 / 210 = 1.24
    b = claims["b_40_robots"]
    assert b["holds"] is True and len(b["per_events"]["5"]["p"]) == 10, b
    assert b["per_events"]["5"]["significant_pairs"] == [], b
    c = claims["c_30_robots"]["per_events"]["5"]
    assert claims["c_30_robots"]["holds"] is True, claims["c_30_robots"]
    assert c["vs"]["p75"]["close"] and c["vs"]["p100"]["close"], c
    assert c["vs"]["p50"]["significantly_better"] and c["vs"]["all"]["significantly_worse"], c
    assert claims["runs"] == {"with_summary": 60, "finished": 59, "unfinished_at_cap": 1,
                              "failed_or_not_run": 1, "cap": "400 s"}, claims["runs"]

    with open(os.path.join(report, "completion.png"), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"

    # Results whose runs have no task_events fields are refused with the reason.
    bare = os.path.join(tmp, "bare.csv")
    with open(bare, "w") as f:
        f.write("run_id,seed,status,robots.count,world.0.params.events,name,duration_s\n"
                "a,1,ok,20,5,all,400\n")
    done = subprocess.run([sys.executable, script, "--results", bare, "--swarmnet", binary],
                          capture_output=True, text=True)
    assert done.returncode != 0 and "no task_events fields" in done.stderr, done.stderr
print("reproduce_task_allocation.py: ok")
