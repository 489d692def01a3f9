#!/usr/bin/env python3
"""scripts/seed_interval.py against values worked out by hand: the mean and the 95% Student-t
interval of four per-seed differences, no interval for a single seed, and a clear error when
`swarmnet stats` cannot run."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
from seed_interval import student_interval  # noqa: E402

swarmnet = os.environ["SWARMNET_BIN"]

# Differences 1.0, -2.5, 3.0, 0.5: mean 0.5, sd 2.27303 (sum of squares 15.5 / 3), standard error
# 1.136515, t(3, 0.975) = 3.182446: half-width 3.616898.
got = student_interval(swarmnet, [1.0, -2.5, 3.0, 0.5])
assert got["n"] == 4, got
assert abs(got["mean"] - 0.5) < 1e-12, got
assert abs(got["sd"] - 2.273030) < 1e-6, got
assert abs(got["low"] - (0.5 - 3.616898)) < 1e-5, got
assert abs(got["high"] - (0.5 + 3.616898)) < 1e-5, got

# A value the CSV must carry exactly (no rounding on the way to `swarmnet stats`).
got = student_interval(swarmnet, [0.1 + 0.2, 0.1 + 0.2])
assert got["mean"] == 0.1 + 0.2 and got["low"] == got["high"] == got["mean"], got

assert student_interval(swarmnet, [4.0]) is None
assert student_interval(swarmnet, []) is None

try:
    student_interval(os.path.join(os.path.dirname(swarmnet), "no-such-binary"), [1.0, 2.0])
except (RuntimeError, OSError) as error:
    assert "no-such-binary" in str(error), error
else:
    raise AssertionError("a missing binary was not reported")
print("ok")
