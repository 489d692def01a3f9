#!/usr/bin/env python3
"""A figure script started with a python3 that lacks matplotlib (pyenv's, a virtualenv's) restarts
itself under Debian's /usr/bin/python3, which has it, and draws. Run with the first python3 on
PATH; exit 77 (skipped) where that one has matplotlib itself or /usr/bin/python3 lacks it."""
import os
import subprocess
import sys
import tempfile

script = sys.argv[1]
try:
    import matplotlib  # noqa: F401
    print(f"SKIPPED: {sys.executable} has matplotlib, so nothing needs restarting")
    sys.exit(77)
except ImportError:
    pass
if subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"]).returncode != 0:
    print("SKIPPED: /usr/bin/python3 has no matplotlib (Debian: apt-get install python3-matplotlib)")
    sys.exit(77)

with tempfile.TemporaryDirectory() as tmp:
    results = os.path.join(tmp, "results.csv")
    with open(results, "w") as f:
        f.write("run_id,seed,status,robots.count,arena.width_m,arena.height_m,duration_s,wall_s,"
                "cpu_s.robot,cpu_s.network,cpu_s.transport,cpu_s.total,realtime_factor,pdr\n")
        f.write("a,1,ok,200,1000,1000,100,31,0.1,30,0.2,30.3,3.2,0.8\n")
    done = subprocess.run([sys.executable, script, "--results", results], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    assert "running under /usr/bin/python3" in done.stderr, done.stderr
    with open(os.path.join(tmp, "scaling.png"), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"
print("figure scripts restart under a python3 with matplotlib: ok")
