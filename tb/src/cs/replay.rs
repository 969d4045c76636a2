//! Level 3 of the verification (STYLE.md §5): the generated Verilog replays vectors recorded from the
//! RustHDL bench (inputs applied every cycle, outputs the cycle model expects every cycle) in a
//! self-checking Icarus Verilog testbench, and the first mismatches are reported by port and cycle.
//! Also the lint (`verilator --lint-only -Wall`, named waivers) and synthesis (`yosys synth_ice40 -dsp`)
//! checks of the blocks.

use crate::cs::pack::BitVector;
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

/// A port of the top module: its Verilog name and width.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PortSpec {
    pub name: String,
    pub width: usize,
}

pub fn port(name: &str, width: usize) -> PortSpec {
    PortSpec { name: name.to_string(), width }
}

/// Per-cycle vectors: `vin[c]` are the inputs applied in cycle c (the `clock` port excluded), `vout[c]`
/// the outputs expected before the rising edge of cycle c. Fields are in port order, first port in
/// the least significant bits.
#[derive(Clone, Debug, Default)]
pub struct Recording {
    pub inputs: Vec<PortSpec>,
    pub outputs: Vec<PortSpec>,
    pub vin: Vec<BitVector>,
    pub vout: Vec<BitVector>,
}

impl Recording {
    pub fn new(inputs: Vec<PortSpec>, outputs: Vec<PortSpec>) -> Recording {
        Recording { inputs, outputs, vin: Vec::new(), vout: Vec::new() }
    }
    fn width(ports: &[PortSpec]) -> usize {
        ports.iter().map(|p| p.width).sum()
    }
    pub fn push(&mut self, vin: BitVector, vout: BitVector) {
        assert_eq!(vin.len(), Self::width(&self.inputs), "input vector width");
        assert_eq!(vout.len(), Self::width(&self.outputs), "output vector width");
        self.vin.push(vin);
        self.vout.push(vout);
    }
    pub fn cycles(&self) -> usize {
        self.vin.len()
    }
}

fn ident(name: &str) -> String {
    name.replace('$', "_")
}

/// The self-checking testbench for `top` and this recording.
pub fn testbench(top: &str, rec: &Recording) -> String {
    testbench_for(top, rec, rec.cycles())
}

/// The self-checking testbench for `top`, the ports of `rec` and recordings of up to `capacity`
/// cycles: it replays `rec.cycles()` of them, or `+cycles=N` given at run time (one build for several
/// recordings of the same ports, [`replay_verilator_all`]).
fn testbench_for(top: &str, rec: &Recording, capacity: usize) -> String {
    let wi = Recording::width(&rec.inputs);
    let wo = Recording::width(&rec.outputs);
    let n = rec.cycles();
    let mut s = String::new();
    let _ = writeln!(s, "`timescale 1ns/1ps\nmodule replay_tb;");
    let _ = writeln!(s, "  reg clock = 1'b0;\n  reg [{}:0] vin [0:{}];\n  reg [{}:0] vout [0:{}];", wi - 1, capacity - 1, wo - 1, capacity - 1);
    let _ = writeln!(s, "  reg [{}:0] cur_in;\n  reg [{}:0] cur_out;", wi - 1, wo - 1);
    let mut off = 0;
    for p in &rec.inputs {
        let _ = writeln!(s, "  wire [{}:0] in_{} = cur_in[{}:{}];", p.width - 1, ident(&p.name), off + p.width - 1, off);
        off += p.width;
    }
    for p in &rec.outputs {
        let _ = writeln!(s, "  wire [{}:0] out_{};", p.width - 1, ident(&p.name));
    }
    let mut conns = vec![".clock(clock)".to_string()];
    conns.extend(rec.inputs.iter().map(|p| format!(".{}(in_{})", p.name, ident(&p.name))));
    conns.extend(rec.outputs.iter().map(|p| format!(".{}(out_{})", p.name, ident(&p.name))));
    let _ = writeln!(s, "  {top} dut(\n    {}\n  );", conns.join(",\n    "));
    let _ = writeln!(s, "  integer cyc, errors, n;");
    let _ = writeln!(s, "  initial begin");
    let _ = writeln!(s, "    if (!$value$plusargs(\"cycles=%d\", n)) n = {n};");
    let _ = writeln!(s, "    $readmemh(\"in.hex\", vin);\n    $readmemh(\"out.hex\", vout);\n    errors = 0;");
    let _ = writeln!(s, "    for (cyc = 0; cyc < n; cyc = cyc + 1) begin");
    let _ = writeln!(s, "      cur_in = vin[cyc];\n      cur_out = vout[cyc];\n      clock = 1'b0;\n      #5;");
    let mut off = 0;
    for p in &rec.outputs {
        let id = ident(&p.name);
        let hi = off + p.width - 1;
        let _ = writeln!(
            s,
            "      if (out_{id} !== cur_out[{hi}:{off}]) begin\n        $display(\"MISMATCH cycle %0d port {name} expected %h actual %h\", cyc, cur_out[{hi}:{off}], out_{id});\n        errors = errors + 1;\n      end",
            name = p.name
        );
        off += p.width;
    }
    let _ = writeln!(s, "      if (errors >= 8) begin\n        $display(\"REPLAY STOPPED errors %0d\", errors);\n        $finish;\n      end");
    let _ = writeln!(s, "      clock = 1'b1;\n      #5;\n    end");
    let _ = writeln!(s, "    $display(\"REPLAY DONE cycles %0d errors %0d\", n, errors);\n    $finish;\n  end\nendmodule");
    s
}

