//! Level 3 of the verification: the generated Verilog of `rc` replays the vectors recorded from a
//! bench run (inputs and the cycle model's outputs, every cycle) in the self-checking testbench
//! `tb/verilator/rc/tb_rc.v`, under Icarus or Verilator. This is what shows that RustHDL's Verilog
//! means what its simulation meant.

use super::pack::command_word;
use crate::common::scratch_dir;
use golden::cycle::rc::{RcInputs, RcOutputs};
use golden::format::Screen;
use hdl::rc::{RcCommand, RcResult};
use rust_hdl::prelude::*;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The result port's word the model expects.
fn result_word(exp: &RcOutputs) -> Bits<{ RcResult::BITS }> {
    RcResult {
        eof: exp.res.eof,
        index: (exp.res.index as u64).into(),
        culled: exp.res.culled,
        zero_area: exp.res.zero_area,
        visible: exp.res.visible,
    }
    .into()
}

/// Writes one line per cycle: the inputs, then the expected outputs, all in hex.
pub struct VectorWriter {
    out: BufWriter<File>,
    pub path: PathBuf,
    pub cycles: u64,
}

fn hex_of<const N: usize>(b: Bits<N>) -> String {
    let digits = N.div_ceil(4);
    (0..digits)
        .rev()
        .map(|d| {
            let nibble = (0..4).filter(|j| 4 * d + j < N && b.get_bit(4 * d + j)).map(|j| 1u32 << j).sum::<u32>();
            char::from_digit(nibble, 16).unwrap()
        })
        .collect()
}

impl VectorWriter {
    pub fn create(path: PathBuf) -> Result<VectorWriter, String> {
        let f = File::create(&path).map_err(|e| format!("cannot create {}: {e}", path.display()))?;
        Ok(VectorWriter { out: BufWriter::new(f), path, cycles: 0 })
    }

