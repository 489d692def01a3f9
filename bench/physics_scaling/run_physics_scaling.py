#!/usr/bin/env python3
"""Physics cost per simulated second at constant density: ode against kinematic2d
(docs/performance.md, "Physics scaling").

Runs BUILD_DIR/bin/physics_scaling (the robot half's physics alone: the plugin loaded from
BUILD_DIR/plugins through its SDK entry point, N robots diffusing at 0.5 robots/m^2, 0.1 s steps,
24 proximity rays of 0.1 m per robot) for each engine and N, interleaving the engines, REPEATS
times each; keeps the median by CPU time. Writes JSON: one row per engine and N, with every
repeat's CPU seconds, and prints a Markdown table. Run it with nothing else on the machine.

Usage: run_physics_scaling.py BUILD_DIR [--robots 50,400,2000,10000] [--engines ode,kinematic2d]
         [--repeats 3] [--sim-s-for N=S,...] [--density 0.5] [--out physics_scaling.json]
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys

DEFAULT_SIM_S = {50: 60.0, 400: 30.0, 2000: 20.0, 10000: 10.0}


def parse_sim_s(text):
    table = dict(DEFAULT_SIM_S)
    for item in filter(None, (text or "").split(",")):
        n, s = item.split("=")
        table[int(n)] = float(s)
    return table


def run_once(build, engine, robots, sim_s, density):
    binary = os.path.join(build, "bin", "physics_scaling")
    out = subprocess.run([binary, os.path.join(build, "plugins"), engine, str(robots), str(sim_s),
                          str(density)], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--robots", default="50,400,2000,10000")
    parser.add_argument("--engines", default="ode,kinematic2d")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--sim-s-for", default="")
    parser.add_argument("--density", type=float, default=0.5)
    parser.add_argument("--out", default="physics_scaling.json")
    args = parser.parse_args()
    sim_s_for = parse_sim_s(args.sim_s_for)
    engines = args.engines.split(",")
    rows = []
    for robots in (int(n) for n in args.robots.split(",")):
        sim_s = sim_s_for.get(robots, 10.0)
        runs = {engine: [] for engine in engines}
        for _ in range(args.repeats):
            for engine in engines:
                runs[engine].append(run_once(args.build, engine, robots, sim_s, args.density))
        for engine in engines:
            ordered = sorted(runs[engine], key=lambda r: r["cpu_s"])
            median = ordered[len(ordered) // 2]
            if len({r["mean_x_m"] for r in ordered}) != 1:
                sys.exit(f"{engine} at {robots} robots: repeats ended in different states")
            median["repeats_cpu_s"] = [r["cpu_s"] for r in runs[engine]]
            rows.append(median)
            print(f"{engine:12s} {robots:6d} robots: {median['realtime_factor']:9.2f}x real time, "
                  f"{median['us_per_robot_step']:7.3f} us per robot-step", file=sys.stderr)
    with open(args.out, "w") as f:
        json.dump({"machine": platform.processor() or platform.machine(),
                   "cpus": os.cpu_count(), "density_per_m2": args.density,
                   "repeats": args.repeats, "rows": rows}, f, indent=2)
    print("| robots | engine | sim s | CPU s per sim s | real-time factor | us per robot-step "
          "(step + proximity) |")
    print("|---:|---|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['robots']} | {r['engine']} | {r['sim_s']:.0f} | {r['cpu_s_per_sim_s']:.4f} | "
              f"{r['realtime_factor']:.1f}x | {r['us_per_robot_step']:.2f} "
              f"({1e6 * r['step_cpu_s'] / r['steps'] / r['robots']:.2f} + "
              f"{1e6 * r['proximity_cpu_s'] / r['steps'] / r['robots']:.2f}) |")


if __name__ == "__main__":
    main()
