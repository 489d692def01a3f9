#!/usr/bin/env python3
"""frame_agreement.py on traces written here: ACKs matched SIFS after a frame's airtime, an MPDU's
attempts grouped and its fate told (first attempt, later, never: at the retry limit), a lost ACK
seen as a retransmission after it, distances from ns-2 moves, a lost attempt put down to what
else was on the air (and to whom, and when it started), and a malformed trace refused by
name."""
import json
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "frame_agreement.py")
HEADER = "time_ns,node,kind,retry,receiver,bytes,sequence,message_id\n"
# 164 bytes at 6 Mbit/s: 20 us + 56 symbols of 4 us = 244 us; its ACK starts SIFS (16 us) later.
ACK_AFTER_NS = (244 + 16) * 1000
MOBILITY = ("$node_(0) set X_ 0\n$node_(0) set Y_ 0\n$node_(0) set Z_ 0\n"
            "$node_(1) set X_ 50\n$node_(1) set Y_ 0\n$node_(1) set Z_ 0\n"
            "$node_(2) set X_ 0\n$node_(2) set Y_ 115\n$node_(2) set Z_ 0\n"
            # node 2 moves away from 115 m to 130 m between t = 1 s and t = 2 s
            '$ns_ at 1.0 "$node_(2) setdest 0 130 15"\n'
            # node 3 is in range of nodes 0 and 1; node 4 of node 1 only (110 m; 160 m from 0)
            "$node_(3) set X_ 25\n$node_(3) set Y_ 30\n$node_(3) set Z_ 0\n"
            "$node_(4) set X_ 160\n$node_(4) set Y_ 0\n$node_(4) set Z_ 0\n")


def data(t, node, receiver, sequence, retry=0, message=1):
    return f"{t},{node},data,{retry},{receiver},164,{sequence},{message}\n"


def ack(t, node, receiver):
    return f"{t},{node},ack,0,{receiver},14,-1,-1\n"