/// Outcome of a replay.
#[derive(Clone, Debug)]
pub struct ReplayReport {
    pub cycles: usize,
    pub seconds: f64,
}

/// Write the top's Verilog, the testbench and the vectors of `rec` into `dir`.
fn write_replay(verilog: &str, top: &str, rec: &Recording, dir: &Path) -> Result<(), String> {
    write_replay_for(verilog, top, rec, rec.cycles(), dir)
}

/// [`write_replay`] with a testbench for up to `capacity` cycles.
fn write_replay_for(verilog: &str, top: &str, rec: &Recording, capacity: usize, dir: &Path) -> Result<(), String> {
    if rec.cycles() == 0 {
        return Err("replay: empty recording".into());
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("replay: cannot create {}: {e}", dir.display()))?;
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).map_err(|e| format!("replay: cannot write {name}: {e}"));
    write(&format!("{top}.v"), verilog)?;
    write("replay_tb.v", &testbench_for(top, rec, capacity))?;
    write_vectors(rec, dir)
}

/// The vectors of `rec` as `in.hex` and `out.hex` in `dir`.
fn write_vectors(rec: &Recording, dir: &Path) -> Result<(), String> {
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).map_err(|e| format!("replay: cannot write {name}: {e}"));
    write("in.hex", &rec.vin.iter().map(|v| v.hex() + "\n").collect::<String>())?;
    write("out.hex", &rec.vout.iter().map(|v| v.hex() + "\n").collect::<String>())
}

