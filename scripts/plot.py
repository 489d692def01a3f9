#!/usr/bin/env python3
"""Plot SwarmNet results: a sweep's results.csv, or one run's series.csv or robot_metrics.csv.

    swarmnet plot runs/sweeps/NAME/results.csv --x robots.count --y pdr \
        --by network.routing --out fig.png
    swarmnet plot runs/NAME/series.csv --y route_known --out fig.png [--robots mean|all|0,3]
    swarmnet plot runs/NAME/robot_metrics.csv --y decisions [--stat mean] --out fig.png

results.csv: one line per --by group, the mean of a metric over seeds with 95% confidence
intervals (Student t) as error bars; rows whose status is not "ok" or whose --y cell is empty are
left out. series.csv (what controllers and worlds sample()): the series --y against simulated
time; by default the mean over the robots that sampled it at each time, with a 95% band, and a
world's own series as a line of its own; --robots all draws every robot, --robots 0,3 those
robots. robot_metrics.csv (what controllers record(), per robot): one bar per robot of --stat
(count, sum, mean, min or max) of the metric --y, with the mean over robots as a line.

`swarmnet plot` runs this script with a python3 that has matplotlib (Debian's python3 and
python3-matplotlib, which ./swarmnet installs, first). The file's kind is told by its header.
See docs/experiments.md.
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


SERIES_HEADER = ["time_ns", "robot", "series", "value"]
ROBOT_METRICS_HEADER = ["robot", "metric", "count", "sum", "mean", "min", "max"]
STATS = ["count", "sum", "mean", "min", "max"]


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", help="results.csv, series.csv or robot_metrics.csv")
    parser.add_argument("--x", default=None,
                        help="results.csv: column on the x axis (numbers or labels)")
    parser.add_argument("--y", required=True,
                        help="results.csv: metric column; series.csv: series name; "
                             "robot_metrics.csv: metric name")
    parser.add_argument("--by", default="",
                        help="results.csv: columns that split the lines, comma-separated")
    parser.add_argument("--robots", default="mean",
                        help="series.csv: mean (default), all, or robot ids, comma-separated")
    parser.add_argument("--stat", default="mean", choices=STATS,
                        help="robot_metrics.csv: which per-robot value (default mean)")
    parser.add_argument("--out", required=True, help="image file (PNG, or any matplotlib format)")
    parser.add_argument("--title", default="")
    parser.add_argument("--xlabel", default=None)
    parser.add_argument("--ylabel", default=None)
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    return parser.parse_args(argv)


def read_rows(path):
    try:
        with open(path, newline="") as f:
            reader = csv.reader(f)
            header = next(reader, [])
            return header, list(reader)
    except OSError as error:
        sys.exit(f"plot.py: {path}: {error.strerror}")


def sweep_lines(args, header, rows):
    """{label: {x: [y over seeds]}} from a sweep's results.csv."""
    if args.x is None:
        sys.exit(f"plot.py: {args.results}: a results file needs --x (a column)")
    by = [c for c in args.by.split(",") if c]
    for column in [args.x, args.y] + by:
        if column not in header:
            sys.exit(f"plot.py: {args.results}: no column '{column}'")
    groups = OrderedDict()
    for cells in rows:
        row = dict(zip(header, cells))
        if row.get("status", "ok") != "ok" or row.get(args.y, "") == "":
            continue
        y = number(row[args.y])
        if y is None:
            sys.exit(f"plot.py: {args.results}: '{row[args.y]}' in column {args.y} is not a number")
        label = ", ".join(f"{c}={row[c]}" for c in by) if by else args.y
        groups.setdefault(label, OrderedDict()).setdefault(row[args.x], []).append(y)
    if not groups:
        sys.exit(f"plot.py: {args.results}: no rows with a value of {args.y}")
    return groups, bool(by), "error bars: 95% CI over seeds"


