#!/usr/bin/env python3
"""Where the messages of a grid row are lost, on each side, per run: SwarmNet's packet traces
against ns-3's IP traces of the same traces (issue 19's 150-robot row).

  --swarmnet RUN_DIR ...   SwarmNet run directories written with output.packet_trace=true
  --ns3 JSON:IP_TRACE ...  the replay's JSON (-o) and its --ip-trace of one run, joined by ':'

For every run it counts the messages (control packets are left out) delivered and dropped, by
reason and by where: at their source or at a relay. SwarmNet's reasons are its packets.csv's
(`arp_queue_full`, `arp_unresolved`, `no_route`, `retry_limit`, ...); ns-3's are the IP trace's
ARP drops (`arp_drop`: queue_full, dead_entry, retries_exhausted, queue_full_or_dead_entry) and
IP drops (`drop`: no_route, ttl_expired, route_error), named so that the two sides line up:
ns-3's dead_entry and retries_exhausted are SwarmNet's arp_unresolved, queue_full is
arp_queue_full, and an IP drop keeps its name. What neither trace records (ns-3: the MAC's retry
limit and queues, AODV's own queue) is the rest: sent - delivered - every drop counted.
A message is counted once, at its first drop, and SwarmNet's not at all if a copy of it was
delivered (a copy retransmitted by the MAC can be delivered and dropped); ns-3's IP trace does
not say which were delivered. A source is the message's source in traffic.csv, read from the
SwarmNet run directory the replay names in its JSON (run_dir).

Writes the mean per run of every count on each side as JSON (stdout or --out) and prints a table.
Python standard library only."""
import argparse
import collections
import csv
import json
import os
import sys

# SwarmNet's drop reason for each of ns-3's ARP drop reasons (the replay's --ip-trace); the
# unplaced one has no SwarmNet counterpart. arp_agreement.py checks message by message with it.
NS3_ARP_AS = {"queue_full": "arp_queue_full", "dead_entry": "arp_unresolved",
              "retries_exhausted": "arp_unresolved",
              "queue_full_or_dead_entry": "arp_queue_full_or_unresolved"}


def read_csv(path):
    try:
        with open(path, encoding="utf-8", newline="") as f:
            return list(csv.DictReader(f))
    except OSError as error:
        raise SystemExit(f"loss_by_reason: cannot read {path}: {error.strerror}") from error


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        raise SystemExit(f"loss_by_reason: cannot read {path}: {error}") from error


def count_first_drop(counts, dropped, message, reason, node, source):
    """Counts `message` under reason@source or reason@relay unless it was counted before."""
    if message in dropped:
        return
    dropped.add(message)
    counts[f"{reason}@{'source' if node == source else 'relay'}"] += 1


def swarmnet_run(run_dir):
    """One SwarmNet run's counts: sent, delivered and data drops by reason@where."""
    summary = read_json(os.path.join(run_dir, "summary.json"))
    packets = os.path.join(run_dir, "packets.csv")
    if not os.path.exists(packets):
        raise SystemExit(f"loss_by_reason: {packets} missing: run with "
                         "--set output.packet_trace=true")
    counts = collections.Counter(sent=summary["packets"]["sent"],
                                 delivered=summary["packets"]["delivered"])
    rows = [row for row in read_csv(packets) if row["message_id"] not in ("", "-1")]
    delivered = {row["message_id"] for row in rows if row["event"] == "deliver"}
    dropped = set()
    for row in rows:
        if row["event"] == "drop" and row["message_id"] not in delivered:
            count_first_drop(counts, dropped, row["message_id"], row["detail"], row["node"],
                             row["source"])
    return counts


def ns3_run(spec):
    """One ns-3 run's counts, from 'JSON:IP_TRACE'."""
    json_path, sep, trace_path = spec.rpartition(":")
    if not sep or not json_path:
        raise SystemExit(f"loss_by_reason: --ns3 {spec}: expected JSON:IP_TRACE")
    replay = read_json(json_path)
    traffic = os.path.join(replay["run_dir"], "traffic.csv")
    source_of = {row["message_id"]: row["source"] for row in read_csv(traffic)}
    counts = collections.Counter(sent=replay["packets"]["sent"],
                                 delivered=replay["packets"]["delivered"])
    dropped = set()
    for row in read_csv(trace_path):
        if row["event"] == "arp_drop":
            reason = NS3_ARP_AS.get(row["detail"], "arp_" + row["detail"])
        elif row["event"] == "drop":
            reason = row["detail"]
        else:
            continue
        source = source_of.get(row["message_id"])
        if source is None:
            raise SystemExit(f"loss_by_reason: {trace_path}: message {row['message_id']} is not "
                             f"in {traffic}")
        count_first_drop(counts, dropped, row["message_id"], reason, row["node"], source)
    return counts


def mean_per_run(runs):
    total = collections.Counter()
    for counts in runs:
        total.update(counts)
    means = {key: value / len(runs) for key, value in sorted(total.items())}
    drops = sum(value for key, value in means.items() if "@" in key)
    means["rest"] = means["sent"] - means["delivered"] - drops
    return means


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--swarmnet", nargs="+", required=True, metavar="RUN_DIR")
    parser.add_argument("--ns3", nargs="+", required=True, metavar="JSON:IP_TRACE")
    parser.add_argument("--out", help="write the JSON here instead of stdout")
    args = parser.parse_args()
    result = {"swarmnet": mean_per_run([swarmnet_run(d) for d in args.swarmnet]),
              "ns3": mean_per_run([ns3_run(s) for s in args.ns3]),
              "runs": {"swarmnet": len(args.swarmnet), "ns3": len(args.ns3)}}
    keys = sorted(set(result["swarmnet"]) | set(result["ns3"]),
                  key=lambda k: (k not in ("sent", "delivered"), k == "rest", k))
    print(f"{'per run':40s} {'SwarmNet':>10s} {'ns-3':>10s} {'difference':>11s}", file=sys.stderr)
    for key in keys:
        a, b = result["swarmnet"].get(key, 0.0), result["ns3"].get(key, 0.0)
        print(f"{key:40s} {a:10.1f} {b:10.1f} {a - b:+11.1f}", file=sys.stderr)
    text = json.dumps(result, indent=1, sort_keys=True)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text + "\n")
    else:
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
