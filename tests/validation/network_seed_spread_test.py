#!/usr/bin/env python3
"""network_seed_spread.py on grids written here: each model's mean, sample sd and range per row
and metric, a single run shown alone, and a grid lacking a row refused with its file named; with
--ns3, the difference of both sides' means and its standard error, a row no ns-3 re-draw ran left
out, and grids of other traces refused."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "network_seed_spread.py")


def grid(root, name, rows):
    path = os.path.join(root, name)
    os.makedirs(path)
    with open(os.path.join(path, "results.json"), "w", encoding="utf-8") as f:
        json.dump({"rows": [dict(name=row, pdr_diff_points=pdr, delay_mean_diff_pct=delay,
                                 mac_tx_diff_pct=mac, control_diff_pct=None)
                            for row, (pdr, delay, mac) in rows.items()]}, f)
    return path


def raw_grid(root, name, rows):
    """A grid whose rows carry both sides' pooled values: {row: (pdr, delay_s, frames, sent)},
    each of the first three a [SwarmNet, ns-3] pair."""
    path = os.path.join(root, name)
    os.makedirs(path)
    tolerances = {"pdr_points": 3.0, "delay_pct": 20.0, "mac_pct": 10.0, "control_pct": None}
    with open(os.path.join(path, "results.json"), "w", encoding="utf-8") as f:
        json.dump({"rows": [dict(name=row, pdr=pdr, delay_mean_s=delay, mac_tx_frames=frames,
                                 control_per_delivered=None, unicast_sent=sent,
                                 tolerances=tolerances, pdr_diff_points=0.0,
                                 delay_mean_diff_pct=0.0, mac_tx_diff_pct=0.0,
                                 control_diff_pct=None)
                            for row, (pdr, delay, frames, sent) in rows.items()]}, f)
    return path


def check_means(root, failures):
    # SwarmNet's network seeds a, b; ns-3's run numbers a, r2 (its SwarmNet side is a's).
    a = raw_grid(root, "ra", {"row-x": ([0.80, 0.70], [0.10, 0.10], [1000, 1000], 50),
                              "row-y": ([0.5, 0.5], [0.2, 0.2], [10, 10], 7)})
    b = raw_grid(root, "rb", {"row-x": ([0.82, 0.70], [0.12, 0.10], [1040, 1000], 50),
                              "row-y": ([0.5, 0.5], [0.2, 0.2], [10, 10], 7)})
    r2 = raw_grid(root, "r2", {"row-x": ([0.80, 0.74], [0.10, 0.10], [1000, 1000], 50)})
    done = run("--model", f"default={a},{b}", "--ns3", f"{a},{r2}")
    if done.returncode != 0:
        failures.append(f"--ns3: exit {done.returncode}: {done.stderr}")
    lines = done.stdout.splitlines()
    # Delivery: means 0.81 (se 0.01) and 0.72 (se 0.02): +9.0 ± 2.2 points, past 3. Delay: 0.11
    # (se 0.01) over 0.10 (se 0): +10.0 ± 10.0%. Frames: 1020 (se 20) over 1000: +2.0 ± 2.0%.
    expected = "| row-x | default | 2 | 2 | +9.0 ± 2.2 (beyond) | +10.0 ± 10.0% | +2.0 ± 2.0% | - |"
    if expected not in lines:
        failures.append("the means line of row-x is missing:\n" + done.stdout)
    done = run("--model", f"default={a},{b}", "--ns3", r2)
    lines = done.stdout.splitlines()
    if "| row-x | default | 2 | 1 | +7.0 ± ? (beyond) | +10.0 ± ?% | +2.0 ± ?% | - |" not in lines:
        failures.append("one ns-3 realization is not shown without an error:\n" + done.stdout)
    if any(line.startswith("| row-y | default | 2 | ") and line.count(" | ") == 7
           for line in lines):
        failures.append("row-y, which no ns-3 re-draw ran, is in the means table:\n" + done.stdout)
    other = raw_grid(root, "other", {"row-x": ([0.80, 0.74], [0.10, 0.10], [1000, 1000], 51)})
    done = run("--model", f"default={a},{b}", "--ns3", f"{a},{other}")
    if done.returncode == 0 or "row-x" not in done.stderr or "same traces" not in done.stderr:
        failures.append("an ns-3 grid of other traces was not refused: " + done.stderr)


SWARMNET = "swarmnet"


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, "--swarmnet", SWARMNET, *args],
                          capture_output=True, text=True)


def main():
    global SWARMNET
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--swarmnet", required=True, help="the swarmnet command")
    SWARMNET = parser.parse_args().swarmnet
    failures = []
    with tempfile.TemporaryDirectory() as root:
        a = grid(root, "a", {"row-x": (1.0, -10.0, 2.0), "row-y": (0.0, 0.0, 0.0)})
        b = grid(root, "b", {"row-x": (3.0, -20.0, 4.0), "row-y": (0.0, 0.0, 0.0)})
        c = grid(root, "c", {"row-x": (-4.0, 6.0, 1.0), "row-y": (2.0, 0.0, 0.0)})
        done = run("--model", f"default={a},{b}", "--model", f"rule={c}")
        if done.returncode != 0:
            failures.append(f"exit {done.returncode}: {done.stderr}")
        lines = done.stdout.splitlines()
        # row-x, default: delivery mean 2.0, sd sqrt(2) = 1.4; delay mean -15.0, sd 7.1.
        expected = ("| row-x | default | 2 | +2.0 ± 1.4 [+1.0, +3.0] | -15.0 ± 7.1 [-20.0, -10.0]% "
                    "| +3.0 ± 1.4 [+2.0, +4.0]% | - |")
        if expected not in lines:
            failures.append("row-x default line missing:\n" + done.stdout)
        if "| row-x | rule | 1 | -4.0 | +6.0% | +1.0% | - |" not in lines:
            failures.append("a single run is not shown alone:\n" + done.stdout)
        if [line.split(" | ")[0] for line in lines if line.startswith("| row-")] != \
                ["| row-x", "| row-x", "| row-y", "| row-y"]:
            failures.append("rows not in the first grid's order, each model once:\n" + done.stdout)
        short = grid(root, "short", {"row-x": (0.0, 0.0, 0.0)})
        done = run("--model", f"default={a},{short}")
        if done.returncode == 0 or os.path.join(short, "results.json") not in done.stderr + \
                done.stdout or "row-y" not in done.stderr + done.stdout:
            failures.append("a grid lacking a row was not refused by name: " + done.stderr)
        check_means(root, failures)
        done = run("--model", f"default={os.path.join(root, 'absent')}")
        if done.returncode == 0 or "absent" not in done.stderr + done.stdout:
            failures.append("a missing results.json was not refused by name: " + done.stderr)
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