def series_lines(args, rows):
    """{label: {time_s: [values]}} from a run's series.csv, as --robots asks."""
    wanted = None
    if args.robots not in ("mean", "all"):
        try:
            wanted = {int(r) for r in args.robots.split(",") if r}
        except ValueError:
            sys.exit(f"plot.py: --robots {args.robots}: give mean, all, or robot ids like 0,3")
    groups = OrderedDict()
    names = set()
    for number_in_file, cells in enumerate(rows, start=2):
        if len(cells) != 4:
            sys.exit(f"plot.py: {args.results}:{number_in_file}: expected 4 fields, "
                     f"found {len(cells)}")
        time_ns, robot, name, value = cells
        names.add(name)
        if name != args.y:
            continue
        t = int(time_ns) / 1e9
        if robot == "":
            label = "world"
        elif args.robots == "mean":
            label = f"mean over robots ({args.y})"
        elif wanted is None or int(robot) in wanted:
            label = f"robot {robot}"
        else:
            continue
        groups.setdefault(label, OrderedDict()).setdefault(t, []).append(float(value))
    if not groups:
        known = ", ".join(sorted(names)) or "none"
        sys.exit(f"plot.py: {args.results}: no samples of series '{args.y}' "
                 f"for --robots {args.robots} (series in the file: {known})")
    band = "band: 95% CI over robots" if args.robots == "mean" else ""
    return groups, len(groups) > 1, band


def robot_metric_bars(args, rows):
    """[(robot, value)] of --stat of metric --y, from a run's robot_metrics.csv."""
    column = ROBOT_METRICS_HEADER.index(args.stat)
    bars = []
    names = set()
    for cells in rows:
        if len(cells) != len(ROBOT_METRICS_HEADER):
            sys.exit(f"plot.py: {args.results}: a row has {len(cells)} fields, "
                     f"expected {len(ROBOT_METRICS_HEADER)}")
        names.add(cells[1])
        if cells[1] == args.y:
            bars.append((int(cells[0]), float(cells[column])))
    if not bars:
        known = ", ".join(sorted(names)) or "none"
        sys.exit(f"plot.py: {args.results}: no robot recorded metric '{args.y}' "
                 f"(metrics in the file: {known})")
    return bars


def main(argv=None):
    args = parse_args(argv)
    header, rows = read_rows(args.results)

    if header == ROBOT_METRICS_HEADER:
        bars = robot_metric_bars(args, rows)
        plt = pyplot()
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        ax.bar([r for r, _ in bars], [v for _, v in bars], color="#4c72b0")
        mean = sum(v for _, v in bars) / len(bars)
        ax.axhline(mean, color="#dd8452", label=f"mean over {len(bars)} robots: {mean:.4g}")
        ax.legend()
        finish(plt, fig, ax, args, "robot", f"{args.y} ({args.stat} per robot)", "")
        return 0

    if header == SERIES_HEADER:
        groups, legend, note = series_lines(args, rows)
        xlabel = "simulated time (s)"
    else:
        groups, legend, note = sweep_lines(args, header, rows)
        xlabel = args.x
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    numeric_x = all(isinstance(x, float) or number(x) is not None
                    for g in groups.values() for x in g)
    categories = list(OrderedDict.fromkeys(x for g in groups.values() for x in g))
    for label, points in groups.items():
        xs = sorted(points, key=float) if numeric_x else list(points)
        stats = [mean_ci(points[x]) for x in xs]
        positions = [float(x) for x in xs] if numeric_x else [categories.index(x) for x in xs]
        means = [m for m, _ in stats]
        if header == SERIES_HEADER:
            line, = ax.plot(positions, means, label=label, linewidth=1.2)
            if any(h > 0 for _, h in stats):
                ax.fill_between(positions, [m - h for m, h in stats], [m + h for m, h in stats],
                                color=line.get_color(), alpha=0.2, linewidth=0)
        else:
            ax.errorbar(positions, means, yerr=[h for _, h in stats], marker="o", capsize=3,
                        label=label)
    if not numeric_x:
        ax.set_xticks(range(len(categories)))
        ax.set_xticklabels(categories)
    if legend:
        ax.legend()
    finish(plt, fig, ax, args, xlabel, args.y, note)
    return 0


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def finish(plt, fig, ax, args, xlabel, ylabel, note):
    ax.set_xlabel(args.xlabel or xlabel)
    ax.set_ylabel(args.ylabel or ylabel)
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, alpha=0.3)
    if note:
        ax.text(0.99, 0.01, note, transform=ax.transAxes, ha="right", va="bottom", fontsize=7,
                alpha=0.6)
    fig.tight_layout()
    fig.savefig(args.out, dpi=150)
    plt.close(fig)
    print(f"plot.py: wrote {args.out}")

if __name__ == "__main__":
    sys.exit(main())
