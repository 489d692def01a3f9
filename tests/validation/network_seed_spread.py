#!/usr/bin/env python3
"""How far the validation grid's figures move when only SwarmNet's network half is re-drawn.

A grid run with `--set network.seed=N --ns3-from EARLIER` replays the very same traces (the
robots and the traffic keep the master seed; run_grid.py checks the traces byte for byte) against
the very same ns-3 results, and re-draws only SwarmNet's backoff, reception draws, ARP and
routing jitter. The spread of a row's pooled difference to ns-3 over such runs is the part of
that difference that is SwarmNet's own run-to-run noise on fixed traces: a model change that
moves a row by less than it has not been shown to move it. (ns-3's own noise is not in it: its
side is one run per trace.)

    python3 tests/validation/network_seed_spread.py --swarmnet build/bin/swarmnet \\
        --model default=GRID_A,GRID_B,GRID_C --model rule=GRID_D,GRID_E,GRID_F

Each GRID is a run_grid.py output directory (its results.json); the rows of the first grid of
the first model are reported, in its order. Writes a Markdown table to stdout (or --out); exits
non-zero, naming the file, if a results.json is missing or unreadable or lacks a row."""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from seed_interval import student_interval  # noqa: E402  (swarmnet stats: one implementation)

# (results.json key, column heading, unit)
METRICS = [("pdr_diff_points", "delivery (pts)", ""), ("delay_mean_diff_pct", "mean delay", "%"),
           ("mac_tx_diff_pct", "MAC frames", "%"), ("control_diff_pct", "control/deliv.", "%")]


def parse_model(text):
    label, sep, dirs = text.partition("=")
    if not sep or not label or not dirs:
        raise argparse.ArgumentTypeError(f"expected LABEL=DIR[,DIR...], got '{text}'")
    return label, [d for d in dirs.split(",") if d]


def read_rows(grid_dir):
    path = os.path.join(grid_dir, "results.json")
    try:
        with open(path, encoding="utf-8") as f:
            rows = json.load(f)["rows"]
    except (OSError, ValueError, KeyError) as error:
        raise SystemExit(f"network_seed_spread: cannot read {path}: {error}")
    return path, {row["name"]: row for row in rows}


def summary(swarmnet, values):
    """'mean ± sd [min, max]' of the realizations' values, the mean and sample sd from
    `swarmnet stats`; a single realization is shown alone."""
    stats = student_interval(swarmnet, values)
    if stats is None:
        return f"{values[0]:+.1f}"
    return f"{stats['mean']:+.1f} ± {stats['sd']:.1f} [{min(values):+.1f}, {max(values):+.1f}]"


def spread_table(swarmnet, models):
    """models: [(label, [(path, rows_by_name), ...]), ...] -> Markdown text."""
    first_rows = models[0][1][0][1]
    head = ["row", "model", "runs"] + [heading for _, heading, _ in METRICS]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for name in first_rows:
        for label, grids in models:
            cells = [name, label, str(len(grids))]
            for key, _, unit in METRICS:
                values = []
                for path, rows in grids:
                    if name not in rows:
                        raise SystemExit(f"network_seed_spread: {path} has no row {name}")
                    if rows[name].get(key) is not None:
                        values.append(float(rows[name][key]))
                cells.append(summary(swarmnet, values) + unit if values else "-")
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--model", type=parse_model, action="append", required=True,
                        metavar="LABEL=DIR[,DIR...]",
                        help="a model's grid runs, one per network seed")
    parser.add_argument("--swarmnet", default="swarmnet",
                        help="the swarmnet command, whose `stats` computes the means and sds")
    parser.add_argument("--out", help="write the table here instead of stdout")
    args = parser.parse_args(argv)
    models = [(label, [read_rows(d) for d in dirs]) for label, dirs in args.model]
    table = ("Pooled difference to ns-3 (SwarmNet minus ns-3) over the runs of each model: mean ± "
             "sample sd [min, max].\n\n" + spread_table(args.swarmnet, models))
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(table)
    else:
        sys.stdout.write(table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
