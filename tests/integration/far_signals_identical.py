#!/usr/bin/env python3
"""Far signals, lazy or as events, give the same run to the byte (issue 13).

network.channel.far_signals: lazy (the default) hands a far signal (too weak to be detected or to
make the medium busy alone; network/far_signals.hpp) to a receiver only when it can matter there;
events hands every signal over as events. Both must give the same results. Each scenario below is
run twice with the built `swarmnet`, once per mode, and the runs' packets.csv are compared byte for
byte and their summary.json without the fields that measure the machine (TIMING) or count the
simulator's own work (WORK: scheduler events), the exclusions of pinned_outputs.py. The other
outputs (positions, mobility, traffic) do not depend on the network half's physics.

    python3 tests/integration/far_signals_identical.py --bin build/bin/swarmnet

Standard library only.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import time

import pinned_outputs  # beside this file: the same scenario and summary exclusions

SOURCE = pathlib.Path(__file__).resolve().parents[2]

MODES = ["lazy", "events"]


def paper(robots: int, side_m: float, duration_s: float, seed: int, *extra: str) -> tuple:
    """pinned_outputs.py's study scenario (packet trace on) with another seed."""
    return pinned_outputs.paper(robots, side_m, duration_s, "--set", f"seed={seed}", *extra)


# name: (scenario, extra arguments). About 16 s for all of them, both modes (RelWithDebInfo, one
# core each).
RUNS = {
    # The study's density (side sqrt(N * 5000) m) and load.
    "paper-200-seed2": paper(200, 1000, 10, 2),
    # Four times the density, half the robots sending 20 msg/s: many frames on the air at once,
    # receivers hot (far power summing to -82 dBm) for long stretches.
    "paper-100-dense-loaded": paper(100, 400, 5, 3,
                                    "--set", "robots.controllers.1.params.fraction=0.5",
                                    "--set", "robots.controllers.1.params.rate_hz=20"),
    # AODV without link-layer feedback or HELLOs (the default has both): other routes, other
    # traffic patterns.
    "paper-150-no-feedback": paper(150, 600, 6, 5,
                                   "--set", "network.routing.params.link_layer_feedback=false",
                                   "--set", "network.routing.params.enable_hello=false"),
    # Quiet signals below -87 dBm: far signals are then only those in [-87, -82) dBm, and
    # the quiet ones come from the channel's own query beside them.
    "paper-100-sensing-floor": paper(100, 707.1, 8, 7,
                                     "--set", "network.phy.sensing_floor_db=-5"),
    # Flooding over the same radio, with an obstacle.
    "wireless": ("configs/wireless.yaml", ["--set", "duration_s=10"]),
    # Saturated (pinned_outputs.py's "saturated", another seed): every robot sends 50 msg/s.
    "saturated": paper(100, 500, 5, 4, "--set", "robots.controllers.1.params.fraction=1",
                       "--set", "robots.controllers.1.params.rate_hz=50"),
    # Energy detection below the CCA threshold (-88 dBm): far signals are those below -88 dBm,
    # and the hot bound counts against the lower threshold.
    "paper-ed-below-cca": paper(100, 500, 5, 6, "--set", "network.phy.energy_detection_dbm=-88",
                                "--set", "robots.controllers.1.params.rate_hz=20"),
    # RTS/CTS for every data frame: short control frames among long ones, NAV.
    "paper-rts-cts": paper(100, 500, 5, 10, "--set", "network.mac.params.rts_threshold_bytes=100",
                           "--set", "robots.controllers.1.params.rate_hz=20"),
    # ns-3's header-failure rule: far signals that join a locked frame's preamble or header
    # decide what the MAC is told, and while it counts the medium idle the next signal to start
    # ends that, far ones included. Dense and loaded, so headers fail often.
    "paper-100-dense-header-rule": paper(100, 400, 5, 12,
                                         "--set", "network.phy.header_failure_cca=ns3",
                                         "--set", "robots.controllers.1.params.fraction=0.5",
                                         "--set", "robots.controllers.1.params.rate_hz=20"),
    "saturated-header-rule": paper(100, 500, 5, 13, "--set", "network.phy.header_failure_cca=ns3",
                                   "--set", "robots.controllers.1.params.fraction=1",
                                   "--set", "robots.controllers.1.params.rate_hz=50"),
    # Quiet signals under saturation.
    "saturated-sensing-floor": paper(100, 500, 5, 11, "--set", "network.phy.sensing_floor_db=-5",
                                     "--set", "robots.controllers.1.params.fraction=1",
                                     "--set", "robots.controllers.1.params.rate_hz=30"),
}