/// Run the built testbench (`cmd` in `dir`, bounded in time) and judge what it printed.
fn run_replay(cmd: &[&str], sim: &str, top: &str, rec: &Recording, dir: &Path) -> Result<ReplayReport, String> {
    let t0 = std::time::Instant::now();
    // A zero-delay oscillation (a combinational loop that Icarus cannot settle) would run forever:
    // bound the run (Icarus replays these designs at > 5k cycles/s, `cs_tex` excepted).
    let limit = (60 + rec.cycles() / 500).to_string();
    let out = Command::new("timeout")
        .current_dir(dir)
        .arg(&limit)
        .args(cmd)
        .output()
        .map_err(|e| format!("replay: cannot run {sim}: {e}"))?;
    let seconds = t0.elapsed().as_secs_f64();
    if out.status.code() == Some(124) {
        return Err(format!("replay of {top}: {sim} did not finish {} cycles in {limit} s (a combinational loop that never settles?); files in {}", rec.cycles(), dir.display()));
    }
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let mismatches: Vec<&str> = text.lines().filter(|l| l.starts_with("MISMATCH")).collect();
    if !mismatches.is_empty() {
        return Err(format!(
            "the Verilog of {top} differs from the cycle model ({} shown, files in {}):\n{}",
            mismatches.len(),
            dir.display(),
            mismatches.join("\n")
        ));
    }
    let done = format!("REPLAY DONE cycles {} errors 0", rec.cycles());
    if !text.contains(&done) {
        return Err(format!("replay of {top} did not finish cleanly:\n{text}\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    Ok(ReplayReport { cycles: rec.cycles(), seconds })
}

/// Replay `rec` on the Verilog `verilog` (top module `top`) under Icarus Verilog in `dir`. Errors carry
/// the first mismatching ports with cycle, expected and actual values.
pub fn replay_iverilog(verilog: &str, top: &str, rec: &Recording, dir: &Path) -> Result<ReplayReport, String> {
    write_replay(verilog, top, rec, dir)?;
    let out = Command::new("iverilog")
        .current_dir(dir)
        .args(["-g2005", "-o", "replay.vvp", "replay_tb.v", &format!("{top}.v")])
        .output()
        .map_err(|e| format!("replay: cannot run iverilog: {e}"))?;
    if !out.status.success() {
        return Err(format!("replay: iverilog failed to compile {top}:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    run_replay(&["vvp", "-n", "replay.vvp"], "vvp", top, rec, dir)
}

/// [`replay_iverilog`] under Verilator (`--binary --timing`, the same testbench), for tops that Icarus
/// replays too slowly: on `cs_tex` Icarus managed about 2 cycles per second (its one large always
/// block re-runs for every change of the texture unit's outputs), Verilator the whole run in 0.1 s
/// after a 15 s build.
pub fn replay_verilator(verilog: &str, top: &str, rec: &Recording, dir: &Path) -> Result<ReplayReport, String> {
    replay_verilator_all(verilog, top, std::slice::from_ref(rec), dir).map(|mut r| r.remove(0))
}

/// [`replay_verilator`] of several recordings of the same ports, one after another, each from the
/// top's initial state (a new run of the one Verilator build, which takes most of the time: about
/// 15 s on `cs_tex`, its Yosys netlist longer). The first failing recording ends it.
pub fn replay_verilator_all(verilog: &str, top: &str, recs: &[Recording], dir: &Path) -> Result<Vec<ReplayReport>, String> {
    let first = recs.first().ok_or("replay: no recording")?;
    if let Some(k) = recs.iter().position(|r| r.inputs != first.inputs || r.outputs != first.outputs) {
        return Err(format!("replay: recording {k} has other ports than recording 0"));
    }
    let capacity = recs.iter().map(|r| r.cycles()).max().unwrap_or(0);
    write_replay_for(verilog, top, first, capacity, dir)?;
    let _ = std::fs::remove_dir_all(dir.join("obj_dir"));
    let out = Command::new("verilator")
        .current_dir(dir)
        .args(["--binary", "--timing", "-O2", "-Wno-fatal", "-Wno-lint", "-Wno-style", "-Wno-UNOPTFLAT", "--top-module", "replay_tb", "replay_tb.v", &format!("{top}.v")])
        .output()
        .map_err(|e| format!("replay: cannot run verilator: {e}"))?;
    if !out.status.success() {
        return Err(format!("replay: verilator failed to build {top}:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    let mut reports = Vec::new();
    for (k, rec) in recs.iter().enumerate() {
        if k > 0 {
            write_vectors(rec, dir)?;
        }
        let cycles = format!("+cycles={}", rec.cycles());
        let r = run_replay(&["./obj_dir/Vreplay_tb", &cycles], "the Verilator model", top, rec, dir)
            .map_err(|e| if recs.len() > 1 { format!("recording {k} of {}: {e}", recs.len()) } else { e })?;
        reports.push(r);
    }
    Ok(reports)
}

/// Cell counts of `yosys synth_ice40 -dsp`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SynthFigures {
    pub lut4: u64,
    pub carry: u64,
    pub ff: u64,
    pub bram: u64,
    pub dsp: u64,
    pub latches: u64,
}

/// Synthesize with `yosys synth_ice40 -dsp` and count cells; latches are an error.
pub fn synth_ice40(verilog: &str, top: &str, dir: &Path) -> Result<SynthFigures, String> {
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    let file = dir.join(format!("{top}.v"));
    std::fs::write(&file, verilog).map_err(|e| e.to_string())?;
    let script = format!("read_verilog {}; synth_ice40 -dsp -top {top}; stat", file.display());
    let out = Command::new("yosys").current_dir(dir).args(["-q", "-l", "synth.log", "-p", &script]).output().map_err(|e| format!("cannot run yosys: {e}"))?;
    let log = std::fs::read_to_string(dir.join("synth.log")).unwrap_or_default();
    if !out.status.success() {
        return Err(format!("yosys synth_ice40 of {top} failed:\n{}\n{}", String::from_utf8_lossy(&out.stderr), log));
    }
    // The last `stat` block: "   <count>   <cell>" lines (yosys 0.23 prints "     123   SB_LUT4").
    let stat = &log[log.rfind("Number of cells").unwrap_or(0)..];
    let count = |cell: &str| -> u64 {
        stat.lines()
            .filter_map(|l| {
                let mut it = l.split_whitespace();
                let (a, b) = (it.next()?, it.next()?);
                if b == cell {
                    a.parse::<u64>().ok()
                } else if a == cell {
                    b.parse::<u64>().ok()
                } else {
                    None
                }
            })
            .sum()
    };
    let ff: u64 = ["SB_DFF", "SB_DFFE", "SB_DFFSR", "SB_DFFR", "SB_DFFS", "SB_DFFESR", "SB_DFFER", "SB_DFFES", "SB_DFFSS", "SB_DFFESS"]
        .iter()
        .map(|c| count(c))
        .sum();
    let latches = log.lines().filter(|l| l.contains("Latch inferred")).count() as u64 + count("$_DLATCH_P_") + count("$_DLATCH_N_");
    let f = SynthFigures {
        lut4: count("SB_LUT4"),
        carry: count("SB_CARRY"),
        ff,
        bram: count("SB_RAM40_4K"),
        dsp: count("SB_MAC16"),
        latches,
    };
    if f.latches > 0 {
        return Err(format!("yosys inferred {} latch(es) in {top}; see {}", f.latches, dir.join("synth.log").display()));
    }
    Ok(f)
}
