#!/usr/bin/env python3
"""Frame by frame, how each side's unicast frames fare: SwarmNet's frame trace against the ns-3
replay's, over the same traces (docs/validation.md, "AODV: the saturated 150-robot row", issue
19's 150-robot row; the analyses made with it: docs/history/validation-journal.md, "The 150-robot
row frame by frame" and "The 150-robot row's lost attempts: whose frame, and when").

  --pair RUN_DIR:NS3_FRAMES ...   a SwarmNet run directory written with output.frame_trace=true
                                  (its frames.csv and mobility.ns2) and the replay's --frame-trace
                                  of the same run, joined by ':' (run_grid.py --frame-traces
                                  writes both: SEED_DIR/swarmnet and SEED_DIR/ns3-frames.csv)
  --seed-dirs DIR ...             the same, given as run_grid.py's seed directories

Both traces have the columns time_ns,node,kind,retry,receiver,bytes,sequence,message_id. For every
unicast data frame (an IP packet or an ARP reply to one receiver) it decides whether the receiver
acknowledged it: an ACK from the receiver to the transmitter starting SIFS after the frame's end
(802.11a OFDM airtime at --rate-mbps; within --ack-slack-us either way, for the propagation
delay). A frame's distance is the one between transmitter and receiver when it starts, from the
run's mobility.ns2 (ns-2 setdest semantics, which both sides follow).

A lost attempt between nodes within the nominal range (--range-m) is put down to what else the
trace shows on the air during it, the first that applies: the receiver itself transmitting; a
frame from within range of the receiver that started before it (the receiver may have been
locked on that one: no capture); one that started during it (a collision); only frames from
farther away (interference alone); nothing at all. For the receiver's own frame, and otherwise
the first to start of the frames near the receiver, it also tells whom (the receiver's ACK or
another frame of the receiver; a node in range of the sender, which the sender could sense, or
one hidden from it) and when that frame started against the attempt: more than 4 us before,
within 4 us (two stations that sense each other chose the same slot), or more than 4 us after.
Between stations in range of each other, before or after means that one of them transmitted
into a frame it could sense.

An MPDU is a node's first transmission of a frame (Retry bit clear) with the retransmissions that
follow it (Retry bit set, same receiver and sequence number): one in flight per node, as in
802.11's DCF. Its fate: acknowledged at its first attempt, at a later one, or never (given up at
the retry limit, --retry-limit attempts; or fewer, when it expired in the queue or the run ended).
One given up at the limit is put down to its receiver being beyond range at its first attempt,
or else to what lost most of its attempts (the groups above, only far frames, nothing; the first
on a tie): the persistent losses that a MAC reports to routing as broken links. Those whose
receiver was beyond range are also counted by payload (messages, control packets, ARP): a
source that keeps sending messages to a next hop that has moved away holds a route that its
routing protocol does not see break.

--from-s and --to-s keep only the frames that start in that window of simulated time (ACKs a
little beyond its end too, so that its last frames can be acknowledged; an MPDU whose first
attempt lies before the window is counted as begun_before_trace, with no fate), to compare the
two sides before
their runs part ways.

Prints, per side and pooled over the pairs: frames by kind, and first transmissions by what
they carry (broadcast or unicast, a message or a control packet, and the frame's size, which
tells a routing protocol's messages apart: with AODV over ns-3's default stack a RREQ is an 88 B
broadcast, a HELLO an 84 B one, a RREP an 84 B unicast); the share of unicast attempts
acknowledged, first attempts and retransmissions apart, and per distance band; the MPDUs' fates;
and writes the same as JSON (--out). Python standard library only."""
import argparse
import bisect
import collections
import csv
import json
import math
import os
import re
import sys

SIFS_US = 16.0
DISTANCE_BANDS_M = (20, 40, 60, 80, 90, 100, 110, 120)  # upper edges; the last band is beyond
RANGE_M = 120.0  # the grid's nominal range: received power at the -82 dBm detection threshold
# What else was on the air when an attempt within range was lost, most telling first.
LOSS_CAUSES = ("receiver_transmitting", "earlier_frame_near_receiver",
               "later_frame_near_receiver", "only_far_frames", "nothing_else_on_air")
# When the frame behind a loss (the receiver's own, or the first to start of those near the
# receiver) started, against the lost attempt: two stations that sense each other and start
# within 4 us (ns-3's preamble-detection window) chose the same slot; one that starts later than
# that transmitted into a frame it could sense.
SAME_SLOT_US = 4.0
OVERLAP_STARTS = ("before", "within_4_us", "after")