def run(binary: str, name: str, scenario: str, extra: list, mode: str,
        out: pathlib.Path) -> None:
    command = [binary, "run", scenario, "--quiet", "--transport", "inproc", "--out", str(out),
               *extra, "--set", f"network.channel.far_signals={mode}"]
    done = subprocess.run(command, cwd=SOURCE, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"far_signals_identical: {name} ({mode}): {' '.join(command)} failed:\n"
                 f"{done.stdout}{done.stderr}")


def first_difference(a: list, b: list) -> str:
    for number, (line_a, line_b) in enumerate(zip(a, b), start=1):
        if line_a != line_b:
            return f"line {number}:\n  lazy:   {line_a!r}\n  events: {line_b!r}"
    return (f"line {min(len(a), len(b)) + 1}: one file ends there "
            f"(lazy {len(a)} lines, events {len(b)} lines)")


def summary_lines(path: pathlib.Path) -> list:
    results = pinned_outputs.results_of(json.loads(path.read_text()))
    return json.dumps(results, sort_keys=True, indent=1).splitlines()


def compare(name: str, outs: dict) -> list:
    """The differences between the two modes' outputs, one message each."""
    problems = []
    lazy, events = outs["lazy"], outs["events"]
    packets = [(out / "packets.csv").read_bytes() for out in (lazy, events)]
    if packets[0] != packets[1]:
        text = [p.decode(errors="replace").splitlines() for p in packets]
        problems.append(f"{name}: packets.csv differs at {first_difference(*text)}")
    elif packets[0].count(b"\n") < 2:
        problems.append(f"{name}: packets.csv holds no packet (is the trace on?)")
    summaries = [summary_lines(out / "summary.json") for out in (lazy, events)]
    if summaries[0] != summaries[1]:
        left_out = ", ".join(pinned_outputs.TIMING + pinned_outputs.WORK)
        problems.append(f"{name}: summary.json (less {left_out}) differs at "
                        f"{first_difference(*summaries)}")
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True, help="the swarmnet command to run")
    parser.add_argument("--only", action="append", help="run only this scenario (repeatable)")
    args = parser.parse_args()
    names = args.only or list(RUNS)
    unknown = [n for n in names if n not in RUNS]
    if unknown:
        sys.exit(f"far_signals_identical: unknown scenario {unknown}; known: {list(RUNS)}")
    problems = []
    with tempfile.TemporaryDirectory(prefix="swarmnet-far-signals-") as work:
        for name in names:
            scenario, extra = RUNS[name]
            started = time.monotonic()
            outs = {}
            for mode in MODES:
                outs[mode] = pathlib.Path(work) / name / mode
                run(args.bin, name, scenario, extra, mode, outs[mode])
            found = compare(name, outs)
            if found:
                found.append(f"{name}: reproduce with\n  {args.bin} run {scenario} --quiet "
                             f"--transport inproc {' '.join(extra)} "
                             "--set network.channel.far_signals=lazy (and =events)")
            problems += found
            events = {mode: json.loads((outs[mode] / "summary.json").read_text()).get("events")
                      for mode in MODES}
            print(f"far_signals_identical: {name}: {'DIFFERS' if found else 'identical'} "
                  f"({time.monotonic() - started:.1f} s; scheduler events lazy {events['lazy']}, "
                  f"events {events['events']})")
    if problems:
        for problem in problems:
            print(f"far_signals_identical: {problem}")
        print("far_signals_identical: far_signals lazy and events gave different results: a bug "
              "in the lazy path (core/src/network/far_signals.cpp, phy.cpp).")
        return 1
    print(f"far_signals_identical: {len(names)} scenarios identical in both modes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
