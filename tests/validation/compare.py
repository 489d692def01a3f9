#!/usr/bin/env python3
"""Compares a SwarmNet run with its ns-3 replay (swarmnet_ns3_replay) and prints one row.

    python3 tests/validation/compare.py RUN_DIR NS3_JSON [--pdr-points 3] [--delay-pct 20]
        [--mac-pct 10] [--control-pct 20] [--min-speedup 10] [--format text]

RUN_DIR is a SwarmNet run directory (or its summary.json). Compared: delivery ratio (difference in
percentage points), mean delay (difference in % of ns-3's), 95th-percentile delay, MAC
transmissions (frames put on the air, ACKs and ARP frames included; difference in %), AODV
control packets per delivered packet, ARP (requests and replies sent, packets dropped; reported,
not judged) and the CPU seconds of both network halves with their ratio. The default tolerances
are issue 19's targets (delivery 3 points, mean delay 20%, MAC frames 10%, control packets per
delivery 20%); a tolerance of a negative value is not checked. Exits 1 if a compared value is
outside its tolerance, 2 on a usage or input error. Python standard library only.
"""
import argparse
import json
import math
import os
import sys

# Issue 19's targets (docs/validation.md). control_pct applies where both sides send control
# packets (AODV); min_speedup is judged by run_grid.py on rows of 100 nodes or more.
DEFAULTS = {"pdr_points": 3.0, "delay_pct": 20.0, "mac_pct": 10.0, "control_pct": 20.0,
            "min_speedup": None}


def load_json(path):
    if os.path.isdir(path):
        path = os.path.join(path, "summary.json")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _pct(a, b):
    """a relative to b, in % of b; None when undefined."""
    if a is None or b is None or b == 0:
        return None
    return 100.0 * (a - b) / b


def _per_delivered(doc):
    control = doc.get("routing", {}).get("control_packets")
    delivered = doc.get("packets", {}).get("delivered")
    if not control or not delivered:
        return None
    return control / delivered


def pool(docs):
    """One document of the fields compare() reads, aggregated over runs (seeds) of one case:
    counts and CPU seconds add up, the delivery ratio is the sum delivered / sum of unicast sent,
    mean delay and hops are means over all deliveries; a percentile cannot be pooled from
    summaries and is None."""
    def total(*keys):
        values = [_get(doc, keys) for doc in docs]
        return None if any(v is None for v in values) else sum(values)

    def per_delivery(*keys):
        pairs = [(_get(doc, keys), doc["packets"]["delivered"]) for doc in docs]
        pairs = [(v, n) for v, n in pairs if n > 0]
        if not pairs or any(v is None for v, _ in pairs):
            return None
        return sum(v * n for v, n in pairs) / sum(n for _, n in pairs)

    sent, broadcast = total("packets", "sent"), total("packets", "broadcast_sent") or 0
    delivered = total("packets", "delivered")
    return {
        "robots": docs[0].get("robots"),
        "sim_time_s": docs[0].get("sim_time_s"),
        "routing_plugin": docs[0].get("routing_plugin"),
        "packets": {"sent": sent, "broadcast_sent": broadcast, "delivered": delivered},
        "pdr": delivered / (sent - broadcast) if sent > broadcast else 0.0,
        "delay_s": {"mean": per_delivery("delay_s", "mean"), "p95": None},
        "hops_mean": per_delivery("hops_mean"),
        "mac": {"tx_frames": total("mac", "tx_frames")},
        "routing": {"control_packets": total("routing", "control_packets")},
        "arp": {key: total("arp", key) for key in ("requests_sent", "replies_sent")},
        "arp_packets_dropped": total_arp_drops(docs),
        "cpu_s": {"network": total("cpu_s", "network")},
    }


