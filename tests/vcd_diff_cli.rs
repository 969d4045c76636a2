//! `idxrender vcd-diff` on a real pair of traces of the same top on the same stimulus: the RustHDL
//! simulation of `rc` (direct drive, whole hierarchy, `uut` scope, struct ports written field by
//! field) and the generated Verilog of `rc` under Icarus replaying the vectors recorded from that run
//! (`tb/verilator/rc/tb_rc.v`, `$dumpvars(1, dut)`: flat vector ports, different timing). They must
//! compare equal on every port; a trace with one value changed must be reported at exactly the
//! cycle and signal of the change.

use std::path::{Path, PathBuf};
use std::process::Command;
use tb::common::require_tools;
use std::sync::OnceLock;
use tb::rc::bench::{run_rtl, Drive};
use tb::rc::replay::{replay_dumping, Simulator, VectorWriter};
use tb::rc::stimulus::{hand_made, hand_made_screen};

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target").join("test-cli").join("vcd_diff");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// (RustHDL trace, Icarus trace, cycles), made once for the tests of this file.
fn traces() -> &'static (PathBuf, PathBuf, u64) {
    static T: OnceLock<(PathBuf, PathBuf, u64)> = OnceLock::new();
    T.get_or_init(|| {
        // Two hand-made frames (shared edge, fill-rule corners) on the 32x24 test screen, with random
        // gaps and back-pressure.
        let cmds: Vec<_> = hand_made().into_iter().take(2).flat_map(|(_, c)| c).collect();
        let drive = Drive { garbage: false, ..Drive::random("vcd_diff_pair", 0x5eed) };
        let vectors = dir().join("pair.vec");
        let mut w = VectorWriter::create(vectors.clone()).unwrap();
        // run_rtl writes its VCD (target/vcd/rc/<test>.vcd) when VCD is set.
        std::env::set_var("VCD", "1");
        let run = run_rtl("vcd_diff_pair", hand_made_screen(), &cmds, drive, Some(&mut w)).unwrap_or_else(|e| panic!("{e}"));
        let (vectors, cycles) = w.finish().unwrap();
        assert_eq!(cycles, run.cycles);
        let rusthdl = tb::common::vcd_path("rc", "vcd_diff_pair");
        let icarus = dir().join("icarus.vcd");
        let _ = std::fs::remove_file(&icarus);
        let checked = replay_dumping(Simulator::Icarus, hand_made_screen(), &vectors, Some(&icarus)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(checked, cycles);
        (rusthdl, icarus, cycles)
    })
}

fn vcd_diff(a: &Path, b: &Path, extra: &[&str]) -> (i32, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).arg("vcd-diff").arg(a).arg(b).args(extra).output().unwrap();
    (o.status.code().unwrap_or(-1), format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr)))
}

/// The ports of `rc` (every one must be compared).
const RC_PORTS: &[&str] = &[
    "cmd$data", "cmd$valid", "cmd$ready", "result$data", "result$valid", "result$ready", "z_re", "z_rd_addr", "z_we", "z_wr_addr", "z_wr_data",
    "z_rd_data", "i_we", "i_wr_addr", "i_wr_data", "i_rd_data",
];

#[test]
fn rusthdl_and_icarus_traces_of_rc_compare_equal_on_every_port() {
    if !require_tools("rusthdl_and_icarus_traces_of_rc_compare_equal_on_every_port", &["iverilog"]) {
        return;
    }
    let (rusthdl, icarus, cycles) = traces();
    let (code, out) = vcd_diff(rusthdl, icarus, &[]);
    assert_eq!(code, 0, "vcd-diff:\n{out}");
    // The Icarus trace has one rising edge per replayed cycle; the RustHDL one as many.
    assert!(out.contains(&format!("equal: {cycles} cycles")), "{out}");
    let compared = out.lines().find_map(|l| l.strip_prefix("compared: ")).unwrap();
    let compared: Vec<&str> = compared.split(", ").collect();
    for p in RC_PORTS {
        assert!(compared.contains(p), "port {p} was not compared:\n{out}");
    }
    // Either order, and a named subset.
    let (code, out) = vcd_diff(icarus, rusthdl, &["--signals", "cmd$data,z_wr_data"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("compared: cmd$data, z_wr_data"), "{out}");
    let (code, out) = vcd_diff(icarus, rusthdl, &["--signals", "no_such_port"]);
    assert_eq!(code, 2, "{out}");
    assert!(out.contains("no signal `no_such_port`"), "{out}");
}

/// Rising-edge times of `clock` in a VCD, read as plain text (independently of vcd-diff).
fn rising_edges(text: &str, clock_code: &str) -> Vec<u64> {
    let (mut t, mut clk, mut edges) = (0u64, '?', Vec::new());
    for l in text.lines() {
        if let Some(n) = l.strip_prefix('#') {
            t = n.trim().parse().unwrap();
        } else if l.len() >= 2 && l[1..] == *clock_code && (l.starts_with('0') || l.starts_with('1')) {
            let v = l.chars().next().unwrap();
            if v == '1' && clk == '0' {
                edges.push(t);
            }
            clk = v;
        }
    }
    edges
}

/// The id code of `name` declared in `text`.
fn code_of(text: &str, name: &str) -> String {
    text.lines()
        .filter(|l| l.contains("$var"))
        .find_map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            (w.len() >= 5 && (w[4] == name || w[4] == format!("\\{name}"))).then(|| w[3].to_string())
        })
        .unwrap_or_else(|| panic!("no $var {name}"))
}

