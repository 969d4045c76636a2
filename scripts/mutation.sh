#!/usr/bin/env bash
# Mutation cover of one top's generated netlist (YosysHQ mcy's method; too long for CI):
#   bash scripts/mutation.sh TOP N [--seed S] [--jobs J] [--only I,J,...] [--replay-only]     TOP: rc, rc3, colour_setup, cs, cs_tex, opp, tex_setup
# Yosys draws N mutations of the top's netlist; each mutant is replayed under Icarus (Verilator for cs_tex)
# on the recorded stimulus and the cycle model's expected outputs (killed when any port differs in any cycle); a
# survivor is tried for equivalence (its cell dead in the flattened top, else Yosys's equiv_* passes over
# the mutated module, then over the whole top). One line per mutant; the counts and
# every mutant in target/mutation/TOP.json. See docs/verification.md, "Mutation cover".
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in yosys iverilog vvp verilator; do
  command -v "$tool" >/dev/null 2>&1 || { echo "error: $tool is missing (apt-get install yosys iverilog verilator)" >&2; exit 1; }
done
mkdir -p target/tmp
export TMPDIR="$PWD/target/tmp"
cargo build --release -q -p tb --bin mutation
# The RustHDL benches that record the stimulus recurse deeply (as under cargo test).
RUST_MIN_STACK=33554432 exec target/release/mutation "$@"
