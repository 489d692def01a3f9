#!/usr/bin/env python3
"""network_seed_spread.py on grids written here: each model's mean, sample sd and range per row
and metric, a single run shown alone, and a grid lacking a row refused with its file named."""
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
        done = run("--model", f"default={os.path.join(root, 'absent')}")
        if done.returncode == 0 or "absent" not in done.stderr + done.stdout:
            failures.append("a missing results.json was not refused by name: " + done.stderr)
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
