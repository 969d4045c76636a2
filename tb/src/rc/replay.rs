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
        let res = RcResult {
            eof: exp.res.eof,
            index: (exp.res.index as u64).into(),
            culled: exp.res.culled,
            zero_area: exp.res.zero_area,
            visible: exp.res.visible,
        };
        let res: Bits<{ RcResult::BITS }> = res.into();
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
            run(c.arg(harness()).arg(&rc_v), "iverilog")?;
            let mut c = Command::new("vvp");
            c.arg("-n").arg(&exe).arg(&plusarg);
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
                    .arg(&rc_v),
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
