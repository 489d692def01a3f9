#!/usr/bin/env python3
"""run_grid.py --ns3-from: a pair re-run on SwarmNet's side only takes ns-3's result from an
earlier run of the same pair, and refuses to when the replay would not have been the same.

Runs configs/validation/small.yaml (5 simulated s) once through SwarmNet and ns-3, then again
with a SwarmNet-side option (network.phy.header_failure_cca: ns3) reusing ns-3's result: the
result must be the earlier one, byte for byte; and with another network.seed, which re-draws the
network half alone and so leaves the traces as they were. Then three reuses that must be refused:
other ns-3 options (the aligned setup), another ns-3 run number (run_grid.py --ns3-run), and
other traces (a shorter run, so other messages). Then a pair with another ns-3 run number runs
ns-3 with it (its RngRun) on the very same traces. Last, run_grid.py --resume: a copy of the
first pair's directory is read back without running anything, and run again when asked for
other commands.
"""
import argparse
import filecmp
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_runner as vr  # noqa: E402

SHORT = ["duration_s=5"]


def refused(run, fragment):
    """Whether run() raises a RuntimeError whose text holds `fragment`."""
    try:
        run()
    except RuntimeError as error:
        if fragment in str(error):
            return True
        print(f"refused, but with another reason: {error}")
        return False
    return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--swarmnet", required=True, help="the swarmnet command")
    parser.add_argument("--ns3", required=True, help="the swarmnet_ns3_replay program")
    parser.add_argument("--work", required=True, help="directory for the runs")
    args = parser.parse_args()
    scenario = os.path.join(vr.SOURCE_DIR, "configs", "validation", "small.yaml")
    stack, _ = vr.detect_stack(args.swarmnet, scenario)
    if stack != "80211":
        print("SwarmNet's 802.11 stack is not available: nothing to check")
        return 77

    def pair(name, overrides, **options):
        return vr.run_pair(args.swarmnet, args.ns3, scenario, os.path.join(args.work, name),
                           "direct", stack, overrides, log=lambda s: None, **options)

    failures = []
    kept = os.path.join(args.work, "kept")
    pair("kept", SHORT)
    reused = os.path.join(args.work, "reused")
    summary, _ = pair("reused", SHORT + ["network.phy.header_failure_cca=ns3"], ns3_from=kept)
    if not filecmp.cmp(os.path.join(kept, "ns3.json"), os.path.join(reused, "ns3.json"),
                       shallow=False):
        failures.append("the reused ns3.json is not the kept one")
    with open(os.path.join(reused, "commands.json"), encoding="utf-8") as f:
        if json.load(f).get("ns3_from") != kept:
            failures.append("commands.json does not say where ns-3's result came from")
    if os.path.exists(os.path.join(reused, "ns3.out")):
        failures.append("ns-3 ran although its result was reused")
    if "pdr" not in summary:
        failures.append("SwarmNet's run has no summary")
    try:
        pair("network-seed", SHORT + ["network.seed=1001"], ns3_from=kept)
    except RuntimeError as error:
        failures.append(f"a run with another network.seed could not reuse ns-3's result: {error}")
    if not refused(lambda: pair("aligned", SHORT, setup="aligned", ns3_from=kept),
                   "its ns-3 run had other options"):
        failures.append("a reuse with other ns-3 options was not refused")
    if not refused(lambda: pair("ns3-run-reused", SHORT, ns3_from=kept, ns3_run=7),
                   "its ns-3 run had other options"):
        failures.append("a reuse with another ns-3 run number was not refused")
    redrawn = os.path.join(args.work, "ns3-run")
    pair("ns3-run", SHORT, ns3_run=7)
    with open(os.path.join(redrawn, "commands.json"), encoding="utf-8") as f:
        command = json.load(f)["ns3"]
    if command[command.index("--seed") + 1] != "7":
        failures.append(f"ns-3 did not run with the run number asked for: {command}")
    for name in ("mobility.ns2", "traffic.csv"):
        if not filecmp.cmp(os.path.join(kept, "swarmnet", name),
                           os.path.join(redrawn, "swarmnet", name), shallow=False):
            failures.append(f"another ns-3 run number changed SwarmNet's {name}")
    if not refused(lambda: pair("shorter", ["duration_s=4"], ns3_from=kept),
                   "the traces changed"):
        failures.append("a reuse with other traces was not refused")
    copied = os.path.join(args.work, "copied")
    shutil.rmtree(copied, ignore_errors=True)
    shutil.copytree(kept, copied)
    outputs = [os.path.join(copied, name) for name in ("swarmnet.out", "ns3.out")]
    for output in outputs:
        os.remove(output)  # written again only if a program runs again
    pair("copied", SHORT, resume=True)
    if any(os.path.exists(output) for output in outputs):
        failures.append("a pair copied to another directory was run again under --resume")
    pair("copied", SHORT + ["network.seed=1001"], resume=True)
    if not all(os.path.exists(output) for output in outputs):
        failures.append("a pair asked for with other commands was read back under --resume")
    for failure in failures:
        print("FAIL: " + failure)
    if not failures:
        print("ns-3 results are reused only for the same replay of the same traces, and pairs "
              "resumed only for the same commands")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
