#!/usr/bin/env python3
"""scripts/reproduce_scaling.py --results on a small results file: averages the seeds of each
size, divides by each size's own duration, puts the study's figures beside sizes it measured,
leaves out failed runs, and draws a PNG. Exit 77 (skipped) when matplotlib is not installed."""
import os
import subprocess
import sys
import tempfile

script = sys.argv[1]
try:
    import matplotlib  # noqa: F401
except ImportError:
    print("SKIPPED: matplotlib is not installed (Debian: apt-get install python3-matplotlib)")
    sys.exit(77)

COLUMNS = ("run_id,seed,status,robots.count,arena.width_m,arena.height_m,duration_s,wall_s,"
           "cpu_s.robot,cpu_s.network,cpu_s.transport,cpu_s.total,realtime_factor,pdr\n")
with tempfile.TemporaryDirectory() as tmp:
    results = os.path.join(tmp, "results.csv")
    with open(results, "w") as f:
        f.write(COLUMNS)
        # 200 robots, 100 s, two seeds: network 30 and 50 CPU-s -> mean 40, 0.4 per simulated s.
        f.write("a,1,ok,200,1000,1000,100,31,0.1,30,0.2,30.3,3.2,0.8\n")
        f.write("b,2,ok,200,1000,1000,100,51,0.1,50,0.2,50.3,2.0,0.9\n")
        f.write("c,3,failed,200,1000,1000,100,,,,,,,\n")
        # 800 robots, 10 s: 80 CPU-s of network -> 8 per simulated s; no study figure.
        f.write("d,1,ok,800,2000,2000,10,85,0.05,80,0.3,80.35,0.12,0.3\n")
    done = subprocess.run([sys.executable, script, "--results", results], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    with open(os.path.join(tmp, "table.md")) as f:
        rows = [line for line in f.read().splitlines() if line.startswith("| 200 ") or
                line.startswith("| 800 ")]
    assert len(rows) == 2, rows
    assert "| 0.10 + 40.00 + 0.20 = 40.30 |" in rows[0], rows[0]
    assert "| 0.0010 / 0.4000 |" in rows[0], rows[0]
    assert "| 0.264 / 1.298 (1.968) |" in rows[0], rows[0]  # the study's Tables II and I / 200 s
    assert "| 0.850 |" in rows[0], rows[0]
    assert "| 0.0050 / 8.0000 | - |" in rows[1], rows[1]
    with open(os.path.join(tmp, "scaling.png"), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"
print("reproduce_scaling.py: ok")