SETDEST = re.compile(r'\$ns_ at ([0-9.eE+-]+) "\$node_\((\d+)\) setdest ([0-9.eE+-]+) '
                     r'([0-9.eE+-]+) ([0-9.eE+-]+)"')
INITIAL = re.compile(r'\$node_\((\d+)\) set ([XY])_ ([0-9.eE+-]+)')


class Mobility:
    """Positions from an ns-2 mobility trace: initial X_/Y_, then straight moves at a speed."""

    def __init__(self, path):
        initial = collections.defaultdict(lambda: [0.0, 0.0])
        moves = collections.defaultdict(list)
        try:
            f = open(path, encoding="utf-8")
        except OSError as error:
            sys.exit(f"frame_agreement.py: cannot read {path}: {error.strerror}")
        with f:
            for line in f:
                move = SETDEST.search(line)
                if move:
                    t, node, x, y, speed = move.groups()
                    moves[int(node)].append((float(t), float(x), float(y), float(speed)))
                    continue
                start = INITIAL.search(line)
                if start:
                    node, axis, value = start.groups()
                    initial[int(node)][0 if axis == "X" else 1] = float(value)
        # Per node: segment start times, and (t0, x0, y0, t1, x1, y1) for each.
        self.starts = {}
        self.segments = {}
        for node in set(initial) | set(moves):
            x, y = initial[node]
            segments = [(0.0, x, y, 0.0, x, y)]
            for t, tx, ty, speed in sorted(moves[node]):
                x, y = self._along(segments[-1], t)  # where the node is when the move starts
                length = math.hypot(tx - x, ty - y)
                arrive = t + (length / speed if speed > 0 else 0.0)
                segments.append((t, x, y, arrive, tx, ty))
            self.segments[node] = segments
            self.starts[node] = [s[0] for s in segments]

    @staticmethod
    def _along(segment, t):
        t0, x0, y0, t1, x1, y1 = segment
        if t >= t1 or t1 <= t0:
            return x1, y1
        f = (t - t0) / (t1 - t0)
        return x0 + f * (x1 - x0), y0 + f * (y1 - y0)

    def position(self, node, t):
        segments = self.segments.get(node)
        if segments is None:
            raise KeyError(f"node {node} is not in the mobility trace")
        i = bisect.bisect_right(self.starts[node], t) - 1
        return self._along(segments[max(i, 0)], t)

    def distance(self, a, b, t):
        (xa, ya), (xb, yb) = self.position(a, t), self.position(b, t)
        return math.hypot(xa - xb, ya - yb)


def airtime_us(frame_bytes, rate_mbps):
    """802.11a OFDM (20 MHz): 16 us preamble, 4 us SIGNAL, 4 us symbols of rate*4 data bits."""
    bits_per_symbol = rate_mbps * 4.0
    return 20.0 + 4.0 * math.ceil((16 + 8 * frame_bytes + 6) / bits_per_symbol)


def read_frames(path):
    try:
        with open(path, encoding="utf-8", newline="") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            expected = ["time_ns", "node", "kind", "retry", "receiver", "bytes", "sequence",
                        "message_id"]
            if header != expected:
                sys.exit(f"frame_agreement.py: {path}: header {header}, expected {expected}")
            frames = []
            for number, row in enumerate(reader, start=2):
                if len(row) != 8:
                    sys.exit(f"frame_agreement.py: {path}:{number}: {len(row)} fields, expected 8")
                try:
                    frames.append((int(row[0]), int(row[1]), row[2], row[3] == "1", int(row[4]),
                                   int(row[5]), int(row[6]), int(row[7])))
                except ValueError as error:
                    sys.exit(f"frame_agreement.py: {path}:{number}: {error}")
            return frames
    except OSError as error:
        sys.exit(f"frame_agreement.py: cannot read {path}: {error.strerror}")


def band_of(distance_m):
    for edge in DISTANCE_BANDS_M:
        if distance_m < edge:
            return f"<{edge} m"
    return f">={DISTANCE_BANDS_M[-1]} m"