    pub fn cycle(&mut self, ty: golden::raster::RcType, inp: &RcInputs, exp: &RcOutputs) -> Result<(), String> {
        if ty != golden::raster::RcType::IV {
            return Err("the rc replay records the Type IV top's ports; rc3 records through super::replay3".into());
        }
        let cmd: Bits<{ RcCommand::BITS }> = command_word(&inp.cmd).into();
        let res = result_word(exp);
        writeln!(
            self.out,
            "{} {} {} {} {} {} {} {:05x} {} {:05x} {:06x} {} {:05x} {:04x}",
            inp.cmd_valid as u8,
            hex_of(cmd),
            inp.res_ready as u8,
            exp.cmd_ready as u8,
            exp.res_valid as u8,
            hex_of(res),
            exp.z_re as u8,
            exp.z_rd_addr,
            exp.z_we as u8,
            exp.z_wr_addr,
            exp.z_wr_data,
            exp.i_we as u8,
            exp.i_wr_addr,
            exp.i_wr_data
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

/// The Verilog simulators the replay runs under.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Simulator {
    Icarus,
    Verilator,
}

/// The self-checking testbench source.
pub fn harness() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("verilator").join("rc").join("tb_rc.v")
}

/// Write the RC's Verilog for a screen into `dir/rc.v`.
pub fn write_rc_verilog(screen: Screen, dir: &Path) -> Result<PathBuf, String> {
    let v = hdl::rc::verilog(screen.width, screen.height)?;
    let p = dir.join("rc.v");
    std::fs::write(&p, v).map_err(|e| format!("cannot write {}: {e}", p.display()))?;
    Ok(p)
}

fn run(cmd: &mut Command, what: &str) -> Result<String, String> {
    let o = cmd.output().map_err(|e| format!("{what}: cannot run: {e}"))?;
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    if !o.status.success() {
        return Err(format!("{what} failed ({}):\n{text}", o.status));
    }
    Ok(text)
}

/// Build the testbench with the RC for `screen` (once per screen and simulator; reused if built) and
/// replay `vectors`; returns the number of cycles checked.
pub fn replay(sim: Simulator, screen: Screen, vectors: &Path) -> Result<u64, String> {
    replay_dumping(sim, screen, vectors, None)
}

/// As [`replay`]; with `vcd` (Icarus only) the testbench also dumps the ports and top-level nets of
/// the `rc` instance (`$dumpvars(1, dut)`) into that file, for `idxrender vcd-diff`.
pub fn replay_dumping(sim: Simulator, screen: Screen, vectors: &Path, vcd: Option<&Path>) -> Result<u64, String> {
    if vcd.is_some() && sim != Simulator::Icarus {
        return Err("replay: VCD dumping is wired for Icarus only".into());
    }
    let tag = format!("rc_replay_{}x{}_{:?}", screen.width, screen.height, sim).to_lowercase();
    let dir = scratch_dir(&tag);
    let rc_v = write_rc_verilog(screen, &dir)?;
    replay_verilog(sim, screen, &rc_v, &dir, vectors, vcd)
}

/// As [`replay_dumping`], of the module `rc` in the Verilog file `rc_v` (the generated one, or a
/// mutant of it), building in `dir`. Icarus runs under `timeout` (a mutant may never settle).
pub fn replay_verilog(sim: Simulator, screen: Screen, rc_v: &Path, dir: &Path, vectors: &Path, vcd: Option<&Path>) -> Result<u64, String> {
    let words = screen.pixels().to_string();
    let plusarg = format!("+vectors={}", vectors.display());
    let text = match sim {
        Simulator::Icarus => {
            let exe = dir.join(if vcd.is_some() { "tb_rc_vcd.vvp" } else { "tb_rc.vvp" });
            let mut c = Command::new("iverilog");
            c.args(["-g2012", "-o"]).arg(&exe).arg(format!("-Ptb_rc.WORDS={words}"));
            if vcd.is_some() {
                c.arg("-DDUMP_VCD");
            }
            run(c.arg(harness()).arg(rc_v), "iverilog")?;
            let mut c = Command::new("timeout");
            c.args(["600", "vvp", "-n"]).arg(&exe).arg(&plusarg);
            if let Some(v) = vcd {
                c.arg(format!("+vcd={}", v.display()));
            }
            run(&mut c, "vvp")?
        }
        Simulator::Verilator => {
            let obj = dir.join("obj");
            run(
                Command::new("verilator")
                    .args(["--binary", "--timing", "-O3", "-j", "2", "-Wno-fatal", "-Wno-lint", "-Wno-style", "--top-module", "tb_rc"])
                    .arg(format!("-GWORDS={words}"))
                    .arg("-Mdir")
                    .arg(&obj)
                    .args(["-o", "vtb_rc"])
                    .arg(harness())
                    .arg(rc_v),
                "verilator",
            )?;
            run(Command::new(obj.join("vtb_rc")).arg(&plusarg), "verilated testbench")?
        }
    };
    if let Some(line) = text.lines().find(|l| l.contains("TESTBENCH FAILED")) {
        return Err(format!("{sim:?} replay of {}: {line}", vectors.display()));
    }
    let passed = text
        .lines()
        .find_map(|l| l.strip_prefix("TESTBENCH PASSED ").and_then(|n| n.trim().parse::<u64>().ok()))
        .ok_or_else(|| format!("{sim:?} replay of {}: no verdict in the output:\n{text}", vectors.display()))?;
    Ok(passed)
}

/// What a bench run records every cycle for a Verilog replay: [`VectorWriter`] (the `rc` top and its
/// testbench with memory models) or [`Rc3Vectors`] (the `rc3` top, every port a column).
pub trait RcVectors {
    fn cycle(&mut self, ty: golden::raster::RcType, inp: &RcInputs, exp: &RcOutputs) -> Result<(), String>;
}

impl RcVectors for VectorWriter {
    fn cycle(&mut self, ty: golden::raster::RcType, inp: &RcInputs, exp: &RcOutputs) -> Result<(), String> {
        VectorWriter::cycle(self, ty, inp, exp)
    }
}

/// The ports of the Type III top `rc3` in the order [`Rc3Vectors`] writes them. Its memories' read
/// data are inputs like any other: the replay drives what the bench's memory models returned.
pub fn rc3_ports() -> Vec<crate::proof::replay::Port> {
    use crate::proof::replay::{inp, out};
    vec![
        inp("cmd$valid", 1),
        inp("cmd$data", RcCommand::BITS),
        inp("result$ready", 1),
        inp("i_rd_data", 16),
        inp("tdbv_rd_a", 40),
        inp("tdbv_rd_b", 40),
        inp("tdbv_rd_c", 56),
        out("cmd$ready", 1, None),
        out("result$valid", 1, None),
        out("result$data", RcResult::BITS, None),
        out("i_re", 1, None),
        out("i_rd_addr", 20, None),
        out("tdbv_re", 1, None),
        out("tdbv_rd_addr", 16, None),
        out("tdbv_we", 1, None),
        out("tdbv_wr_addr", 16, None),
        out("tdbv_wr_a", 40, None),
        out("tdbv_wr_b", 40, None),
        out("tdbv_wr_c", 56, None),
        out("i_we", 1, None),
        out("i_wr_addr", 20, None),
        out("i_wr_data", 16, None),
    ]
}

/// Records `rc3`'s ports every cycle (inputs, then the cycle model's outputs) for
/// `crate::proof::replay::replay`, the replay generated from a port list.
pub struct Rc3Vectors(pub crate::proof::replay::Recorder);

impl Rc3Vectors {
    pub fn create(path: PathBuf) -> Result<Rc3Vectors, String> {
        Ok(Rc3Vectors(crate::proof::replay::Recorder::create(path, &rc3_ports())?))
    }
}

impl RcVectors for Rc3Vectors {
    fn cycle(&mut self, ty: golden::raster::RcType, inp: &RcInputs, exp: &RcOutputs) -> Result<(), String> {
        if ty != golden::raster::RcType::III {
            return Err("Rc3Vectors records the Type III top".into());
        }
        let hex = |v: i64, bits: usize| format!("{:0w$x}", (v as u64) & (u64::MAX >> (64 - bits)), w = bits.div_ceil(4));
        let cmd: Bits<{ RcCommand::BITS }> = command_word(&inp.cmd).into();
        let res = result_word(exp);
        let t = inp.tdbv_rd_data;
        let w = exp.tdbv_wr_data;
        let row = vec![
            hex(inp.cmd_valid as i64, 1),
            hex_of(cmd),
            hex(inp.res_ready as i64, 1),
            hex(inp.i_rd_data as i64, 16),
            hex(t.a, 40),
            hex(t.b, 40),
            hex(t.c, 56),
            hex(exp.cmd_ready as i64, 1),
            hex(exp.res_valid as i64, 1),
            hex_of(res),
            hex(exp.z_re as i64, 1),
            hex(exp.z_rd_addr as i64, 20),
            hex(exp.tdbv_re as i64, 1),
            hex(exp.tdbv_rd_addr as i64, 16),
            hex(exp.tdbv_we as i64, 1),
            hex(exp.tdbv_wr_addr as i64, 16),
            hex(w.a, 40),
            hex(w.b, 40),
            hex(w.c, 56),
            hex(exp.i_we as i64, 1),
            hex(exp.i_wr_addr as i64, 20),
            hex(exp.i_wr_data as i64, 16),
        ];
        self.0.cycle(&row)
    }
}

/// Replay `rc3`'s recorded vectors on its generated Verilog for `screen` under `sim`.
pub fn replay_rc3(sim: Simulator, screen: Screen, vectors: &Path, cycles: u64) -> Result<String, String> {
    let tag = format!("rc3_replay_{}x{}_{:?}", screen.width, screen.height, sim).to_lowercase();
    let dir = scratch_dir(&tag);
    let v = hdl::rc::rc3::verilog(screen.width, screen.height)?;
    let sim = match sim {
        Simulator::Icarus => "iverilog",
        Simulator::Verilator => "verilator",
    };
    crate::proof::replay::replay(sim, &dir, "rc3", &rc3_ports(), &v, vectors, cycles)
}
