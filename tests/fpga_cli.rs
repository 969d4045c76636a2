//! `idxrender fpga-report` on one small top and one device: yosys + nextpnr run, and the table has
//! numeric cell counts and either an Fmax or the reason the top does not fit.

use std::path::PathBuf;
use std::process::Command;
use tb::common::require_tools;

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target").join("test-cli").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The smallest top in generated Verilog lines (the PROOF shading stage today), found rather than named.
fn smallest_top() -> &'static str {
    hdl::TOPS.iter().map(|t| t.0).min_by_key(|t| hdl::verilog_top(t).map(|v| v.len()).unwrap_or(usize::MAX)).unwrap()
}

#[test]
fn fpga_report_on_the_smallest_top_gives_cell_counts_and_an_fmax_or_a_reason() {
    if !require_tools("fpga_report_on_the_smallest_top_gives_cell_counts_and_an_fmax_or_a_reason", &["yosys", "nextpnr-ice40"]) {
        return;
    }
    let top = smallest_top();
    let dir = scratch("fpga_report");
    let out = dir.join("report.md");
    let t0 = std::time::Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_idxrender"))
        .args(["fpga-report", "--block", top, "--device", "up5k", "--timeout", "300", "--out"])
        .arg(&out)
        .arg("--work")
        .arg(dir.join("work"))
        .output()
        .unwrap();
    let log = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "fpga-report failed:\n{log}");
    println!("fpga-report --block {top} --device up5k: {:.0} s\n{log}", t0.elapsed().as_secs_f64());
    let md = std::fs::read_to_string(&out).unwrap();
    let rows: Vec<&str> = md.lines().filter(|l| l.starts_with(&format!("| `{top}` |"))).collect();
    assert_eq!(rows.len(), 1, "expected one row for {top} on up5k:\n{md}");
    let cells: Vec<&str> = rows[0].split('|').map(str::trim).collect();
    // | top | device | LUT4 | FF | CARRY | BRAM | DSP | Fmax or reason | wrapper | device LCs | time |
    assert_eq!(cells[2], "up5k");
    let num = |i: usize| cells[i].parse::<u64>().unwrap_or_else(|_| panic!("column {i} is not a number: {}", rows[0]));
    let (lut, ff) = (num(3), num(4));
    assert!(lut > 0 && ff > 0, "no logic: {}", rows[0]);
    for i in 5..=7 {
        num(i);
    }
    let fmax = cells[8];
    assert!(fmax.parse::<f64>().is_ok_and(|f| f > 0.0) || fmax.starts_with("does not fit: needs "), "neither an Fmax nor a reason: {fmax}");
    // The yosys log has the same count for the top's own module.
    let ylog = std::fs::read_to_string(dir.join("work").join(top).join("yosys_dsp.log")).unwrap();
    let section = &ylog[ylog.rfind(&format!("=== {top} ===")).unwrap()..];
    let lut_in_log: u64 = section.lines().find_map(|l| l.trim().strip_prefix("SB_LUT4").map(|n| n.trim().parse().unwrap())).unwrap();
    assert_eq!(lut, lut_in_log);
}

#[test]
fn fpga_report_rejects_an_unknown_block() {
    let dir = scratch("fpga_report_unknown");
    let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).args(["fpga-report", "--block", "nosuch", "--out"]).arg(dir.join("r.md")).output().unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("unknown block 'nosuch'"), "{err}");
}

#[test]
fn fpga_report_takes_an_opp_size_only_for_the_opp_and_never_zero() {
    let dir = scratch("fpga_report_opp_ops");
    for (args, needle) in [(vec!["--block", "rc", "--opp-ops", "16"], "--opp-ops applies to --block opp"), (vec!["--block", "opp", "--opp-ops", "0"], "at least one object processor")] {
        let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).arg("fpga-report").args(&args).arg("--out").arg(dir.join("r.md")).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains(needle), "{args:?}: {err}");
    }
}