def frame_class(frame):
    """What a frame carries, to tell a routing protocol's messages apart by their size: "ack",
    "arp request", "arp reply", or "broadcast|unicast message|control N B" for a data frame."""
    kind, receiver, frame_bytes, message = frame[2], frame[4], frame[5], frame[7]
    if kind == "arp":
        return "arp request" if receiver < 0 else "arp reply"
    if kind != "data":
        return kind
    return (f"{'broadcast' if receiver < 0 else 'unicast'} "
            f"{'message' if message >= 0 else 'control'} {frame_bytes} B")


def overlap_start(other_start_ns, start_ns):
    """OVERLAP_STARTS: when a frame started, against an attempt that started at start_ns."""
    offset_us = (other_start_ns - start_ns) / 1000.0
    if offset_us < -SAME_SLOT_US:
        return OVERLAP_STARTS[0]
    return OVERLAP_STARTS[1] if offset_us <= SAME_SLOT_US else OVERLAP_STARTS[2]


def analyse(frames, mobility, rate_mbps, slack_us, retry_limit, range_m=RANGE_M):
    """Counts for one trace (see the module's docstring)."""
    kinds = collections.Counter(frame[2] for frame in frames)
    classes = collections.Counter(frame_class(frame) for frame in frames if not frame[3])
    frames = sorted(frames, key=lambda f: f[0])  # by start: both traces are, stably
    starts = [f[0] for f in frames]
    ends = [f[0] + airtime_us(f[5], rate_mbps) * 1000.0 for f in frames]
    longest_ns = max((e - t for e, t in zip(ends, starts)), default=0.0)

    def loss_cause(i, receiver):
        """What else was on the air during frame i (LOSS_CAUSES), and for a frame from the
        receiver or near it, which group of loss_overlaps it counts in and when it started."""
        t, end = starts[i], ends[i]
        sender = frames[i][1]
        j = bisect.bisect_left(starts, t - longest_ns)
        causes = set()
        first_near = None
        while j < len(frames) and starts[j] < end:
            other = frames[j]
            if j != i and ends[j] > t and other[1] != sender:
                if other[1] == receiver:
                    group = "receiver_ack" if other[2] == "ack" else "receiver_other"
                    return LOSS_CAUSES[0], (group, overlap_start(starts[j], t))
                near = mobility.distance(other[1], receiver, t / 1e9) < range_m
                if near:
                    causes.add(1 if starts[j] <= t else 2)
                    if first_near is None:  # frames are by start: the first is the earliest
                        first_near = j
                else:
                    causes.add(3)
            j += 1
        if not causes:
            return LOSS_CAUSES[4], None
        if first_near is None:
            return LOSS_CAUSES[3], None
        sensed = mobility.distance(frames[first_near][1], sender, t / 1e9) < range_m
        return LOSS_CAUSES[min(causes)], ("near_sensed_by_sender" if sensed else
                                          "near_hidden_from_sender",
                                          overlap_start(starts[first_near], t))

    acks = collections.defaultdict(list)  # (from, to) -> ACK start times, ns
    for t, node, kind, _, receiver, *_ in frames:
        if kind == "ack":
            acks[(node, receiver)].append(t)
    for times in acks.values():
        times.sort()

    def acknowledged(t, node, receiver, frame_bytes):
        due = t + (airtime_us(frame_bytes, rate_mbps) + SIFS_US) * 1000.0
        times = acks.get((receiver, node), ())
        i = bisect.bisect_left(times, due - slack_us * 1000.0)
        return i < len(times) and times[i] <= due + slack_us * 1000.0

    attempts = collections.Counter()  # (first|retry, acked) -> count
    bands = collections.defaultdict(collections.Counter)  # band -> {attempts, acked, first, ...}
    # node -> the MPDU in flight: [receiver, sequence, attempts, acked_at (0: not), payload, whole,
    # its receiver beyond range at the first attempt, its lost attempts by what lost them]
    mpdus = {}
    fates = collections.Counter()
    given_up_by_payload = collections.Counter()  # messages, control packets or ARP, at the limit
    given_up_by_attempts = collections.Counter()
    given_up_by_loss = collections.Counter()
    given_up_beyond_range = collections.Counter()  # by payload: a next hop that had moved away
    lost = collections.defaultdict(collections.Counter)  # band -> cause -> lost attempts
    # group -> start -> attempts within range under such a frame, and those of them lost
    overlapped = collections.defaultdict(collections.Counter)
    overlaps = collections.defaultdict(collections.Counter)

    def close(mpdu):
        if mpdu is None:
            return
        _, _, count, acked_at, payload, whole, beyond_range, losses = mpdu
        if not whole:
            fates["begun_before_trace"] += 1  # its first attempt is not in the trace: no fate
            return
        if acked_at:
            fates["acked_first" if acked_at == 1 else "acked_later"] += 1
            if count > acked_at:
                fates["sent_again_after_ack"] += 1  # the ACK was lost to the transmitter
        else:
            fates["never_acked"] += 1
            fates["given_up_at_limit" if count >= retry_limit else "never_acked_fewer"] += 1
            if count >= retry_limit:
                given_up_by_payload[payload] += 1
                # where the receiver was, else what lost most of its attempts (the first on a tie)
                given_up_by_loss["receiver_beyond_range" if beyond_range else
                                 losses.most_common(1)[0][0]] += 1
                if beyond_range:
                    given_up_beyond_range[payload] += 1
            given_up_by_attempts[count] += 1

    for i, (t, node, kind, retry, receiver, frame_bytes, sequence, message) in enumerate(frames):
        if kind not in ("data", "arp") or receiver < 0:
            continue
        acked = acknowledged(t, node, receiver, frame_bytes)
        distance = mobility.distance(node, receiver, t / 1e9)
        loss = "beyond_range"
        if distance < range_m:
            cause, overlap = loss_cause(i, receiver)
            loss = cause if overlap is None else overlap[0]
            if overlap is not None:
                overlapped[overlap[0]][overlap[1]] += 1
            if not acked:
                lost[band_of(distance)][cause] += 1
                if overlap is not None:
                    overlaps[overlap[0]][overlap[1]] += 1
        band = bands[band_of(distance)]
        band["attempts"] += 1
        band["acked"] += acked
        band["first_attempts" if not retry else "retries"] += 1
        band["first_acked" if not retry else "retries_acked"] += acked
        attempts[("retry" if retry else "first", acked)] += 1
        mpdu = mpdus.get(node)
        if retry and mpdu is not None and mpdu[0] == receiver and mpdu[1] == sequence:
            mpdu[2] += 1
        else:
            close(mpdu)
            payload = "arp" if kind == "arp" else "message" if message >= 0 else "control"
            mpdu = mpdus[node] = [receiver, sequence, 1, 0, payload, not retry,
                                  distance >= range_m, collections.Counter()]
        if acked and not mpdu[3]:
            mpdu[3] = mpdu[2]
        if not acked:
            mpdu[7][loss] += 1
    for mpdu in mpdus.values():
        close(mpdu)
    fates["mpdus"] = sum(fates[k] for k in ("acked_first", "acked_later", "never_acked"))
    return {
        "frames": dict(sorted(kinds.items())),
        "first_transmissions": dict(sorted(classes.items())),
        "unicast_attempts": sum(attempts.values()),
        "first_attempts": attempts[("first", True)] + attempts[("first", False)],
        "first_acked": attempts[("first", True)],
        "retries": attempts[("retry", True)] + attempts[("retry", False)],
        "retries_acked": attempts[("retry", True)],
        "bands": {band: dict(counts) for band, counts in bands.items()},
        "mpdus": dict(fates),
        "never_acked_by_attempts": {str(k): v for k, v in sorted(given_up_by_attempts.items())},
        "given_up_at_limit_by_payload": dict(sorted(given_up_by_payload.items())),
        "given_up_at_limit_by_loss": dict(sorted(given_up_by_loss.items())),
        "given_up_at_limit_beyond_range_by_payload": dict(sorted(given_up_beyond_range.items())),
        "lost_in_range_by_cause": {band: dict(causes) for band, causes in lost.items()},
        "lost_in_range_by_overlap": {group: dict(starts) for group, starts in
                                     sorted(overlaps.items())},
        "in_range_by_overlap": {group: dict(starts) for group, starts in
                                sorted(overlapped.items())},
    }


