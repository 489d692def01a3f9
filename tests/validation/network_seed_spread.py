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
        --model default=GRID_A,GRID_B,GRID_C --model rule=GRID_D,GRID_E,GRID_F \\
        [--ns3 GRID_A,GRID_R2,GRID_R3]

With --ns3, grids run with `run_grid.py --ns3-run N` (other ns-3 run numbers over the same
traces) bring ns-3's own noise in: a second table gives, per row and model, the difference of
SwarmNet's mean over its runs and ns-3's mean over its realizations, with its standard error,
judged against the row's targets. That, not one draw against one draw, is what a row's agreement
is. A row's ns-3 realizations are the --ns3 grids that ran it (a re-draw may cover some rows
only); a row none ran is left out of that table.

Each GRID is a run_grid.py output directory (its results.json); the rows of the first grid of
the first model are reported, in its order. Writes Markdown tables to stdout (or --out); exits
non-zero, naming the file, if a results.json is missing or unreadable or lacks a row, or if an
--ns3 grid's row sent other messages than the model's (other traces)."""
import argparse
import json
import math
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


# (results.json key of the [SwarmNet, ns-3] pair, tolerance key, column heading, unit, scale):
# delivery is compared in points, the others relative to ns-3's mean.
RAW_METRICS = [("pdr", "pdr_points", "delivery (pts)", "", "points"),
               ("delay_mean_s", "delay_pct", "mean delay", "%", "relative"),
               ("mac_tx_frames", "mac_pct", "MAC frames", "%", "relative"),
               ("control_per_delivered", "control_pct", "control/deliv.", "%", "relative")]


def side_values(grids, name, key, side):
    """One side's pooled value of `key` in row `name` of every grid (None where not measured)."""
    values = []
    for path, rows in grids:
        if name not in rows:
            raise SystemExit(f"network_seed_spread: {path} has no row {name}")
        pair = rows[name].get(key)
        values.append(None if pair is None or pair[side] is None else float(pair[side]))
    return values


def mean_and_se(swarmnet, values):
    """The mean of the realizations and its standard error (None for a single realization)."""
    stats = student_interval(swarmnet, values)
    if stats is None:
        return values[0], None
    return stats["mean"], stats["sd"] / math.sqrt(stats["n"])


def difference_cell(swarmnet, mine, theirs, scale, tolerance, unit):
    """'diff ± se' of the two sides' means (se '?' when a side has one realization), with
    '(beyond)' when the difference passes the row's tolerance."""
    if any(v is None for v in mine + theirs):
        return "-"
    m, m_se = mean_and_se(swarmnet, mine)
    n, n_se = mean_and_se(swarmnet, theirs)
    if scale == "points":
        diff = 100.0 * (m - n)
        se = None if m_se is None or n_se is None else 100.0 * math.hypot(m_se, n_se)
    else:
        diff = 100.0 * (m / n - 1.0)
        se = (None if m_se is None or n_se is None else
              100.0 * (m / n) * math.hypot(m_se / m, n_se / n))
    text = f"{diff:+.1f}" + (f" ± {se:.1f}" if se is not None else " ± ?") + unit
    if tolerance is not None and tolerance >= 0 and abs(diff) > tolerance:
        text += " (beyond)"
    return text


def means_table(swarmnet, models, ns3_grids):
    """Per row and model: the difference of SwarmNet's mean over its runs and ns-3's mean over
    its run numbers, ± the standard error of that difference."""
    first_rows = models[0][1][0][1]
    head = ["row", "model", "runs", "ns-3 runs"] + [heading for _, _, heading, _, _ in RAW_METRICS]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for name in first_rows:
        # A row's ns-3 realizations are the --ns3 grids that ran it (a re-draw may cover a
        # subset of the rows); a row none of them ran is left out.
        row_ns3 = [(path, rows) for path, rows in ns3_grids if name in rows]
        if not row_ns3:
            continue
        sent = set()
        for path, rows in [g for _, grids in models for g in grids] + row_ns3:
            if name not in rows:
                raise SystemExit(f"network_seed_spread: {path} has no row {name}")
            sent.add(rows[name].get("unicast_sent"))
        if len(sent) > 1:
            raise SystemExit(f"network_seed_spread: row {name} sent {sorted(map(str, sent))} "
                             f"messages in different grids: they did not replay the same traces")
        tolerances = first_rows[name].get("tolerances") or {}
        for label, grids in models:
            cells = [name, label, str(len(grids)), str(len(row_ns3))]
            for key, tolerance, _, unit, scale in RAW_METRICS:
                cells.append(difference_cell(swarmnet, side_values(grids, name, key, 0),
                                             side_values(row_ns3, name, key, 1), scale,
                                             tolerances.get(tolerance), unit))
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--model", type=parse_model, action="append", required=True,
                        metavar="LABEL=DIR[,DIR...]",
                        help="a model's grid runs, one per network seed")
    parser.add_argument("--swarmnet", default="swarmnet",
                        help="the swarmnet command, whose `stats` computes the means and sds")
    parser.add_argument("--ns3", metavar="DIR[,DIR...]",
                        help="grids whose ns-3 side are other realizations (run_grid.py "
                             "--ns3-run) over the same traces: adds the table of both sides' means")
    parser.add_argument("--out", help="write the table here instead of stdout")
    args = parser.parse_args(argv)
    models = [(label, [read_rows(d) for d in dirs]) for label, dirs in args.model]
    table = ("Pooled difference to ns-3 (SwarmNet minus ns-3) over the runs of each model: mean ± "
             "sample sd [min, max].\n\n" + spread_table(args.swarmnet, models))
    if args.ns3:
        ns3_grids = [read_rows(d) for d in args.ns3.split(",") if d]
        table += ("\nSwarmNet's mean over each model's runs minus ns-3's mean over its run "
                  "numbers (delivery in points, the others relative to ns-3's mean), ± the "
                  "standard error of that difference; (beyond): past the row's target.\n\n"
                  + means_table(args.swarmnet, models, ns3_grids))
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(table)
    else:
        sys.stdout.write(table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
