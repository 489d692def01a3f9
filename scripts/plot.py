#!/usr/bin/env python3
"""Plot a SwarmNet sweep's results.csv: one line per group, the mean of a metric over seeds with
95% confidence intervals (Student t) as error bars.

    swarmnet plot runs/sweeps/NAME/results.csv --x robots.count --y pdr \
        --by network.routing --out fig.png

`swarmnet plot` runs this script with a python3 that has matplotlib (Debian's python3 and
python3-matplotlib, which ./swarmnet installs, first). Rows whose
status is not "ok" or whose --y cell is empty are left out. See docs/experiments.md.
"""
import argparse
import csv
import math
import sys
from collections import OrderedDict

# Two-sided 95% Student t quantiles (t_0.975) for 1..30 degrees of freedom.
T975 = [12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622, 2.2281,
        2.2010, 2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860,
        2.0796, 2.0739, 2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423]


def t975(df):
    """t_0.975 for df degrees of freedom: the table, then a Cornish-Fisher expansion (to 1e-4)."""
    if df <= len(T975):
        return T975[df - 1]
    z = 1.959964
    return (z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df ** 2)
            + (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / (384 * df ** 3))


def mean_ci(values):
    n = len(values)
    mean = sum(values) / n
    if n < 2:
        return mean, 0.0
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    return mean, t975(n - 1) * sd / math.sqrt(n)


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", help="results.csv written by swarmnet sweep")
    parser.add_argument("--x", required=True, help="column on the x axis (numbers or labels)")
    parser.add_argument("--y", required=True, help="metric column on the y axis")
    parser.add_argument("--by", default="", help="columns that split the lines, comma-separated")
    parser.add_argument("--out", required=True, help="image file (PNG, or any matplotlib format)")
    parser.add_argument("--title", default="")
    parser.add_argument("--xlabel", default=None)
    parser.add_argument("--ylabel", default=None)
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    args = parser.parse_args(argv)

    with open(args.results, newline="") as f:
        rows = list(csv.DictReader(f))
    by = [c for c in args.by.split(",") if c]
    header = rows[0].keys() if rows else []
    for column in [args.x, args.y] + by:
        if column not in header:
            sys.exit(f"plot.py: {args.results}: no column '{column}'")

    groups = OrderedDict()  # label -> {x: [y...]}
    for row in rows:
        if row.get("status", "ok") != "ok" or row[args.y] == "":
            continue
        y = number(row[args.y])
        if y is None:
            sys.exit(f"plot.py: {args.results}: '{row[args.y]}' in column {args.y} is not a number")
        label = ", ".join(f"{c}={row[c]}" for c in by) if by else args.y
        groups.setdefault(label, OrderedDict()).setdefault(row[args.x], []).append(y)
    if not groups:
        sys.exit(f"plot.py: {args.results}: no rows with a value of {args.y}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    numeric_x = all(number(x) is not None for g in groups.values() for x in g)
    categories = list(OrderedDict.fromkeys(x for g in groups.values() for x in g))
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for label, points in groups.items():
        xs = sorted(points, key=number) if numeric_x else list(points)
        stats = [mean_ci(points[x]) for x in xs]
        positions = [number(x) for x in xs] if numeric_x else [categories.index(x) for x in xs]
        ax.errorbar(positions, [m for m, _ in stats], yerr=[h for _, h in stats], marker="o",
                    capsize=3, label=label)
    if not numeric_x:
        ax.set_xticks(range(len(categories)))
        ax.set_xticklabels(categories)
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or args.y)
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, alpha=0.3)
    if by:
        ax.legend()
    ax.text(0.99, 0.01, "error bars: 95% CI over seeds", transform=ax.transAxes, ha="right",
            va="bottom", fontsize=7, alpha=0.6)
    fig.tight_layout()
    fig.savefig(args.out, dpi=150)
    print(f"plot.py: wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
