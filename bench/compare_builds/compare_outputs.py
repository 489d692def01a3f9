#!/usr/bin/env python3
"""Do two SwarmNet builds give byte-identical outputs on every scenario in configs/?

    python3 bench/compare_builds/compare_outputs.py BEFORE_SWARMNET AFTER_SWARMNET
        [--sim-s 10] [--transport inproc] [--json out.json]

Runs every scenario file in configs/ and configs/paper/ and configs/validation/ (sweep files are
grids of these and are left out) with both commands for a short duration, and compares the
outputs a change must not move unless it means to: packets.csv, positions.bin, mobility.ns2,
traffic.csv, and summary.json without its timing fields (hashed as tests/integration/
pinned_outputs.py hashes them). Prints one row per scenario and file and exits 1 if any differs.
Standard library only.
"""
import argparse
import importlib.util
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(__file__).resolve().parents[2]
SCENARIO_DIRS = ["configs", "configs/paper", "configs/validation"]


def load_pinned_outputs():
    """The hashing rule of the pinned-outputs check, so both checks agree on what 'same' means."""
    path = SOURCE / "tests" / "integration" / "pinned_outputs.py"
    spec = importlib.util.spec_from_file_location("pinned_outputs", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def scenarios():
    found = []
    for folder in SCENARIO_DIRS:
        found += sorted((SOURCE / folder).glob("*.yaml"))
    return found


def run(binary, scenario, out, sim_s, transport):
    """Runs one scenario; returns None, or the refusal of a scenario the build cannot read (exit
    status 2: e.g. a plugin or key newer than the build), which is reported, not compared."""
    shutil.rmtree(out, ignore_errors=True)
    command = [binary, "run", str(scenario), "--quiet", "--transport", transport, "--out",
               str(out), "--set", f"duration_s={sim_s}"]
    done = subprocess.run(command, cwd=SOURCE, capture_output=True, text=True, check=False)
    if done.returncode == 2:
        return done.stderr.strip().splitlines()[0] if done.stderr.strip() else "refused"
    if done.returncode != 0:
        sys.exit(f"compare_outputs: {' '.join(command)} failed ({done.returncode}):\n"
                 f"{done.stdout}{done.stderr}")
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("before", help="the reference swarmnet command")
    parser.add_argument("after", help="the changed swarmnet command")
    parser.add_argument("--sim-s", type=float, default=10.0, help="simulated seconds per run")
    parser.add_argument("--transport", default="inproc", help="transport both builds run over")
    parser.add_argument("--json", help="write every hash here")
    args = parser.parse_args()
    pinned = load_pinned_outputs()
    rows = []
    refused = []
    with tempfile.TemporaryDirectory(prefix="swarmnet-outputs-") as work:
        for scenario in scenarios():
            hashes = {}
            for label, binary in (("before", args.before), ("after", args.after)):
                out = pathlib.Path(work) / f"{scenario.stem}-{label}"
                refusal = run(binary, scenario, out, args.sim_s, args.transport)
                if refusal is not None:
                    refused.append((str(scenario.relative_to(SOURCE)), label, refusal))
                    break
                hashes[label] = {name: pinned.digest(out / name) for name in pinned.FILES
                                 if (out / name).exists()}
            if len(hashes) < 2:
                continue
            for name in pinned.FILES:
                before, after = hashes["before"].get(name), hashes["after"].get(name)
                rows.append({"scenario": str(scenario.relative_to(SOURCE)), "file": name,
                             "before": before, "after": after, "same": before == after})
    print("| scenario | file | same |")
    print("|---|---|---|")
    for row in rows:
        print(f"| {row['scenario']} | {row['file']} | {'yes' if row['same'] else 'NO'} |")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=2) + "\n")
    for scenario, label, refusal in refused:
        print(f"compare_outputs: not compared: the {label} build cannot read {scenario}: {refusal}")
    differ = [row for row in rows if not row["same"]]
    print(f"compare_outputs: {len(rows) - len(differ)} of {len(rows)} outputs identical "
          f"({args.sim_s:g} simulated s, {args.transport})")
    # A scenario the changed build refuses is a regression; one only the reference refuses is new.
    return 1 if differ or any(label == "after" for _, label, _ in refused) else 0


if __name__ == "__main__":
    sys.exit(main())
