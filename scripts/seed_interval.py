"""How sure a comparison over seeds is: the mean of one value per seed (for example SwarmNet's
delivery ratio minus ns-3's on the same trace) and its 95% Student-t confidence interval, as
`swarmnet stats` computes them, so that the grid, the benches and the sweeps share one statistics
implementation.

Single AODV runs of a few hundred messages swing by tens of points between seeds (a flow lost to
an undetected break costs a whole flow), so a pooled difference over eight seeds can miss a
3-point target by chance alone; the interval says whether it does."""
import csv
import json
import pathlib
import subprocess
import tempfile


def student_interval(swarmnet, values):
    """{'n', 'mean', 'sd', 'low', 'high'} of `values` from `swarmnet stats`; None for fewer than
    two values (no interval exists). The interval is of the unweighted mean of the values; beside
    a pooled difference over seeds of near-equal size it is a close companion, not the same
    number. Raises RuntimeError naming the command if it fails, OSError if it cannot start."""
    values = [float(v) for v in values]
    if len(values) < 2:
        return None
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "values.csv"
        with open(path, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["value"])
            writer.writerows([repr(v)] for v in values)
        command = [str(swarmnet), "stats", str(path), "--metric", "value", "--json"]
        done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
    group = json.loads(done.stdout)["metrics"]["value"]["groups"][0]
    return {"n": group["n"], "mean": group["mean"], "sd": group["sd"], "low": group["ci_low"],
            "high": group["ci_high"]}
