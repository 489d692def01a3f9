#!/usr/bin/env python3
"""Results change only on purpose: short reference runs whose output hashes are pinned in the tree.

Runs each reference scenario below with the built `swarmnet`, hashes its outputs (packets.csv,
positions.bin, mobility.ns2, traffic.csv, summary.json, headings.bin, and the task-allocation
run's view_states.csv) and compares them with tests/integration/pinned_outputs.txt. summary.json
is hashed without its top-level fields that measure the machine (TIMING) or count the
simulator's own work (WORK: scheduler events), so a faster simulator moves no pin; everything
the simulation produced (packets, drops, frames, routing and ARP counts) stays in the hash.
A change that moves a result fails here; if the change is meant to move it, re-pin and say so
in the commit:

    python3 tests/integration/pinned_outputs.py --bin build/bin/swarmnet --repin

Standard library only.
"""
import argparse
import hashlib
import json
import pathlib
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(__file__).resolve().parents[2]
PINS = SOURCE / "tests" / "integration" / "pinned_outputs.txt"


def paper(robots: int, side_m: float, duration_s: float, *extra: str) -> tuple:
    """The study's evaluation scenario (802.11a DCF, sinr PHY, AODV, ARP; traffic from 1 s)."""
    return ("configs/paper/evaluation.yaml",
            ["--set", f"robots.count={robots}", "--set", f"arena.width_m={side_m}",
             "--set", f"arena.height_m={side_m}", "--set", f"duration_s={duration_s}",
             "--set", "output.packet_trace=true", *extra])


# name: (scenario, extra arguments). Short, so the whole check takes seconds.
RUNS = {
    "quickstart-strict": ("configs/quickstart.yaml", ["--set", "duration_s=20"]),
    "quickstart-pipelined": ("configs/quickstart.yaml",
                             ["--set", "duration_s=20", "--set", "sync=pipelined"]),
    "wireless": ("configs/wireless.yaml", ["--set", "duration_s=10"]),
    "aodv": ("configs/aodv.yaml", ["--set", "duration_s=10"]),
    # ODE physics (Debian's libode 0.16.2): a change of the plugin or of the library shows here.
    "ode": ("configs/ode.yaml", ["--set", "duration_s=10"]),
    # The study's task allocation (world plugin, controller, flooding over 802.11a), 10 robots and
    # 2 events, to the end of the task.
    "task-allocation": ("configs/paper/task-allocation.yaml",
                        ["--set", "robots.count=10", "--set", "world.0.params.events=2",
                         "--set", "output.packet_trace=true"]),
    # The study's evaluation at its constant density (side sqrt(N * 5000) m, as
    # configs/sweeps/paper-scaling.yaml), the default result issue 13 guards. Base build, 2 cores:
    # 0.3, 1.2 and 1.9 s wall.
    "paper-100": paper(100, 707.1, 10),
    "paper-200": paper(200, 1000, 10),
    "paper-400": paper(400, 1414.2, 5),
    # Fading: configs/wireless.yaml's path loss, then nakagami with ns-3's defaults. A list can
    # only be replaced whole, so the path loss is repeated here.
    "nakagami": ("configs/wireless.yaml",
                 ["--set", "duration_s=10", "--set",
                  "network.propagation=[{plugin: log_distance, params: {exponent: 3, "
                  "reference_distance_m: 1, reference_loss_db: 46.6777}}, {plugin: nakagami}]"]),
    # Saturated: twice the density and every robot sending 50 msg/s (22 Mbit/s offered on a
    # 6 Mbit/s channel): MAC queues hit their 0.5 s wait limit (buffer_timeout), AODV's request
    # buffers and ARP's pending queues overflow, ~10,000 collisions and retries. 1.2 s wall.
    "saturated": paper(100, 500, 5, "--set", "robots.controllers.1.params.fraction=1",
                       "--set", "robots.controllers.1.params.rate_hz=50"),
    # The same with ns-3.37's MAC view after a header failure (network.phy.header_failure_cca),
    # which the validation grid's saturated rows depend on.
    "saturated-ns3-header": paper(100, 500, 5, "--set", "robots.controllers.1.params.fraction=1",
                                  "--set", "robots.controllers.1.params.rate_hz=50",
                                  "--set", "network.phy.header_failure_cca=ns3"),
}
FILES = ["packets.csv", "positions.bin", "mobility.ns2", "traffic.csv", "summary.json",
         "headings.bin"]
# Outputs only some runs write: what the plugins showed the viewer (robot states, world objects).
EXTRA_FILES = {"task-allocation": ["view_states.csv"]}
# Fields of summary.json that measure the machine, not the simulation.
TIMING = ["wall_s", "cpu_s", "realtime_factor", "transport_share"]
# Fields that count the simulator's own work: a change of how it schedules moves them, not results.
WORK = ["events"]


def results_of(summary: dict) -> dict:
    """summary.json less the fields that measure the machine or the simulator's work."""
    return {key: value for key, value in summary.items() if key not in TIMING + WORK}


def digest(path: pathlib.Path) -> str:
    data = path.read_bytes()
    if path.name == "summary.json":
        data = json.dumps(results_of(json.loads(data)), sort_keys=True).encode()
    return hashlib.sha256(data).hexdigest()


def measure(binary: str, work: pathlib.Path) -> dict:
    hashes = {}
    for name, (scenario, extra) in RUNS.items():
        out = work / name
        command = [binary, "run", scenario, "--quiet", "--transport", "inproc", "--out", str(out),
                   *extra]
        done = subprocess.run(command, cwd=SOURCE, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"pinned_outputs: {' '.join(command)} failed:\n{done.stdout}{done.stderr}")
        for file in FILES + EXTRA_FILES.get(name, []):
            hashes[f"{name} {file}"] = digest(out / file)
    return hashes


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True, help="the swarmnet command to run")
    parser.add_argument("--repin", action="store_true", help="write the hashes measured now")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="swarmnet-pinned-") as work:
        measured = measure(args.bin, pathlib.Path(work))
    if args.repin:
        PINS.write_text("".join(f"{key} {value}\n" for key, value in measured.items()))
        print(f"pinned_outputs: wrote {len(measured)} hashes to {PINS.relative_to(SOURCE)}")
        return 0
    pinned = {}
    for line in PINS.read_text().splitlines():
        run, file, value = line.split()
        pinned[f"{run} {file}"] = value
    moved = [key for key in measured if pinned.get(key) != measured[key]]
    missing = [key for key in pinned if key not in measured]
    if moved or missing:
        for key in moved:
            print(f"pinned_outputs: {key} changed ({pinned.get(key, 'not pinned')} -> "
                  f"{measured[key]})")
        for key in missing:
            print(f"pinned_outputs: {key} is pinned but no longer produced")
        print("pinned_outputs: results moved. If that is intended, re-pin and say so in the "
              "commit:\n  python3 tests/integration/pinned_outputs.py --bin build/bin/swarmnet "
              "--repin")
        return 1
    print(f"pinned_outputs: {len(measured)} outputs of {len(RUNS)} reference runs unchanged")
    return 0


if __name__ == "__main__":
    sys.exit(main())
