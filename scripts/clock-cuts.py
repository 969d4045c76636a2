#!/usr/bin/env python3
"""What-if timing cuts on a top's generated Verilog (docs/clock.md, "How far each cut goes").

Usage: python3 scripts/clock-cuts.py IN.v OUT.v CUT [CUT...]

Each CUT puts registers into one named path of the Verilog written by `idxrender verilog` (tops
`rc`, `cs`, `chipset`: the modules are found by their name's tail, whatever the top's prefix). The
result is for timing only: a cut adds a cycle where the design has none, so OUT.v no longer does
what the RTL does, and no test or figure other than a what-if Fmax may be taken from it. Place and
route it with fpga-report's method: `idxrender fpga-report --block TOP --device ecp5-45k
--verilog OUT.v`. A cut whose text is not found is an error: the script never writes a partial cut.

  walk    the traversal's walk decision (walk_end, row_done, nsel, long, has_frag) registered where
          the Walk branch and the record take use it
  grad    setup's Grad product (47x26): its four partial products registered before their sum
  norm    the Phong CS normalizer's three squares: their input registered

The `setup` cut (the partial products of S2's dot units, then of Plane's) is gone: both are
`MulPipeS` in the design itself (S2 since 2026-12-05, Plane since 2026-12-07).
"""
import re
import sys


def module_span(s, tail):
    """(start, end) of the one module whose name ends in `tail` (a `$`-path such as `$mul_g`)."""
    found = [m for m in re.finditer(r"^module (\S+?)\(", s, re.M) if m.group(1).endswith(tail)]
    if len(found) != 1:
        sys.exit(f"error: {len(found)} modules end in `{tail}` (want one)")
    start = found[0].start()
    return start, s.index("endmodule", start), found[0].group(1)


def add_clock_port(s, name, first_port):
    """Give module `name` a clock input before `first_port`, and connect its one instance to its
    parent's clock."""
    hdr = f"module {name}({first_port},"
    end = s.find(");\n", s.find(hdr))
    if s.count(hdr) != 1 or end < 0:
        sys.exit(f"error: `{name}` has no port list starting with `{first_port}`")
    s = s[:end] + ");\n    input wire clock;\n" + s[end + 3:]
    s = s.replace(hdr, f"module {name}(clock,{first_port},", 1)
    inst = f"    {name} {name.rsplit('$', 1)[1]}(\n"
    if s.count(inst) != 1:
        sys.exit(f"error: {s.count(inst)} instances of `{name}` (want one)")
    return s.replace(inst, inst + "        .clock(clock),\n", 1)


def cut_walk(s):
    i, j, _ = module_span(s, "$front$traversal")
    body = s[i:j]
    decl = "    reg  walk_end;\n"
    walk = body.find("TravState$Walk:\n")
    if decl not in body or walk < 0:
        sys.exit("error: the traversal's walk_end declaration or its Walk branch is not found")
    tail = body[walk:]
    for w in ["walk_end", "row_done", "nsel", "long", "has_frag"]:
        tail = re.sub(rf"\b{w}\b", f"{w}_r", tail)
    head = body[:walk].replace(
        decl,
        decl + "    reg walk_end_r; reg row_done_r; reg long_r; reg has_frag_r; reg [2:0] nsel_r;\n"
        "    always @(posedge clock) begin walk_end_r <= walk_end; row_done_r <= row_done; long_r <= long;"
        " has_frag_r <= has_frag; nsel_r <= nsel; end\n",
        1,
    )
    return s[:i] + head + tail + s[j:]


def cut_grad(s):
    i, j, name = module_span(s, "$front$setup$mul_g")
    old = "    always @(*) p = a * b;\n"
    if old not in s[i:j]:
        sys.exit(f"error: `{name}` is not the one-line product this cut expects")
    new = (
        "    wire signed [29:0] ah = a[46:17];\n    wire signed [17:0] al = {1'b0, a[16:0]};\n"
        "    wire signed [8:0] bh = b[25:17];\n    wire signed [17:0] bl = {1'b0, b[16:0]};\n"
        "    reg signed [72:0] hh, hl, lh, ll;\n"
        "    always @(posedge clock) begin hh <= ah * bh; hl <= ah * bl; lh <= al * bh; ll <= al * bl; end\n"
        "    always @(*) p = (hh <<< 34) + (hl <<< 17) + (lh <<< 17) + ll;\n"
    )
    s = s[:i] + s[i:j].replace(old, new, 1) + s[j:]
    return add_clock_port(s, name, "a")


def cut_norm(s):
    for m in ["sq_x", "sq_y", "sq_z"]:
        i, j, name = module_span(s, f"$normalizer${m}")
        body = s[i:j]
        old = "input wire signed [15:0] a;"
        if old not in body:
            sys.exit(f"error: `{name}` has no 16-bit input `a`")
        body = body.replace(old, "input wire signed [15:0] a_in;\n    reg signed [15:0] a; always @(posedge clock) a <= a_in;", 1)
        body = body.replace(f"module {name}(a,", f"module {name}(a_in,", 1)
        s = add_clock_port(s[:i] + body + s[j:], name, "a_in")
        inst = f"    {name} {m}(\n        .clock(clock),\n        .a("
        if s.count(inst) != 1:
            sys.exit(f"error: the instance of `{name}` does not connect `a` first")
        s = s.replace(inst, f"    {name} {m}(\n        .clock(clock),\n        .a_in(", 1)
    return s


CUTS = {"walk": cut_walk, "grad": cut_grad, "norm": cut_norm}


def main():
    if len(sys.argv) < 4 or any(c not in CUTS for c in sys.argv[3:]):
        sys.exit(__doc__.strip() + "\n\nerror: give IN.v OUT.v and at least one of: " + ", ".join(CUTS))
    s = open(sys.argv[1]).read()
    for c in sys.argv[3:]:
        s = CUTS[c](s)
    open(sys.argv[2], "w").write(s)


if __name__ == "__main__":
    main()