#[test]
fn a_trace_with_one_value_changed_is_reported_at_that_cycle_and_signal() {
    if !require_tools("a_trace_with_one_value_changed_is_reported_at_that_cycle_and_signal", &["iverilog"]) {
        return;
    }
    let (rusthdl, icarus, _) = traces();
    let text = std::fs::read_to_string(icarus).unwrap();
    let clock = code_of(&text, "clock");
    let sig = code_of(&text, "z_wr_addr");
    let edges = rising_edges(&text, &clock);
    assert!(edges.len() > 100, "too few cycles in the Icarus trace");
    // The 5th change of z_wr_addr after the first 20 edges: flip its lowest bit.
    let lines: Vec<&str> = text.lines().collect();
    let (mut t, mut picked) = (0u64, None);
    let mut seen = 0;
    for (i, l) in lines.iter().enumerate() {
        if let Some(n) = l.strip_prefix('#') {
            t = n.trim().parse().unwrap();
        } else if l.starts_with('b') && l.split_whitespace().nth(1) == Some(sig.as_str()) && t > edges[20] {
            seen += 1;
            if seen == 5 {
                picked = Some((i, t));
                break;
            }
        }
    }
    let (line, t) = picked.expect("z_wr_addr changes too rarely");
    // The change is first seen at the first rising edge after it (values are sampled just before an
    // edge); make sure the signal does not change again before that edge.
    let cycle = edges.iter().position(|&e| e > t).unwrap();
    let mut tt = t;
    for l in &lines[line + 1..] {
        if let Some(n) = l.strip_prefix('#') {
            tt = n.trim().parse().unwrap();
            if tt >= edges[cycle] {
                break;
            }
        } else {
            assert!(!(l.split_whitespace().nth(1) == Some(sig.as_str()) && tt < edges[cycle]), "z_wr_addr changes twice in cycle {cycle}");
        }
    }
    let old = lines[line].split_whitespace().next().unwrap();
    let flipped = format!("{}{}", &old[..old.len() - 1], if old.ends_with('0') { '1' } else { '0' });
    let mut edited: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
    edited[line] = format!("{flipped} {sig}");
    let broken = dir().join("icarus_edited.vcd");
    std::fs::write(&broken, edited.join("\n") + "\n").unwrap();

    let (code, out) = vcd_diff(rusthdl, &broken, &[]);
    assert_eq!(code, 1, "vcd-diff did not report the edit:\n{out}");
    let first = out.lines().next().unwrap();
    assert!(first.starts_with(&format!("first difference at cycle {cycle} ")), "expected cycle {cycle}:\n{out}");
    assert!(first.contains("time units): signal z_wr_addr: "), "expected signal z_wr_addr:\n{out}");
    assert!(first.contains(&format!(", {} in B,", edges[cycle])), "expected B's edge time {}:\n{out}", edges[cycle]);
    // The values shown are the original (A) and the edited one (B).
    let b_val = u64::from_str_radix(first.rsplit("B = 0x").next().unwrap().trim(), 16).unwrap();
    assert_eq!(b_val, u64::from_str_radix(flipped.trim_start_matches('b'), 2).unwrap(), "{out}");
}