def arp_packets_dropped(doc):
    """Packets ARP dropped (pending queue full, neighbour unresolved or dead), from either side's
    JSON: SwarmNet's packets.dropped.arp_*, the replay's arp.packets_dropped; None if the document
    has no ARP figures (a summary from before ARP, or a pool of them)."""
    if "arp_packets_dropped" in doc:  # a pool
        return doc["arp_packets_dropped"]
    if isinstance(doc.get("arp"), dict) and "packets_dropped" in doc["arp"]:
        return doc["arp"]["packets_dropped"]
    dropped = doc.get("packets", {}).get("dropped")
    if isinstance(dropped, dict) and isinstance(doc.get("arp"), dict):
        return sum(v for k, v in dropped.items() if k.startswith("arp_"))
    return None


def total_arp_drops(docs):
    values = [arp_packets_dropped(doc) for doc in docs]
    return None if any(v is None for v in values) else sum(values)


def _get(doc, keys):
    for key in keys:
        doc = doc.get(key) if isinstance(doc, dict) else None
    return doc


def _checked(tolerance):
    return tolerance is not None and tolerance >= 0


def compare(swarmnet, ns3, pdr_points=DEFAULTS["pdr_points"], delay_pct=DEFAULTS["delay_pct"],
            min_speedup=None, control_pct=DEFAULTS["control_pct"], mac_pct=DEFAULTS["mac_pct"]):
    """Returns a dict with both sides' values, the differences and the failed checks. A tolerance
    of None (or negative) is not checked."""
    row = {
        "robots": swarmnet.get("robots"),
        "sim_time_s": swarmnet.get("sim_time_s"),
        "routing": ns3.get("routing_plugin"),
        "unicast_sent": swarmnet["packets"]["sent"] - swarmnet["packets"].get("broadcast_sent", 0),
        "pdr": [swarmnet["pdr"], ns3["pdr"]],
        "delay_mean_s": [swarmnet["delay_s"]["mean"], ns3["delay_s"]["mean"]],
        "delay_p95_s": [swarmnet["delay_s"]["p95"], ns3["delay_s"]["p95"]],
        "hops_mean": [swarmnet.get("hops_mean"), ns3.get("hops_mean")],
        "mac_tx_frames": [swarmnet["mac"]["tx_frames"], ns3["mac"]["tx_frames"]],
        "control_per_delivered": [_per_delivered(swarmnet), _per_delivered(ns3)],
        "arp_requests": [_get(swarmnet, ("arp", "requests_sent")),
                         _get(ns3, ("arp", "requests_sent"))],
        "arp_replies": [_get(swarmnet, ("arp", "replies_sent")),
                        _get(ns3, ("arp", "replies_sent"))],
        "arp_packets_dropped": [arp_packets_dropped(swarmnet), arp_packets_dropped(ns3)],
        "cpu_s": [swarmnet["cpu_s"]["network"], ns3["cpu_s"]["network"]],
    }
    row["pdr_diff_points"] = 100.0 * (row["pdr"][0] - row["pdr"][1])
    row["delay_mean_diff_pct"] = _pct(*row["delay_mean_s"])
    row["delay_p95_diff_pct"] = _pct(*row["delay_p95_s"])
    row["mac_tx_diff_pct"] = _pct(*row["mac_tx_frames"])
    row["control_diff_pct"] = _pct(*row["control_per_delivered"])
    cpu_sn, cpu_ns3 = row["cpu_s"]
    row["speedup"] = cpu_ns3 / cpu_sn if cpu_sn > 0 else math.inf

    row["tolerances"] = {"pdr_points": pdr_points, "delay_pct": delay_pct, "mac_pct": mac_pct,
                         "control_pct": control_pct, "min_speedup": min_speedup}
    failures = []
    if _checked(pdr_points) and abs(row["pdr_diff_points"]) > pdr_points:
        failures.append(f"delivery ratio differs by {row['pdr_diff_points']:+.2f} points "
                        f"(tolerance {pdr_points:g})")
    d = row["delay_mean_diff_pct"]
    if (row["delay_mean_s"][0] is None) != (row["delay_mean_s"][1] is None):
        failures.append("mean delay: one side delivered nothing")
    elif _checked(delay_pct) and d is not None and abs(d) > delay_pct:
        failures.append(f"mean delay differs by {d:+.1f}% (tolerance {delay_pct:g}%)")
    m = row["mac_tx_diff_pct"]
    if _checked(mac_pct) and m is not None and abs(m) > mac_pct:
        failures.append(f"MAC frames differ by {m:+.1f}% (tolerance {mac_pct:g}%)")
    if _checked(min_speedup) and row["speedup"] < min_speedup:
        failures.append(f"SwarmNet is {row['speedup']:.1f}x faster than ns-3 "
                        f"(needs {min_speedup:g}x)")
    c = row["control_diff_pct"]
    if _checked(control_pct) and c is not None and abs(c) > control_pct:
        failures.append(f"control packets per delivered packet differ by {c:+.1f}% "
                        f"(tolerance {control_pct:g}%)")
    row["failures"] = failures
    row["pass"] = not failures
    return row


