//! Level 3 for PROOF: the generated Verilog of an OPP replays vectors recorded from a bench run (every
//! cycle's inputs and the cycle model's outputs) in a self-checking Verilog testbench, under Icarus
//! Verilog or Verilator (`--binary`). This is what shows that the Verilog means what the RustHDL
//! simulation meant.

use super::convert::{hex_of, params_to_rtl, slot_to_rtl};
use golden::proof::cycle_opp::{OppIn, OppOut};
use hdl::proof::{ObjParams, ProofSlot};
use rust_hdl::prelude::*;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

/// One line per cycle: inputs, then expected outputs, in hex.
pub struct VectorWriter {
    out: BufWriter<File>,
    pub path: PathBuf,
    pub cycles: u64,
}

impl VectorWriter {
    pub fn create(path: PathBuf) -> Result<VectorWriter, String> {
        let f = File::create(&path).map_err(|e| format!("cannot create {}: {e}", path.display()))?;
        Ok(VectorWriter { out: BufWriter::new(f), path, cycles: 0 })
    }

    pub fn cycle(&mut self, inp: &OppIn, exp: &OppOut) -> Result<(), String> {
        let params: Bits<{ ObjParams::BITS }> = params_to_rtl(&inp.load.map(|l| l.1).unwrap_or_default()).into();
        let up: Bits<{ ProofSlot::BITS }> = slot_to_rtl(&inp.up_data).into();
        let down: Bits<{ ProofSlot::BITS }> = slot_to_rtl(&exp.down_data).into();
        let any_free = exp.free.iter().any(|&f| f);
        let free_op = exp.free.iter().rposition(|&f| f).unwrap_or(0);
        writeln!(
            self.out,
            "{} {:04x} {} {} {} {} {} {} {} {} {:04x}",
            inp.load.is_some() as u8,
            inp.load.map(|l| l.0).unwrap_or(0),
            hex_of(params),
            inp.up_valid as u8,
            hex_of(up),
            inp.down_ready as u8,
            exp.up_ready as u8,
            exp.down_valid as u8,
            hex_of(down),
            any_free as u8,
            free_op
        )
        .map_err(|e| format!("{}: {e}", self.path.display()))?;
        self.cycles += 1;
        Ok(())
    }

    pub fn finish(mut self) -> Result<(PathBuf, u64), String> {
        self.out.flush().map_err(|e| format!("{}: {e}", self.path.display()))?;
        Ok((self.path, self.cycles))
    }
}

/// The self-checking testbench: inputs change after the falling edge, outputs are compared just
/// before the rising edge; prints `REPLAY PASSED <cycles>` or the first mismatch.
pub fn testbench(top: &str, vectors: &Path, cycles: u64) -> String {
    let (pw, sw) = (ObjParams::BITS, ProofSlot::BITS);
    format!(
        r#"`timescale 1ns/1ps
module tb_{top};
  reg clock = 0;
  reg load = 0; reg [15:0] load_op = 0; reg [{pm}:0] load_params = 0;
  reg up_valid = 0; reg [{sm}:0] up_data = 0; reg down_ready = 0;
  wire up_ready, down_valid, any_free; wire [{sm}:0] down_data; wire [15:0] free_op;
  reg e_up_ready, e_down_valid, e_any_free; reg [{sm}:0] e_down_data; reg [15:0] e_free_op;
  // $fscanf reads into these; plain assignments then drive the inputs (Verilator does not wake
  // combinational logic on variables written by $fscanf).
  reg t_load, t_up_valid, t_down_ready; reg [15:0] t_load_op; reg [{pm}:0] t_load_params; reg [{sm}:0] t_up_data;
  integer fd, r, cyc, errors;
  {top} uut(.clock(clock), .load(load), .load_op(load_op), .load_params(load_params),
    .upstream$data(up_data), .upstream$valid(up_valid), .upstream$ready(up_ready),
    .downstream$data(down_data), .downstream$valid(down_valid), .downstream$ready(down_ready),
    .any_free(any_free), .free_op(free_op));
  initial begin
    fd = $fopen("{vec}", "r");
    errors = 0;
    for (cyc = 0; cyc < {cycles}; cyc = cyc + 1) begin
      r = $fscanf(fd, "%h %h %h %h %h %h %h %h %h %h %h\n", t_load, t_load_op, t_load_params, t_up_valid, t_up_data, t_down_ready,
                  e_up_ready, e_down_valid, e_down_data, e_any_free, e_free_op);
      if (r != 11) begin $display("REPLAY FAILED: bad vector line %0d", cyc); $finish; end
      load = t_load; load_op = t_load_op; load_params = t_load_params;
      up_valid = t_up_valid; up_data = t_up_data; down_ready = t_down_ready;
      #4;
      if (up_ready !== e_up_ready || down_valid !== e_down_valid || down_data !== e_down_data
          || any_free !== e_any_free || free_op !== e_free_op) begin
        $display("REPLAY FAILED at cycle %0d: up_ready %b/%b down_valid %b/%b any_free %b/%b free_op %h/%h", cyc,
                 up_ready, e_up_ready, down_valid, e_down_valid, any_free, e_any_free, free_op, e_free_op);
        $display("  down_data got %h", down_data);
        $display("  down_data exp %h", e_down_data);
        errors = errors + 1;
        $finish;
      end
      #1 clock = 1;
      #5 clock = 0;
    end
    $display("REPLAY PASSED %0d", {cycles});
    $finish;
  end
endmodule
"#,
        pm = pw - 1,
        sm = sw - 1,
        vec = vectors.display(),
    )
}

/// Replay `vectors` on `verilog` (top module `top`) under `sim` ("iverilog" or "verilator");
/// returns the simulator's report line.
pub fn replay(sim: &str, dir: &Path, top: &str, verilog: &str, vectors: &Path, cycles: u64) -> Result<String, String> {
    let dut = dir.join(format!("{top}.v"));
    let tbv = dir.join(format!("tb_{top}.v"));
    std::fs::write(&dut, verilog).map_err(|e| e.to_string())?;
    std::fs::write(&tbv, testbench(top, vectors, cycles)).map_err(|e| e.to_string())?;
    let run = |c: &mut Command| -> Result<String, String> {
        let o = c.output().map_err(|e| format!("cannot run {c:?}: {e}"))?;
        let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        if !o.status.success() {
            return Err(format!("{c:?} failed:\n{text}"));
        }
        Ok(text)
    };
    let out = match sim {
        "iverilog" => {
            let exe = dir.join(format!("tb_{top}.vvp"));
            run(Command::new("iverilog").args(["-g2012", "-o"]).arg(&exe).arg(&tbv).arg(&dut))?;
            run(Command::new("vvp").arg("-n").arg(&exe))?
        }
        "verilator" => {
            let mdir = dir.join("obj_dir");
            run(Command::new("verilator")
                .args(["--binary", "-O2", "-j", "2", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSEDPARAM", "-Wno-STMTDLY", "-Wno-INITIALDLY"])
                .args(["--top-module", &format!("tb_{top}"), "-Mdir"])
                .arg(&mdir)
                .arg(&tbv)
                .arg(&dut))?;
            run(&mut Command::new(mdir.join(format!("Vtb_{top}"))))?
        }
        _ => return Err(format!("unknown simulator {sim}")),
    };
    match out.lines().find(|l| l.contains("REPLAY")) {
        Some(l) if l.contains("PASSED") => Ok(l.trim().to_string()),
        Some(_) => Err(out),
        None => Err(format!("no verdict from {sim}:\n{out}")),
    }
}