/// The ECP5 speed grade is 6, 7 or 8; anything else is refused by name before any tool runs.
#[test]
fn fpga_report_refuses_an_ecp5_speed_grade_the_part_does_not_come_in() {
    let dir = scratch("fpga_report_speed");
    for bad in ["5", "9", "fast"] {
        let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).args(["fpga-report", "--block", "rc", "--speed", bad, "--out"]).arg(dir.join("r.md")).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains("--speed") && err.contains(bad), "--speed {bad}: {err}");
    }
    assert!(!dir.join("r.md").exists());
}

/// `--out` is checked before any synthesis (issue 18: `--out report.json` used to write the JSON over the
/// Markdown name, and a bad folder was found only after the tools had run).
#[test]
fn fpga_report_checks_its_output_path_before_any_synthesis() {
    let dir = scratch("fpga_report_out");
    let run = |out: &std::path::Path| {
        let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).args(["fpga-report", "--block", "chipset", "--out"]).arg(out).output().unwrap();
        (o.status.success(), String::from_utf8_lossy(&o.stderr).to_string())
    };
    let (ok, err) = run(&dir.join("report.json"));
    assert!(!ok && err.contains("name the Markdown file (ending in .md)"), "{err}");
    assert!(!dir.join("report.json").exists() && !dir.join("report.md").exists());
    let file = dir.join("a-file");
    std::fs::write(&file, "not a folder").unwrap();
    let (ok, err) = run(&file.join("r.md"));
    assert!(!ok && err.contains("--out") && err.contains("cannot create"), "{err}");
}

/// `scripts/clock-cuts.py` (the what-if cuts of docs/clock.md, "How far each cut goes") still finds
/// every path it cuts in the Verilog generated today, and yosys elaborates what it writes; a cut
/// asked of a top without that path is an error, not a silent no-op.
#[test]
fn the_clock_cuts_apply_to_the_generated_verilog_and_yosys_elaborates_the_result() {
    if !require_tools("the_clock_cuts_apply_to_the_generated_verilog_and_yosys_elaborates_the_result", &["python3", "yosys"]) {
        return;
    }
    let dir = scratch("clock_cuts");
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scripts").join("clock-cuts.py");
    for (top, cuts, added) in [("rc", &["walk", "grad"][..], "walk_end_r <= walk_end"), ("cs", &["norm"][..], "a <= a_in")] {
        let src = dir.join(format!("{top}.v"));
        let cut = dir.join(format!("{top}_cut.v"));
        std::fs::write(&src, hdl::verilog_top(top).unwrap()).unwrap();
        let o = Command::new("python3").arg(&script).arg(&src).arg(&cut).args(cuts).output().unwrap();
        assert!(o.status.success(), "clock-cuts.py {top} {cuts:?}: {}", String::from_utf8_lossy(&o.stderr));
        let text = std::fs::read_to_string(&cut).unwrap();
        assert!(text.contains(added), "{top}: the cut's register is not in the output");
        let clocks = text.matches(".clock(clock),").count() - std::fs::read_to_string(&src).unwrap().matches(".clock(clock),").count();
        // rc: `mul_g`; cs: the three squares.
        assert_eq!(clocks, if top == "rc" { 1 } else { 3 }, "{top}: leaves given a clock by the cuts");
        let y = Command::new("yosys").args(["-q", "-p"]).arg(format!("read_verilog {}; hierarchy -check -top {top}; proc", cut.display())).output().unwrap();
        assert!(y.status.success(), "yosys does not elaborate the cut {top}:\n{}", String::from_utf8_lossy(&y.stderr));
    }
    let o = Command::new("python3").arg(&script).arg(dir.join("cs.v")).arg(dir.join("bad.v")).arg("walk").output().unwrap();
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("modules end in `$front$traversal`"), "a cut of a missing path must fail");
    assert!(!dir.join("bad.v").exists(), "a failed cut wrote its output");
}