def _ms(v):
    return "-" if v is None else f"{1000.0 * v:.2f}"


def _signed(v, unit=""):
    return "-" if v is None else f"{v:+.1f}{unit}"


def _ratio(v):
    return "-" if v is None else f"{v:.2f}"


HEADER = ("| N | routing | PDR SwarmNet | PDR ns-3 | diff (pts) | mean delay SwarmNet (ms) "
          "| mean delay ns-3 (ms) | diff | p95 SwarmNet (ms) | p95 ns-3 (ms) | MAC tx SwarmNet "
          "| MAC tx ns-3 | MAC diff | control/deliv. SwarmNet | control/deliv. ns-3 | diff "
          "| CPU SwarmNet (s) | CPU ns-3 (s) | speed-up | within targets |")
RULE = "|" + "---|" * HEADER.count(" |")


def markdown_cells(row):
    diff = f"{row['pdr_diff_points']:+.1f}"
    if "pdr_diff_points_range" in row:  # pooled over seeds: the per-seed range too
        diff += " ({:+.1f} to {:+.1f}".format(*row["pdr_diff_points_range"])
        if "pdr_diff_points_interval" in row:  # grids from before it have no interval
            diff += "; 95% CI {:+.1f} to {:+.1f}".format(*row["pdr_diff_points_interval"])
        diff += ")"
    return [
        f"{row['pdr'][0]:.3f}", f"{row['pdr'][1]:.3f}", diff,
        _ms(row["delay_mean_s"][0]), _ms(row["delay_mean_s"][1]),
        _signed(row["delay_mean_diff_pct"], "%"),
        _ms(row["delay_p95_s"][0]), _ms(row["delay_p95_s"][1]),
        str(row["mac_tx_frames"][0]), str(row["mac_tx_frames"][1]),
        _signed(row.get("mac_tx_diff_pct"), "%"),
        _ratio(row["control_per_delivered"][0]), _ratio(row["control_per_delivered"][1]),
        _signed(row.get("control_diff_pct"), "%"),
        f"{row['cpu_s'][0]:.3g}", f"{row['cpu_s'][1]:.3g}", f"{row['speedup']:.1f}x",
        "yes" if row["pass"] else "no: " + "; ".join(row["failures"]),
    ]


