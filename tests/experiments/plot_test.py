#!/usr/bin/env python3
"""scripts/plot.py on a small results file, a run's series.csv and its robot_metrics.csv: writes
a PNG of each, refuses an unknown column, series or metric by name, and its 95% t quantiles match
the textbook values. Exit 77 (skipped) when matplotlib is not installed."""
import importlib.util
import os
import subprocess
import sys
import tempfile

plot = sys.argv[1]
spec = importlib.util.spec_from_file_location("plot", plot)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)
for df, q in [(1, 12.706), (2, 4.303), (5, 2.571), (10, 2.228), (30, 2.042), (60, 2.000),
              (120, 1.980)]:
    assert abs(module.t975(df) - q) < 1e-3, (df, module.t975(df), q)

try:
    import matplotlib  # noqa: F401
except ImportError:
    print("SKIPPED: matplotlib is not installed (Debian: apt-get install python3-matplotlib)")
    sys.exit(77)

with tempfile.TemporaryDirectory() as tmp:
    results = os.path.join(tmp, "results.csv")
    with open(results, "w") as f:
        f.write("run_id,seed,status,robots.count,network.routing,pdr\n")
        for n in (10, 20):
            for routing in ("aodv", "flooding"):
                for seed in (1, 2, 3):
                    pdr = 0.9 - n / 100 + (0.05 if routing == "aodv" else 0) + seed / 100
                    f.write(f"r,{seed},ok,{n},{routing},{pdr}\n")
        f.write("r,4,failed,20,aodv,\n")
    png = os.path.join(tmp, "fig.png")
    subprocess.run([sys.executable, plot, results, "--x", "robots.count", "--y", "pdr",
                    "--by", "network.routing", "--out", png], check=True)
    with open(png, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"
    bad = subprocess.run([sys.executable, plot, results, "--x", "robots", "--y", "pdr",
                          "--out", png], capture_output=True, text=True)
    assert bad.returncode != 0 and "no column 'robots'" in bad.stderr, bad.stderr

    series = os.path.join(tmp, "series.csv")
    with open(series, "w") as f:
        f.write("time_ns,robot,series,value\n")
        for step in range(20):
            for robot in range(3):
                f.write(f"{step * 100000000},{robot},\"rssi, dBm\",{-60 - robot - step * 0.5}\n")
                f.write(f"{step * 100000000},{robot},known,{(robot + step) % 2}\n")
            f.write(f"{step * 100000000 + 100000000},,done,{step}\n")
    for robots in ("mean", "all", "0,2"):
        out = os.path.join(tmp, f"series-{robots}.png")
        subprocess.run([sys.executable, plot, series, "--y", "rssi, dBm", "--robots", robots,
                        "--out", out], check=True)
        with open(out, "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n", robots
    subprocess.run([sys.executable, plot, series, "--y", "done", "--out", png], check=True)
    bad = subprocess.run([sys.executable, plot, series, "--y", "rssi", "--out", png],
                         capture_output=True, text=True)
    assert bad.returncode != 0 and "no samples of series 'rssi'" in bad.stderr, bad.stderr
    assert "rssi, dBm" in bad.stderr and "known" in bad.stderr, bad.stderr
    bad = subprocess.run([sys.executable, plot, series, "--y", "known", "--robots", "x",
                          "--out", png], capture_output=True, text=True)
    assert bad.returncode != 0 and "--robots x" in bad.stderr, bad.stderr

    per_robot = os.path.join(tmp, "robot_metrics.csv")
    with open(per_robot, "w") as f:
        f.write("robot,metric,count,sum,mean,min,max\n")
        for robot in range(4):
            f.write(f"{robot},decisions,{robot + 1},{robot},{robot / (robot + 1)},0,1\n")
    bars = os.path.join(tmp, "bars.png")
    subprocess.run([sys.executable, plot, per_robot, "--y", "decisions", "--stat", "sum",
                    "--out", bars], check=True)
    with open(bars, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"
    bad = subprocess.run([sys.executable, plot, per_robot, "--y", "hops", "--out", bars],
                         capture_output=True, text=True)
    assert bad.returncode != 0 and "no robot recorded metric 'hops'" in bad.stderr, bad.stderr
print("plot.py: ok")