def add(total, part):
    """Adds the counts of `part` into `total` (nested dicts of integers)."""
    for key, value in part.items():
        if isinstance(value, dict):
            add(total.setdefault(key, {}), value)
        else:
            total[key] = total.get(key, 0) + value


def share(numerator, denominator):
    return f"{100.0 * numerator / denominator:.1f}%" if denominator else "-"


def band_order(band):
    return DISTANCE_BANDS_M.index(int(band[1:-2])) if band.startswith("<") else len(
        DISTANCE_BANDS_M)


OVERLAP_LABELS = {
    "receiver_ack": "the receiver sent (an ACK)",
    "receiver_other": "the receiver sent (not an ACK)",
    "near_sensed_by_sender": "near the receiver, in range of the sender",
    "near_hidden_from_sender": "near the receiver, hidden from the sender",
}


GIVEN_UP_LABELS = {
    "receiver_beyond_range": "receiver beyond range at the first attempt",
    **{group: f"most attempts lost to a frame {label}" for group, label in OVERLAP_LABELS.items()},
    "only_far_frames": "most attempts lost under only far frames",
    "nothing_else_on_air": "most attempts lost with nothing else on the air",
    "beyond_range": "most attempts made beyond range",
}


def table(swarmnet, ns3):
    lines = ["| measure | SwarmNet | ns-3 |", "|---|---|---|"]
    for kind in sorted(set(swarmnet["frames"]) | set(ns3["frames"])):
        lines.append(f"| {kind} frames | {swarmnet['frames'].get(kind, 0):,} | "
                     f"{ns3['frames'].get(kind, 0):,} |")
    sc, nc = swarmnet["first_transmissions"], ns3["first_transmissions"]
    for name in sorted(set(sc) | set(nc)):
        lines.append(f"| first transmissions: {name} | {sc.get(name, 0):,} | {nc.get(name, 0):,} |")

    def row(name, key, of):
        lines.append(f"| {name} | {share(swarmnet[key], swarmnet[of])} of {swarmnet[of]:,} | "
                     f"{share(ns3[key], ns3[of])} of {ns3[of]:,} |")
    row("first attempts acknowledged", "first_acked", "first_attempts")
    row("retransmissions acknowledged", "retries_acked", "retries")
    for band in sorted(set(swarmnet["bands"]) | set(ns3["bands"]), key=band_order):
        s = swarmnet["bands"].get(band, {})
        n = ns3["bands"].get(band, {})
        lines.append(f"| {band}: attempts, acknowledged (first / retries) | "
                     f"{s.get('attempts', 0):,}, {share(s.get('acked', 0), s.get('attempts', 0))} "
                     f"({share(s.get('first_acked', 0), s.get('first_attempts', 0))} / "
                     f"{share(s.get('retries_acked', 0), s.get('retries', 0))}) | "
                     f"{n.get('attempts', 0):,}, {share(n.get('acked', 0), n.get('attempts', 0))} "
                     f"({share(n.get('first_acked', 0), n.get('first_attempts', 0))} / "
                     f"{share(n.get('retries_acked', 0), n.get('retries', 0))}) |")
    sm, nm = swarmnet["mpdus"], ns3["mpdus"]
    for key, name in (("mpdus", "MPDUs"), ("acked_first", "acknowledged at the first attempt"),
                      ("acked_later", "acknowledged at a later attempt"),
                      ("given_up_at_limit", "never acknowledged, retry limit"),
                      ("never_acked_fewer", "never acknowledged, fewer attempts"),
                      ("sent_again_after_ack", "sent again after an ACK (ACK lost)")):
        lines.append(f"| {name} | {sm.get(key, 0):,} | {nm.get(key, 0):,} |")
    sg, ng = swarmnet["given_up_at_limit_by_payload"], ns3["given_up_at_limit_by_payload"]
    for payload in sorted(set(sg) | set(ng)):
        lines.append(f"| given up at the limit, {payload} | {sg.get(payload, 0):,} | "
                     f"{ng.get(payload, 0):,} |")
    sg, ng = swarmnet["given_up_at_limit_by_loss"], ns3["given_up_at_limit_by_loss"]
    for loss in sorted(set(sg) | set(ng)):
        lines.append(f"| given up at the limit: {GIVEN_UP_LABELS[loss]} | {sg.get(loss, 0):,} | "
                     f"{ng.get(loss, 0):,} |")
    sb = swarmnet["given_up_at_limit_beyond_range_by_payload"]
    nb = ns3["given_up_at_limit_beyond_range_by_payload"]
    for payload in sorted(set(sb) | set(nb)):
        lines.append(f"| given up at the limit, receiver beyond range: {payload} | "
                     f"{sb.get(payload, 0):,} | {nb.get(payload, 0):,} |")
    sl, nl = swarmnet["lost_in_range_by_cause"], ns3["lost_in_range_by_cause"]
    for band in sorted(set(sl) | set(nl), key=band_order):
        for cause in LOSS_CAUSES:
            s_n, n_n = sl.get(band, {}).get(cause, 0), nl.get(band, {}).get(cause, 0)
            if s_n or n_n:
                lines.append(f"| lost {band}: {cause.replace('_', ' ')} | {s_n:,} | {n_n:,} |")
    sa, na = swarmnet["in_range_by_overlap"], ns3["in_range_by_overlap"]
    so, no = swarmnet["lost_in_range_by_overlap"], ns3["lost_in_range_by_overlap"]
    for group in sorted(set(sa) | set(na)):
        for start in OVERLAP_STARTS:
            s_a, n_a = sa.get(group, {}).get(start, 0), na.get(group, {}).get(start, 0)
            s_n, n_n = so.get(group, {}).get(start, 0), no.get(group, {}).get(start, 0)
            if s_a or n_a:
                lines.append(f"| attempts under a frame {OVERLAP_LABELS[group]}, started "
                             f"{start.replace('_', ' ')}: lost of all | {s_n:,} of {s_a:,} | "
                             f"{n_n:,} of {n_a:,} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--pair", action="append", default=[], metavar="RUN_DIR:NS3_FRAMES")
    parser.add_argument("--seed-dirs", nargs="*", default=[], metavar="DIR",
                        help="run_grid.py seed directories (DIR/swarmnet, DIR/ns3-frames.csv)")
    parser.add_argument("--rate-mbps", type=float, default=6.0, help="data rate of every frame")
    parser.add_argument("--ack-slack-us", type=float, default=3.0,
                        help="how far from SIFS after the frame an ACK may start")
    parser.add_argument("--retry-limit", type=int, default=7, help="attempts before giving up")
    parser.add_argument("--range-m", type=float, default=RANGE_M,
                        help="nominal range: lost attempts within it are put down to a cause")
    parser.add_argument("--from-s", type=float, default=0.0,
                        help="only frames that start at or after this simulated time")
    parser.add_argument("--to-s", type=float, default=math.inf,
                        help="only frames that start before this simulated time")
    parser.add_argument("--out", help="write the counts as JSON here")
    args = parser.parse_args()
    pairs = [tuple(p.rsplit(":", 1)) for p in args.pair]
    pairs += [(os.path.join(d, "swarmnet"), os.path.join(d, "ns3-frames.csv"))
              for d in args.seed_dirs]
    if not pairs or any(len(p) != 2 for p in pairs):
        parser.error("give --pair RUN_DIR:NS3_FRAMES or --seed-dirs DIR ...")
    if not args.from_s < args.to_s:
        parser.error(f"--from-s {args.from_s:g} is not before --to-s {args.to_s:g}")
    window = (args.from_s * 1e9, args.to_s * 1e9)
    result = {"pairs": [], "pooled": {"swarmnet": {}, "ns3": {}}}
    for run_dir, ns3_frames in pairs:
        mobility = Mobility(os.path.join(run_dir, "mobility.ns2"))
        entry = {"run_dir": run_dir, "ns3_frames": ns3_frames}
        for side, path in (("swarmnet", os.path.join(run_dir, "frames.csv")),
                           ("ns3", ns3_frames)):
            # An ACK ends a frame's exchange: one for a frame the window holds may start after it.
            ack_grace = 3e6
            frames = [f for f in read_frames(path) if window[0] <= f[0] < window[1] or
                      (f[2] == "ack" and window[1] <= f[0] < window[1] + ack_grace)]
            try:
                entry[side] = analyse(frames, mobility, args.rate_mbps, args.ack_slack_us,
                                      args.retry_limit, args.range_m)
            except KeyError as error:
                sys.exit(f"frame_agreement.py: {path}: {error.args[0]} ({run_dir}'s mobility.ns2 "
                         f"does not go with this trace)")
            add(result["pooled"][side], entry[side])
        result["pairs"].append(entry)
        print(f"{run_dir}:\n{table(entry['swarmnet'], entry['ns3'])}\n", flush=True)
    if len(pairs) > 1:
        print(f"pooled over {len(pairs)} pairs:\n"
              f"{table(result['pooled']['swarmnet'], result['pooled']['ns3'])}")
    if args.out:
        try:
            with open(args.out, "w", encoding="utf-8") as f:
                json.dump(result, f, indent=1)
        except OSError as error:
            sys.exit(f"frame_agreement.py: cannot write {args.out}: {error.strerror}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
