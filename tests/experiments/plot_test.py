#!/usr/bin/env python3
"""scripts/plot.py on a small results file: writes a PNG, refuses an unknown column, and its
95% t quantiles match the textbook values. Exit 77 (skipped) when matplotlib is not installed."""
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
print("plot.py: ok")
