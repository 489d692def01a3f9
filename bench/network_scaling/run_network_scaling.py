#!/usr/bin/env python3
"""Network-half CPU per simulated second at constant density (docs/performance.md).

Runs whole scenarios with `swarmnet run --transport inproc` for N robots in a square of side
sqrt(N x 5000 m^2) (the reference study's 50 robots in 500 x 500 m) and reads cpu_s.network from
each summary.json. Two stacks:
  flooding  configs/quickstart.yaml: disk 120 m + ideal_mac + flooding, 20% CBR at 5 msg/s
  aodv      configs/wireless.yaml with routing aodv: log_distance + sinr PHY + dcf80211 (6 Mbit/s,
            120 m nominal range) + AODV, 20% CBR at 5 msg/s
Writes JSON (one row per stack and N). Run it with nothing else on the machine.

Usage: run_network_scaling.py BUILD_DIR [--nodes 50,200,800,3200] [--stacks flooding,aodv]
         [--sim-s 10] [--sim-s-for N=S,...] [--out network_scaling.json] [--no-trace]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STACKS = {"flooding": "configs/quickstart.yaml", "aodv": "configs/wireless.yaml"}


def scenario(stack, n, sim_s, trace):
    with open(os.path.join(ROOT, STACKS[stack])) as f:
        s = yaml.safe_load(f)
    side = math.sqrt(n * 5000.0)
    s["robots"]["count"] = n
    s["arena"]["width_m"] = side
    s["arena"]["height_m"] = side
    # The quickstart's obstacle sits mid-arena at 500 m; move it with the centre.
    for o in s["arena"].get("obstacles", []):
        dx, dy = side / 2 - 250.0, side / 2 - 250.0
        o.update({"x_min_m": o["x_min_m"] + dx, "x_max_m": o["x_max_m"] + dx,
                  "y_min_m": o["y_min_m"] + dy, "y_max_m": o["y_max_m"] + dy})
    s["duration_s"] = sim_s
    if stack == "aodv":
        s["network"]["routing"] = {"plugin": "aodv", "params": {}}
    s["output"] = {"packet_trace": trace, "mobility_trace": False, "traffic_schedule": False}
    return s


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--nodes", default="50,200,800,3200")
    ap.add_argument("--stacks", default="flooding,aodv")
    ap.add_argument("--sim-s", type=float, default=10.0)
    ap.add_argument("--sim-s-for", default="", help="per-N durations, e.g. 3200=2,800=5")
    ap.add_argument("--out", default="network_scaling.json")
    ap.add_argument("--no-trace", action="store_true", help="output.packet_trace=false")
    a = ap.parse_args()
    per_n = dict((int(k), float(v)) for k, v in (x.split("=") for x in a.sim_s_for.split(",") if x))
    binary = os.path.join(a.build, "bin", "swarmnet")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for stack in a.stacks.split(","):
            for n in (int(x) for x in a.nodes.split(",")):
                sim_s = per_n.get(n, a.sim_s)
                path = os.path.join(tmp, f"{stack}-{n}.yaml")
                with open(path, "w") as f:
                    yaml.safe_dump(scenario(stack, n, sim_s, not a.no_trace), f)
                out = os.path.join(tmp, f"{stack}-{n}")
                cmd = ["/usr/bin/time", "-f", "%M", binary, "run", path, "--transport", "inproc",
                       "-q", "--out", out, "--overwrite"]
                r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=True)
                rss_kb = int(r.stderr.strip().splitlines()[-1])
                with open(os.path.join(out, "summary.json")) as f:
                    s = json.load(f)
                cpu = s["cpu_s"]["network"]
                row = {"stack": stack, "nodes": n, "side_m": round(math.sqrt(n * 5000.0), 1),
                       "sim_s": sim_s, "cpu_network_s": cpu,
                       "cpu_network_per_sim_s": cpu / sim_s,
                       "cpu_us_per_node_per_sim_s": 1e6 * cpu / sim_s / n,
                       "cpu_robot_s": s["cpu_s"]["robot"], "events": s["events"],
                       "events_per_sim_s": s["events"] / sim_s,
                       "tx_frames": s["mac"]["tx_frames"], "pdr": s["pdr"],
                       "peak_rss_mb": rss_kb / 1024.0}
                rows.append(row)
                print(json.dumps(row), file=sys.stderr)
    with open(a.out, "w") as f:
        json.dump({"benchmark": "network_scaling", "packet_trace": not a.no_trace, "rows": rows},
                  f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