/// A two-cycle flat trace with a 4-bit `x` and, if `real` is given, a real-valued `r` that takes that
/// value in the second cycle.
fn small_trace(dir: &Path, name: &str, real: Option<&str>, edges: bool) -> PathBuf {
    let mut v = String::from("$timescale 1ns $end\n$scope module top $end\n$var wire 1 ! clock $end\n$var wire 4 \" x $end\n");
    if real.is_some() {
        v.push_str("$var real 1 # r $end\n");
    }
    v.push_str("$upscope $end\n$enddefinitions $end\n#0\n0!\nb0000 \"\n");
    if real.is_some() {
        v.push_str("r1.5 #\n");
    }
    if edges {
        v.push_str("#5\n1!\n#10\n0!\n");
        if let Some(r) = real {
            v.push_str(&format!("r{r} #\n"));
        }
        v.push_str("#15\n1!\n#20\n0!\n");
    }
    let p = dir.join(name);
    std::fs::write(&p, v).unwrap();
    p
}

/// Issue 18: vcd-diff called two traces equal when a signal was missing from one, and when neither
/// had a cycle; real-valued signals are compared by value.
#[test]
fn a_missing_signal_or_no_cycle_at_all_is_not_equal_and_reals_are_compared() {
    let dir = std::env::temp_dir().join(format!("idxrender-vcd-small-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (a, b) = (small_trace(&dir, "a.vcd", Some("2.5"), true), small_trace(&dir, "b.vcd", Some("3.5"), true));
    let (code, out) = vcd_diff(&a, &b, &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("signal r: A = \"2.5\", B = \"3.5\""), "{out}");
    let plain = small_trace(&dir, "plain.vcd", None, true);
    let (code, out) = vcd_diff(&a, &plain, &[]);
    assert_eq!(code, 1, "a signal only in A made the traces equal:\n{out}");
    assert!(out.contains("missing from B: r"), "{out}");
    let still = small_trace(&dir, "still.vcd", None, false);
    let (code, out) = vcd_diff(&still, &still, &[]);
    assert_eq!(code, 2, "{out}");
    assert!(out.contains("no cycle to compare"), "{out}");
}

/// A structured trace (RustHDL's: ports in sub-scopes) whose port `cmd$valid` changes, against a flat
/// trace without it: a missing port, not equal. A variable of the top that never changes (a constant
/// such as rust-hdl's `k0_20`) is only listed.
#[test]
fn a_changing_port_missing_from_a_flat_trace_is_a_difference() {
    let dir = std::env::temp_dir().join(format!("idxrender-vcd-port-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let structured = "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 4 \" x $end\n$var wire 2 $ k0 $end\n\
        $scope module cmd $end\n$var wire 1 # valid $end\n$upscope $end\n$upscope $end\n$enddefinitions $end\n\
        #0\n0!\nb0000 \"\nb10 $\n0#\n#5\n1!\n#10\n0!\n1#\n#15\n1!\n#20\n0!\n";
    let a = dir.join("structured.vcd");
    std::fs::write(&a, structured).unwrap();
    let b = small_trace(&dir, "flat.vcd", None, true);
    let (code, out) = vcd_diff(&a, &b, &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("ports of A missing from B: cmd$valid") && out.contains("only in A (nets or constants, not known to be ports): k0"), "{out}");
}

/// The two traces' identifier codes are separate name spaces: here A's `b` and B's `a` share a code,
/// and so do A's `a` and B's `b`. Both signals are compared, and a difference in `b` is found (one set
/// of compared codes for both traces once skipped `b` as compared already).
#[test]
fn signals_whose_codes_cross_between_the_traces_are_each_compared() {
    let d = dir();
    let vcd = |codes: [&str; 2], b_value: &str| {
        format!(
            "$timescale 1ns $end\n$scope module top $end\n$var wire 1 ! clock $end\n$var wire 4 {} a $end\n$var wire 4 {} b $end\n$upscope $end\n$enddefinitions $end\n\
             #0\n0!\nb0011 {}\nb{b_value} {}\n#5\n1!\n#10\n0!\n#15\n1!\n",
            codes[0], codes[1], codes[0], codes[1]
        )
    };
    let (a, b) = (d.join("cross_a.vcd"), d.join("cross_b.vcd"));
    std::fs::write(&a, vcd(["\"", "#"], "0101")).unwrap();
    std::fs::write(&b, vcd(["#", "\""], "0101")).unwrap();
    let (code, out) = vcd_diff(&a, &b, &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("compared: a, b"), "{out}");
    std::fs::write(&b, vcd(["#", "\""], "0110")).unwrap();
    let (code, out) = vcd_diff(&a, &b, &[]);
    assert_ne!(code, 0, "a difference in b was missed:\n{out}");
    assert!(out.contains(" b"), "{out}");
}
