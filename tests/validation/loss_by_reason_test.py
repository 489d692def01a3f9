#!/usr/bin/env python3
"""loss_by_reason.py on runs written here: each side's messages by reason and where, a message
counted once (SwarmNet's not at all when a copy was delivered), ns-3's ARP reasons named as
SwarmNet's, the rest, the mean over runs; a run without its packet trace refused by name."""
import json
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "loss_by_reason.py")
TRAFFIC = [(0, 1, 4), (1, 1, 4), (2, 1, 4), (3, 2, 4), (4, 2, 4)]  # message, source, destination


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def swarmnet_run(root, name, delivered, events, packet_trace=True):
    """A run directory; events are (event, node, message_id, source, detail)."""
    path = os.path.join(root, name)
    os.makedirs(path)
    write(os.path.join(path, "summary.json"),
          json.dumps({"packets": {"sent": len(TRAFFIC), "delivered": delivered}}))
    write(os.path.join(path, "traffic.csv"),
          "message_id,step,inject_ns,source,destination,payload_bytes\n" +
          "".join(f"{m},1,100,{s},{d},64\n" for m, s, d in TRAFFIC))
    if packet_trace:
        write(os.path.join(path, "packets.csv"),
              "time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail\n" +
              "".join(f"{i},{e},{n},{i},{m},{s},4,0,92,{d}\n"
                      for i, (e, n, m, s, d) in enumerate(events)))
    return path


def ns3_run(root, name, run_dir, delivered, events):
    """The replay's JSON and IP trace; events are (event, node, message_id, detail)."""
    json_path = os.path.join(root, name + ".json")
    trace_path = os.path.join(root, name + "-ip.csv")
    write(json_path, json.dumps({"run_dir": run_dir,
                                 "packets": {"sent": len(TRAFFIC), "delivered": delivered}}))
    write(trace_path, "time_ns,node,event,message_id,ip_ttl,ip_destination,detail\n" +
          "".join(f"{i},{n},{e},{m},64,4,{d}\n" for i, (e, n, m, d) in enumerate(events)))
    return f"{json_path}:{trace_path}"


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True,
                          check=False)


def main():
    problems = []
    with tempfile.TemporaryDirectory() as root:
        # Run a: 0 delivered; 1 dropped at its source (ARP, full queue); 2 delivered although a
        # copy was dropped; 3 dropped twice, first at a relay (dead entry), then again; 4 lost
        # without a record. Run b: 0 and 1 delivered, 2 at a relay for no route.
        a = swarmnet_run(root, "a", 2, [
            ("deliver", 4, 0, 1, ""), ("drop", 1, 1, 1, "arp_queue_full"),
            ("deliver", 4, 2, 1, ""), ("drop", 3, 2, 1, "retry_limit"),
            ("drop", 3, 3, 2, "arp_unresolved"), ("drop", 3, 3, 2, "retry_limit")])
        b = swarmnet_run(root, "b", 2, [
            ("deliver", 4, 0, 1, ""), ("deliver", 4, 1, 1, ""), ("drop", 3, 2, 1, "no_route")])
        # ns-3 on run a's traffic: 1 dead entry at its source; 3 retries exhausted at a relay and
        # an IP drop after; 2 queue full at a relay; a control packet's ARP drop left out.
        n = ns3_run(root, "n", a, 1, [
            ("arp_drop", 1, 1, "dead_entry"), ("arp_drop", 3, 3, "retries_exhausted"),
            ("drop", 3, 3, "no_route"), ("arp_drop", 3, 2, "queue_full"),
            ("arp_drop_rrep", 3, -1, "dead_entry"), ("forward", 3, 0, "")])
        out = os.path.join(root, "out.json")
        result = run("--swarmnet", a, b, "--ns3", n, "--out", out)
        if result.returncode != 0:
            return print(result.stderr) or 1
        with open(out, encoding="utf-8") as f:
            got = json.load(f)
        expected_sn = {"sent": 5.0, "delivered": 2.0, "arp_queue_full@source": 0.5,
                       "arp_unresolved@relay": 0.5, "no_route@relay": 0.5, "rest": 1.5}
        expected_ns3 = {"sent": 5.0, "delivered": 1.0, "arp_unresolved@source": 1.0,
                        "arp_unresolved@relay": 1.0, "arp_queue_full@relay": 1.0, "rest": 1.0}
        if got["swarmnet"] != expected_sn:
            problems.append(f"SwarmNet: {got['swarmnet']}, expected {expected_sn}")
        if got["ns3"] != expected_ns3:
            problems.append(f"ns-3: {got['ns3']}, expected {expected_ns3}")
        if got["runs"] != {"swarmnet": 2, "ns3": 1}:
            problems.append(f"runs: {got['runs']}")
        if "arp_unresolved@relay" not in result.stderr:
            problems.append("no table printed")

        bare = swarmnet_run(root, "bare", 0, [], packet_trace=False)
        refused = run("--swarmnet", bare, "--ns3", n)
        if refused.returncode == 0 or "packets.csv missing" not in refused.stderr \
                or "bare" not in refused.stderr:
            problems.append(f"a run without packets.csv: exit {refused.returncode}, "
                            f"{refused.stderr.strip()!r}")
        malformed = run("--swarmnet", a, "--ns3", "no-colon")
        if malformed.returncode == 0 or "JSON:IP_TRACE" not in malformed.stderr:
            problems.append(f"--ns3 without ':': exit {malformed.returncode}")
    for problem in problems:
        print("FAIL:", problem)
    if not problems:
        print("loss_by_reason: counts, mapping, rest and refusals as expected")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