def text_report(row):
    lines = [
        f"robots {row['robots']}, {row['sim_time_s']} s, {row['unicast_sent']} unicast messages",
        f"  delivery ratio   SwarmNet {row['pdr'][0]:.4f}  ns-3 {row['pdr'][1]:.4f}  "
        f"diff {row['pdr_diff_points']:+.2f} points",
        f"  mean delay       SwarmNet {_ms(row['delay_mean_s'][0])} ms  "
        f"ns-3 {_ms(row['delay_mean_s'][1])} ms  diff {_signed(row['delay_mean_diff_pct'], '%')}",
        f"  p95 delay        SwarmNet {_ms(row['delay_p95_s'][0])} ms  "
        f"ns-3 {_ms(row['delay_p95_s'][1])} ms  diff {_signed(row['delay_p95_diff_pct'], '%')}",
        f"  MAC tx frames    SwarmNet {row['mac_tx_frames'][0]}  ns-3 {row['mac_tx_frames'][1]}  "
        f"diff {_signed(row['mac_tx_diff_pct'], '%')}",
    ]
    if "pdr_diff_points_range" in row:
        lines[0] = f"seeds {','.join(map(str, row['seeds']))} pooled: " + lines[0]
        lines.insert(2, "  per seed         delivery diff {:+.2f} to {:+.2f} points".format(
            *row["pdr_diff_points_range"]))
        if "pdr_diff_points_interval" in row:
            lines.insert(3, "  mean per seed    95% Student-t interval {:+.2f} to {:+.2f} points"
                         .format(*row["pdr_diff_points_interval"]))
    if any(v is not None for v in row["control_per_delivered"]):
        a, b = row["control_per_delivered"]
        lines.append(f"  control/deliv.   SwarmNet {a if a is None else round(a, 3)}  "
                     f"ns-3 {b if b is None else round(b, 3)}  "
                     f"diff {_signed(row['control_diff_pct'], '%')}")
    if any(v for v in row.get("arp_requests", []) + row.get("arp_packets_dropped", [])):
        lines.append(f"  ARP              requests SwarmNet {_count(row['arp_requests'][0])}  "
                     f"ns-3 {_count(row['arp_requests'][1])}; replies SwarmNet "
                     f"{_count(row['arp_replies'][0])}  ns-3 {_count(row['arp_replies'][1])}; "
                     f"packets dropped SwarmNet {_count(row['arp_packets_dropped'][0])}  "
                     f"ns-3 {_count(row['arp_packets_dropped'][1])}")
    lines.append(f"  CPU (network)    SwarmNet {row['cpu_s'][0]:.3f} s  ns-3 {row['cpu_s'][1]:.3f} s"
                 f"  SwarmNet {row['speedup']:.1f}x faster")
    lines.append("  within tolerances" if row["pass"] else
                 "  OUTSIDE TOLERANCES: " + "; ".join(row["failures"]))
    return "\n".join(lines)


def _count(v):
    return "-" if v is None else str(v)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("swarmnet", help="SwarmNet run directory or its summary.json")
    parser.add_argument("ns3", help="JSON written by swarmnet_ns3_replay")
    parser.add_argument("--pdr-points", type=float, default=DEFAULTS["pdr_points"],
                        help="largest delivery-ratio difference, percentage points (default 3)")
    parser.add_argument("--delay-pct", type=float, default=DEFAULTS["delay_pct"],
                        help="largest mean-delay difference, %% of ns-3's (default 20)")
    parser.add_argument("--mac-pct", type=float, default=DEFAULTS["mac_pct"],
                        help="largest difference of MAC frames put on the air, %% of ns-3's "
                             "(default 10; -1: reported, not checked, as the aligned setup "
                             "was judged)")
    parser.add_argument("--min-speedup", type=float, default=None,
                        help="smallest ns-3 / SwarmNet network CPU ratio (default: not checked)")
    parser.add_argument("--control-pct", type=float, default=DEFAULTS["control_pct"],
                        help="largest difference of control packets per delivered packet, %% "
                             "(default 20; checked where both sides send control packets)")
    parser.add_argument("--format", choices=["text", "markdown", "json"], default="text")
    args = parser.parse_args(argv)
    try:
        swarmnet, ns3 = load_json(args.swarmnet), load_json(args.ns3)
        row = compare(swarmnet, ns3, args.pdr_points, args.delay_pct, args.min_speedup,
                      args.control_pct, args.mac_pct)
    except (OSError, ValueError, KeyError, TypeError) as error:
        print(f"compare.py: {error}", file=sys.stderr)
        return 2
    if args.format == "json":
        print(json.dumps(row, indent=2))
    elif args.format == "markdown":
        print(HEADER)
        print(RULE)
        print("| " + " | ".join([str(row["robots"]), str(row["routing"])] + markdown_cells(row))
              + " |")
    else:
        print(text_report(row))
    return 0 if row["pass"] else 1


if __name__ == "__main__":
    sys.exit(main())