def frames(ack_lost):
    text = HEADER + data(1_000_000, 0, 1, 5)
    if ack_lost:  # node 1 answers, node 0 does not hear it and sends the frame again
        text += ack(1_000_000 + ACK_AFTER_NS, 1, 0) + data(1_400_000, 0, 1, 5, retry=1)
        text += ack(1_400_000 + ACK_AFTER_NS, 1, 0)
    else:
        text += ack(1_000_000 + ACK_AFTER_NS + 1000, 1, 0)  # 1 us late: within the slack
    # to node 2, 130 m away by then: seven attempts, no ACK
    for attempt in range(7):
        text += data(2_100_000_000 + attempt * 1_000_000, 0, 2, 6, retry=min(attempt, 1))
    # node 1 to node 0: the first attempt fails, the second is acknowledged
    text += data(3_000_000_000, 1, 0, 1) + data(3_001_000_000, 1, 0, 1, retry=1)
    text += ack(3_001_000_000 + ACK_AFTER_NS, 0, 1)
    text += "3500000000,1,data,0,-1,164,2,7\n"  # a broadcast: no ACK expected
    # an ACK at the wrong time (a different exchange) acknowledges nothing
    text += data(4_000_000_000, 0, 1, 7) + ack(4_000_000_000 + ACK_AFTER_NS + 20_000, 1, 0)
    # lost while its receiver transmits a broadcast of its own, 10 us after the frame began
    text += data(5_000_000_000, 0, 1, 8) + "5000010000,1,data,0,-1,164,3,-1\n"
    # lost to node 3, which node 0 senses, starting 2 us later: the same slot
    text += data(6_000_000_000, 0, 1, 9) + "6000002000,3,data,0,-1,164,1,-1\n"
    # lost to node 4, hidden from node 0, on the air since 100 us before
    text += "6999900000,4,data,0,-1,164,1,-1\n" + data(7_000_000_000, 0, 1, 10)
    # received (acknowledged) under the same frame of node 4
    text += "7999900000,4,data,0,-1,164,2,-1\n" + data(8_000_000_000, 0, 1, 11)
    text += ack(8_000_000_000 + ACK_AFTER_NS, 1, 0)
    # given up at the limit, every attempt under a frame of node 4 begun 100 us before it
    for attempt in range(7):
        t = 9_000_000_000 + attempt * 1_000_000
        text += f"{t - 100_000},4,data,0,-1,164,{3 + attempt},-1\n"
        text += data(t, 0, 1, 12, retry=min(attempt, 1))
    return text


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main():
    problems = []
    with tempfile.TemporaryDirectory() as root:
        run_dir = os.path.join(root, "run")
        os.makedirs(run_dir)
        write(os.path.join(run_dir, "mobility.ns2"), MOBILITY)
        write(os.path.join(run_dir, "frames.csv"), frames(ack_lost=False))
        ns3_frames = os.path.join(root, "ns3-frames.csv")
        write(ns3_frames, frames(ack_lost=True))
        out = os.path.join(root, "out.json")
        result = subprocess.run([sys.executable, SCRIPT, "--pair", f"{run_dir}:{ns3_frames}",
                                 "--out", out], capture_output=True, text=True, check=False)
        if result.returncode != 0:
            print(result.stdout, result.stderr)
            return 1
        pooled = json.load(open(out, encoding="utf-8"))["pooled"]
        s, n = pooled["swarmnet"], pooled["ns3"]

        def expect(what, got, want):
            if got != want:
                problems.append(f"{what}: {got}, expected {want}")
        expect("SwarmNet MPDUs", s["mpdus"], {"acked_first": 2, "acked_later": 1,
                                              "never_acked": 6, "given_up_at_limit": 2,
                                              "never_acked_fewer": 4, "mpdus": 9})
        expect("ns-3 MPDUs", n["mpdus"], {"acked_first": 2, "acked_later": 1,
                                          "never_acked": 6, "given_up_at_limit": 2,
                                          "never_acked_fewer": 4, "sent_again_after_ack": 1,
                                          "mpdus": 9})
        expect("given up, by payload", s["given_up_at_limit_by_payload"], {"message": 2})
        # node 2 had moved beyond range; node 1's attempts were all lost to hidden node 4
        expect("given up, by loss", s["given_up_at_limit_by_loss"],
               {"receiver_beyond_range": 1, "near_hidden_from_sender": 1})
        expect("given up beyond range, by payload",
               s["given_up_at_limit_beyond_range_by_payload"], {"message": 1})
        # within range, lost: 1 -> 0 and 0 -> 1 with nothing else on the air, 0 -> 1 while 1
        # transmits, and 0 -> 1 twice under a frame near 1; the seven attempts to node 2, 130 m
        # away, are out of range
        expect("lost by cause", s["lost_in_range_by_cause"],
               {"<60 m": {"nothing_else_on_air": 2, "receiver_transmitting": 1,
                          "later_frame_near_receiver": 1, "earlier_frame_near_receiver": 8}})
        expect("lost by overlap", s["lost_in_range_by_overlap"],
               {"near_hidden_from_sender": {"before": 8},
                "near_sensed_by_sender": {"within_4_us": 1}, "receiver_other": {"after": 1}})
        # every attempt within range under such a frame, lost or not: one more under node 4's
        expect("in range by overlap", s["in_range_by_overlap"],
               {"near_hidden_from_sender": {"before": 9},
                "near_sensed_by_sender": {"within_4_us": 1}, "receiver_other": {"after": 1}})
        expect("SwarmNet first attempts", (s["first_attempts"], s["first_acked"]), (9, 2))
        expect("SwarmNet retries", (s["retries"], s["retries_acked"]), (13, 1))
        expect("ns-3 retries", (n["retries"], n["retries_acked"]), (14, 2))
        expect("never acknowledged by attempts", s["never_acked_by_attempts"], {"1": 4, "7": 2})
        expect("bands", sorted(s["bands"]), ["<60 m", ">=120 m"])
        expect("beyond 120 m", s["bands"][">=120 m"].get("attempts"), 7)
        expect("frames by kind", s["frames"], {"ack": 4, "data": 34})
        # first transmissions by what they carry (the Retry bit clear): the broadcasts of nodes
        # 1, 3 and 4 are control packets of 164 B; every unicast carries a message
        expect("first transmissions", s["first_transmissions"],
               {"ack": 4, "broadcast control 164 B": 11, "broadcast message 164 B": 1,
                "unicast message 164 B": 9})
        if "| first attempts acknowledged | 22.2% of 9 | 22.2% of 9 |" not in result.stdout:
            problems.append("table: no first-attempt row:\n" + result.stdout)
        if ("| attempts under a frame near the receiver, hidden from the sender, started before: "
                "lost of all | 8 of 9 | 8 of 9 |") not in result.stdout:
            problems.append("table: no row of attempts under a frame:\n" + result.stdout)
        # A window of simulated time keeps only the frames that start in it: [3 s, 4.5 s) holds
        # node 1's MPDU (acknowledged at its second attempt), the broadcast and node 0's MPDU
        # whose ACK came too late.
        windowed = subprocess.run([sys.executable, SCRIPT, "--pair", f"{run_dir}:{ns3_frames}",
                                   "--from-s", "3", "--to-s", "4.5", "--out", out],
                                  capture_output=True, text=True, check=False)
        window = json.load(open(out, encoding="utf-8"))["pooled"]["swarmnet"]
        expect("a window's MPDUs", (windowed.returncode, window["mpdus"]),
               (0, {"acked_later": 1, "never_acked": 1, "never_acked_fewer": 1, "mpdus": 2}))
        # A window's edges: the frame at 1 ms is acknowledged after the window ends (its ACK is
        # kept), and node 0's MPDU to node 2 whose first attempt precedes the window has no fate.
        for lo, hi, want in (("0", "0.0011", {"acked_first": 1, "mpdus": 1}),
                             ("2.1025", "2.2", {"begun_before_trace": 1, "mpdus": 0})):
            subprocess.run([sys.executable, SCRIPT, "--pair", f"{run_dir}:{ns3_frames}",
                            "--from-s", lo, "--to-s", hi, "--out", out],
                           capture_output=True, text=True, check=False)
            got = json.load(open(out, encoding="utf-8"))["pooled"]["swarmnet"]["mpdus"]
            expect(f"MPDUs in [{lo} s, {hi} s)", got, want)
        # A mobility trace that lacks a node of the frame trace is refused, naming both.
        other_dir = os.path.join(root, "other")
        os.makedirs(other_dir)
        write(os.path.join(other_dir, "mobility.ns2"), MOBILITY.split("$node_(2)")[0])
        write(os.path.join(other_dir, "frames.csv"), frames(ack_lost=False))
        mismatched = subprocess.run([sys.executable, SCRIPT, "--pair", f"{other_dir}:{ns3_frames}"],
                                    capture_output=True, text=True, check=False)
        if mismatched.returncode == 0 or "does not go with this trace" not in mismatched.stderr:
            problems.append(f"a mobility trace without node 2 was not refused: "
                            f"{mismatched.stderr[-300:]}")
        # A trace with other columns is refused, by name.
        bad = os.path.join(root, "bad.csv")
        write(bad, "time,node\n1,2\n")
        refused = subprocess.run([sys.executable, SCRIPT, "--pair", f"{run_dir}:{bad}"],
                                 capture_output=True, text=True, check=False)
        if refused.returncode == 0 or "bad.csv: header" not in refused.stderr:
            problems.append(f"a malformed trace was not refused by name: {refused.stderr}")
        write(bad, HEADER + "1000,0,data,0,1,164,zero,1\n")
        refused = subprocess.run([sys.executable, SCRIPT, "--pair", f"{run_dir}:{bad}"],
                                 capture_output=True, text=True, check=False)
        if refused.returncode == 0 or "bad.csv:2:" not in refused.stderr:
            problems.append(f"a row that is not integers was not refused by line: "
                            f"{refused.stderr}")
        missing = subprocess.run([sys.executable, SCRIPT, "--seed-dirs", root],
                                 capture_output=True, text=True, check=False)
        if missing.returncode == 0 or "cannot read" not in missing.stderr:
            problems.append(f"a missing run directory was not refused: {missing.stderr}")
    for problem in problems:
        print("FAIL:", problem)
    if not problems:
        print("frame_agreement: ACKs, MPDU fates, distances and refusals as expected")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
