#!/usr/bin/env python3
"""Scenario loading against list length: `swarmnet validate` of the quickstart with N obstacles.

Writes one scenario per N (obstacles in rows above the robots' start region), times `swarmnet
validate` on each with /usr/bin/time (wall seconds, peak RSS), and writes JSON. With --vs OTHER,
the same scenarios are validated by a second build, interleaved (A B A B ...), and the report
gives the ratio per N.

    python3 bench/scenario_loading/run_scenario_loading.py --bin build/bin/swarmnet \\
        --obstacles 1000,4000,16000,100000 [--vs OLD/bin/swarmnet] [--repeats 3] \\
        [--timeout 120] [--out scenario_loading.json]

Standard library only.
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]


def scenario(obstacles: int) -> str:
    rows = []
    for i in range(obstacles):
        x = 1.0 + (i % 400) * 2.0
        y = 200.0 + (i // 400) * 2.0
        rows.append(f"    - {{x_min_m: {x}, y_min_m: {y}, x_max_m: {x + 1}, y_max_m: {y + 1}}}")
    side = max(1000, int(220 + (obstacles // 400) * 2.0 + 10))
    return (f"name: obstacles-{obstacles}\nduration_s: 1\narena:\n  width_m: {side}\n"
            f"  height_m: {side}\n  obstacles:\n" + "\n".join(rows) + "\n"
            "robots:\n  count: 10\n  placement:\n    region: {x_min_m: 0, y_min_m: 0, "
            "x_max_m: 100, y_max_m: 100}\n  controllers:\n    - plugin: diffusion\n"
            "network:\n  propagation:\n    - plugin: disk\n  routing:\n    plugin: flooding\n")


def measure(binary: str, file: pathlib.Path, timeout: float):
    command = ["/usr/bin/time", "-f", "%e %M", binary, "validate", str(file)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return {"wall_s": None, "rss_mb": None, "note": f"did not finish in {timeout} s"}
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stdout}{done.stderr}")
    wall, rss_kb = done.stderr.strip().splitlines()[-1].split()
    return {"wall_s": float(wall), "rss_mb": int(rss_kb) / 1024.0}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--vs", help="a second swarmnet to compare with, interleaved")
    parser.add_argument("--obstacles", default="1000,4000,16000,100000")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--out", default="scenario_loading.json")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory(prefix="swarmnet-loading-") as work:
        for n in (int(x) for x in args.obstacles.split(",")):
            file = pathlib.Path(work) / f"obstacles-{n}.yaml"
            file.write_text(scenario(n))
            runs = {"a": [], "b": []}
            for _ in range(args.repeats):
                runs["a"].append(measure(args.bin, file, args.timeout))
                if args.vs:
                    runs["b"].append(measure(args.vs, file, args.timeout))
            row = {"obstacles": n, "file_mb": file.stat().st_size / 2**20}
            for side, label in (("a", "bin"), ("b", "vs")):
                walls = [r["wall_s"] for r in runs[side] if r["wall_s"] is not None]
                if runs[side]:
                    row[label] = {
                        "median_wall_s": statistics.median(walls) if walls else None,
                        "max_rss_mb": max((r["rss_mb"] for r in runs[side] if r["rss_mb"]),
                                          default=None),
                        "timeouts": len(runs[side]) - len(walls),
                    }
            if args.vs and row["bin"]["median_wall_s"] and row["vs"]["median_wall_s"]:
                row["vs_over_bin"] = row["vs"]["median_wall_s"] / row["bin"]["median_wall_s"]
            rows.append(row)
            print(json.dumps(row))
    pathlib.Path(args.out).write_text(json.dumps({"rows": rows}, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
