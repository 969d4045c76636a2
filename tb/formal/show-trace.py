#!/usr/bin/env python3
"""Print a Yosys witness trace (trace.yw, as scripts/formal.sh writes) one step per line.

Usage: python3 tb/formal/show-trace.py target/formal/<harness>_<task>/engine_0/trace.yw [SIGNAL...]

Each step lists the harness's inputs (and the solver-chosen `anyconst` values at step 0) in hex;
bits the solver left free print as `?`. Name signals to print only those. To see the design's
outputs, drive these inputs into the harness's top in a simulator.
"""
import json
import sys

if len(sys.argv) < 2:
    sys.exit(__doc__)
with open(sys.argv[1]) as f:
    trace = json.load(f)
wanted = set(sys.argv[2:])
for step, bits in enumerate(s["bits"] for s in trace["steps"]):
    end = len(bits)  # the bits of a step are the signals' bits, the first signal's at the end
    fields = []
    for sig in trace["signals"]:
        width = sig["width"]
        value = bits[end - width:end]
        end -= width
        name = ".".join(p.lstrip("\\") for p in sig["path"])
        if (wanted and name not in wanted) or not value or name == "clock":
            continue
        if sig.get("init_only") and step > 0:
            continue
        shown = "%x" % int(value, 2) if set(value) <= set("01") else value
        fields.append("%s=%s" % (name, shown))
    print("step %d: %s" % (step, " ".join(fields)))
