//! The Verilator backend: the generated Verilog of the `chipset` top (`hdl::chipset::verilog`),
//! compiled by Verilator with the C++ harness `tb/verilator/chipset/harness.cpp`, behind
//! `golden::render::Chipset`, so that the host program of the golden model drives the Verilog through
//! seed 001's two pipelines, frames back to back, as it drives the RustHDL simulation in
//! [`crate::chipset::RtlChipset`].
//!
//! ```text
//!   golden::render::render_frames_with (host)              verilated process (Vchipset)
//!   +------------------------------+  stdin: "frame ..." + +-------------------------------------+
//!   | VerilatorChipset::run        |  RC words, Phong      | harness.cpp: the host loop of       |
//!   |   queues every frame, "run"  |  constants; "run"     | RtlChipset::run, memories:          |
//!   |   answers "Q f p" with the   |--------------------->|  Z (W*H x 24), I (2 x W*H x 16),     |
//!   |   host's setup command       |<---------------------|  TdbS (2 x 2^16 x 424, VlWide<14>)  |
//!   |   (LowerPipeline::visible)   |  stdout: Q, results  |   <-> chipset.v (top `chipset`)     |
//!   +------------------------------+  + buffers (R), pixels (O), cycle stamps (F), D, progress  |
//!                                                         +-------------------------------------+
//! ```
//!
//! The harness runs the whole clock loop in C++; it stops only to ask Rust for the colour-setup
//! command of a triangle the RC reported visible (one pipe round trip per visible triangle), so the
//! host's lower pipeline is the golden host program itself. It drives the same handshakes, in the same
//! cycles, with the same random gaps and stalls ([`HostDrive`]), the same memory model (synchronous,
//! latency 1, read-before-write; the same garbage after reset) and the same cycle stamps as
//! `RtlChipset`, so [`PhaseCycles`] of both backends are equal for the same frames (tested).
//!
//! The executable is built once per screen size and trace kind into
//! `target/verilator/chipset_<W>x<H>[_trace|_trace_full]/` and reused while the hash of the Verilog,
//! the harness, the Verilator flags and `verilator --version` is unchanged (written in `hash` there).
//!
//! VCD: with a path, the harness is built with `--trace --trace-depth 1` (and `ports_vlt`, which switches the top module's own signals off) and dumps
//! the 53 top-level ports only (scope `uut`, `$` in port names as in the Verilog: `rc_cmd$data`), at
//! time 10*cycle with the clock low and 10*cycle + 5 after the rising edge: the same instants as
//! `RtlChipset`'s VCD of the same ports (whose scope is `uut` and whose streams are sub-scopes `rc_cmd`
//! with `data`, `valid`, `ready`), for a `vcd-diff` of the two. [`VcdScope::Full`] builds without the
//! depth limit (every signal).

pub mod shared_lib;

use crate::chipset::{HostDrive, PhaseCycles, PortTraffic, Progress, TexTraffic, VcdScope};
use golden::format::Plane;
use golden::raster::RcType;
use crate::common::workspace_target;
use crate::cs::pack::{command_of, rgb_of};
use crate::chipset::{depths_as_seen, FrameRun};
use crate::cs::color_shader_bench::config_ports;
use golden::cycle::colour_setup::SetupCmd;
use golden::format::Screen;
use golden::raster::{Culled, TriResult};
use golden::render::{Chipset, FrameJob, FrameOut, LowerPipeline, ScanOut};
use hdl::rc::{RcCommand, RcResult};
use rust_hdl::prelude::*;
use std::io::{BufRead, BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::Instant;

/// The harness source, compiled into this crate so that the cache key is what gets built.
pub const HARNESS_CPP: &str = include_str!("../../verilator/chipset/harness.cpp");

/// The Verilator warnings the build waives: those of `crate::lint::LINT_WAIVERS` that a build
/// without `-Wall` still reports (each with its reason there).
pub const BUILD_WAIVERS: &[&str] = &["WIDTH", "UNOPTFLAT"];

/// Verilator configuration of the ports-only VCD: `--trace-depth 1` keeps the top-level ports (scope
/// `uut`) but also the top module's own signals one level down; this switches those off.
fn ports_vlt(module: &str) -> String {
    format!("`verilator_config\ntracing_off -scope \"{module}\"\n")
}

/// The top module of a type: `chipset` (Type IV) or `chipset3` (Type III).
pub fn module_of(ty: RcType) -> &'static str {
    match ty {
        RcType::IV => "chipset",
        RcType::III => "chipset3",
    }
}

/// 32-bit words of the packed ports the harness takes (Verilator's VlWide layout: word 0 = bits 31:0).
/// The harness gets them as `-D` defines (`verilator_flags`), so that its C++ follows the structs.
const RC_WORDS: usize = RcCommand::BITS.div_ceil(32);
const SETUP_WORDS: usize = hdl::cs::SetupCommand::BITS.div_ceil(32);
const TEX_WORDS: usize = hdl::cs::TexValues::BITS.div_ceil(32);

/// A built harness.
#[derive(Clone, Debug)]
pub struct Build {
    /// The executable.
    pub exe: PathBuf,
    /// It was built by this call (false: taken from the cache).
    pub fresh: bool,
    /// Seconds spent generating the Verilog and (if fresh) running Verilator.
    pub seconds: f64,
}

fn trace_suffix(vcd: Option<VcdScope>) -> &'static str {
    match vcd {
        None => "",
        Some(VcdScope::Ports) => "_trace",
        Some(VcdScope::Full) => "_trace_full",
    }
}

/// FNV-1a, 64 bits: a cache key that does not change between Rust releases.
pub(crate) fn fnv1a(parts: &[&[u8]]) -> u64 {
    let mut h: u64 = 0xcbf29ce484222325;
    for p in parts {
        for &b in p.iter().chain(&[0xffu8]) {
            h ^= b as u64;
            h = h.wrapping_mul(0x100000001b3);
        }
    }
    h
}

fn verilator_flags(ty: RcType, vcd: Option<VcdScope>) -> Vec<String> {
    let m = module_of(ty);
    let mut f: Vec<String> = ["--cc", "--exe", "--build", "-O3", "-j", "2", "--top-module", m, "-o", &format!("V{m}")].iter().map(|s| s.to_string()).collect();
    if ty == RcType::III {
        f.extend(["-CFLAGS".to_string(), "-DTYPE_III".to_string()]);
    }
    for (name, words) in [("RC_WORDS", RC_WORDS), ("SETUP_WORDS", SETUP_WORDS), ("TEX_WORDS", TEX_WORDS)] {
        f.extend(["-CFLAGS".to_string(), format!("-D{name}={words}")]);
    }
    f.extend(BUILD_WAIVERS.iter().map(|w| format!("-Wno-{w}")));
    match vcd {
        None => {}
        Some(VcdScope::Ports) => f.extend(["--trace", "--trace-depth", "1"].iter().map(|s| s.to_string())),
        Some(VcdScope::Full) => f.push("--trace".into()),
    }
    f
}

/// Build the Type IV harness for `screen` (with a VCD writer of `vcd`'s kind) unless the cache holds it.
pub fn build(screen: Screen, vcd: Option<VcdScope>) -> Result<Build, String> {
    build_of(RcType::IV, screen, vcd)
}

/// Build the harness of the chipset of type `ty` (`chipset` or `chipset3`), as [`build`].
pub fn build_of(ty: RcType, screen: Screen, vcd: Option<VcdScope>) -> Result<Build, String> {
    let verilog = match ty {
        RcType::IV => hdl::chipset::verilog(screen.width, screen.height)?,
        RcType::III => hdl::chipset::chipset3::verilog(screen.width, screen.height)?,
    };
    build_module(module_of(ty), verilog, verilator_flags(ty, vcd), screen, vcd)
}

/// Build the harness of the textured chipset (`chipset_tex`, the harness with `TEXTURED`), as [`build`].
pub fn build_tex(screen: Screen, vcd: Option<VcdScope>) -> Result<Build, String> {
    let verilog = hdl::chipset::chipset_tex::verilog(screen.width, screen.height)?;
    let mut flags = verilator_flags(RcType::IV, vcd);
    for f in flags.iter_mut() {
        if f == "chipset" {
            *f = "chipset_tex".into();
        } else if f == "Vchipset" {
            *f = "Vchipset_tex".into();
        }
    }
    flags.extend(["-CFLAGS".to_string(), "-DTEXTURED".to_string()]);
    build_module("chipset_tex", verilog, flags, screen, vcd)
}

fn build_module(m: &str, verilog: String, flags: Vec<String>, screen: Screen, vcd: Option<VcdScope>) -> Result<Build, String> {
    let t0 = Instant::now();
    let version = verilator_version()?;
    let vlt = ports_vlt(m);
    let key = format!("{:016x}", fnv1a(&[verilog.as_bytes(), HARNESS_CPP.as_bytes(), vlt.as_bytes(), flags.join(" ").as_bytes(), &version]));
    let name = format!("{m}_{}x{}{}", screen.width, screen.height, trace_suffix(vcd));
    let verilog_file = format!("{m}.v");
    cached_build(&name, &key, &format!("obj/V{m}"), t0, &|tmp: &Path| {
        let write = |f: &str, text: &str| std::fs::write(tmp.join(f), text).map_err(|e| format!("cannot write {}: {e}", tmp.join(f).display()));
        write(&verilog_file, &verilog)?;
        write("harness.cpp", HARNESS_CPP)?;
        write("ports.vlt", &vlt)?;
        let config: &[&str] = if vcd == Some(VcdScope::Ports) { &["ports.vlt"] } else { &[] };
        let out = Command::new("verilator")
            .current_dir(tmp)
            .args(&flags)
            .args(["-Mdir", "obj"])
            .args(config)
            .args([verilog_file.as_str(), "harness.cpp"])
            .output()
            .map_err(|e| format!("cannot run verilator: {e}"))?;
        let log = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
        let _ = std::fs::write(tmp.join("build.log"), &log);
        if !out.status.success() {
            return Err(format!("verilator failed to build the chipset harness (files in {}):\n{}", tmp.display(), tail(&log, 4000)));
        }
        Ok(())
    })
}

/// What `verilator --version` prints (part of every cache key), or why Verilator cannot run.
pub(crate) fn verilator_version() -> Result<Vec<u8>, String> {
    let version = Command::new("verilator")
        .arg("--version")
        .output()
        .map_err(|e| format!("--backend verilator needs Verilator 5 on PATH (e.g. apt-get install verilator): cannot run verilator: {e}"))?;
    if !version.status.success() {
        return Err(format!("verilator --version failed: {}", String::from_utf8_lossy(&version.stderr)));
    }
    Ok(version.stdout)
}

/// The build directory `target/verilator/<name>/`, made by `make` unless it holds a build whose
/// `hash` file says `key` and whose `product` (a path inside it) exists. One build at a time in this
/// process (tests run in threads; the machine has 2 cores); other processes are kept apart by
/// building in a private directory and renaming it into place.
pub(crate) fn cached_build(name: &str, key: &str, product: &str, t0: Instant, make: &dyn Fn(&Path) -> Result<(), String>) -> Result<Build, String> {
    static BUILDING: Mutex<()> = Mutex::new(());
    let _one = BUILDING.lock().unwrap_or_else(|e| e.into_inner());
    let root = workspace_target().join("verilator");
    let dir = root.join(name);
    let exe_in = |d: &Path| d.join(product);
    let cached = |d: &Path| std::fs::read_to_string(d.join("hash")).map(|h| h.trim() == key).unwrap_or(false) && exe_in(d).is_file();
    if cached(&dir) {
        return Ok(Build { exe: exe_in(&dir), fresh: false, seconds: t0.elapsed().as_secs_f64() });
    }
    // Build beside the cache entry, then move it into place: concurrent builds never see half a build.
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.subsec_nanos()).unwrap_or(0);
    let tmp = root.join(format!("{name}.build-{}-{nanos}", std::process::id()));
    std::fs::create_dir_all(&tmp).map_err(|e| format!("cannot create {}: {e}", tmp.display()))?;
    make(&tmp)?;
    if !exe_in(&tmp).is_file() {
        return Err(format!("the build in {} did not make {product}", tmp.display()));
    }
    std::fs::write(tmp.join("hash"), format!("{key}\n")).map_err(|e| format!("cannot write {}: {e}", tmp.join("hash").display()))?;
    if dir.exists() && !cached(&dir) {
        // A stale entry (another Verilog or harness): move it aside and remove it.
        let old = root.join(format!("{name}.old-{}-{nanos}", std::process::id()));
        if std::fs::rename(&dir, &old).is_ok() {
            let _ = std::fs::remove_dir_all(&old);
        }
    }
    let fresh = match std::fs::rename(&tmp, &dir) {
        Ok(()) => true,
        // Someone else put the same build in place meanwhile.
        Err(_) if cached(&dir) => {
            let _ = std::fs::remove_dir_all(&tmp);
            false
        }
        Err(e) => return Err(format!("cannot move {} to {}: {e}", tmp.display(), dir.display())),
    };
    Ok(Build { exe: exe_in(&dir), fresh, seconds: t0.elapsed().as_secs_f64() })
}

pub(crate) fn tail(s: &str, n: usize) -> &str {
    let mut i = s.len().saturating_sub(n);
    while !s.is_char_boundary(i) {
        i += 1;
    }
    &s[i..]
}

/// The `chipset` (or `chipset3`) Verilog under Verilator, with its memories in the harness.
pub struct VerilatorChipset {
    pub screen: Screen,
    /// Type IV (`chipset`) or Type III (`chipset3`).
    pub ty: RcType,
    /// The textured top (`chipset_tex`, Type IV).
    pub textured: bool,
    pub cycle: u64,
    pub phases: PhaseCycles,
    /// How the harness was obtained (build time, cache hit).
    pub build: Build,
    child: Child,
    to_sim: BufWriter<ChildStdin>,
    from_sim: BufReader<ChildStdout>,
    stderr: Arc<Mutex<String>>,
    /// Cycles per phase of every frame of the last run.
    pub frame_phases: Vec<PhaseCycles>,
    /// Frames started since reset: frames 0 and 1 clear their bank, later ones find it cleared.
    frames_started: u64,
    /// How the host loop drives the streams (as `RtlChipset`'s).
    pub drive: HostDrive,
    vcd_open: bool,
    progress: Option<Progress>,
}

impl VerilatorChipset {
    /// A chipset for `screen`; with `vcd`, the top-level ports in every half cycle are written there.
    pub fn new(screen: Screen, vcd: Option<PathBuf>) -> Result<VerilatorChipset, String> {
        Self::with_vcd_scope(screen, vcd, VcdScope::Ports)
    }

    /// As [`VerilatorChipset::new`], choosing what the VCD holds.
    pub fn with_vcd_scope(screen: Screen, vcd: Option<PathBuf>, scope: VcdScope) -> Result<VerilatorChipset, String> {
        Self::of_type(RcType::IV, screen, vcd, scope)
    }

    /// The chipset of type `ty` (`chipset3` for Type III), as [`VerilatorChipset::with_vcd_scope`].
    pub fn of_type(ty: RcType, screen: Screen, vcd: Option<PathBuf>, scope: VcdScope) -> Result<VerilatorChipset, String> {
        if let Some(p) = &vcd {
            // Fail before a build with a clear message rather than in the harness.
            std::fs::File::create(p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
        }
        let b = build_of(ty, screen, vcd.as_ref().map(|_| scope))?;
        Self::with_build(ty, screen, vcd, b)
    }

    /// The textured chipset (`chipset_tex`), as [`VerilatorChipset::with_vcd_scope`].
    pub fn textured(screen: Screen, vcd: Option<PathBuf>, scope: VcdScope) -> Result<VerilatorChipset, String> {
        if let Some(p) = &vcd {
            std::fs::File::create(p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
        }
        let b = build_tex(screen, vcd.as_ref().map(|_| scope))?;
        let mut c = Self::with_build(RcType::IV, screen, vcd, b)?;
        c.textured = true;
        Ok(c)
    }

    /// A textured chipset started from a harness built by [`build_tex`] (without a VCD writer).
    pub fn from_build_tex(screen: Screen, build: Build) -> Result<VerilatorChipset, String> {
        let mut c = Self::with_build(RcType::IV, screen, None, build)?;
        c.textured = true;
        Ok(c)
    }

    /// A Type IV chipset started from a harness already built by [`build`] (without a VCD writer): a
    /// run of many frames checks the cache once per screen size instead of once per chipset.
    pub fn from_build(screen: Screen, build: Build) -> Result<VerilatorChipset, String> {
        Self::with_build(RcType::IV, screen, None, build)
    }

    /// As [`VerilatorChipset::from_build`], for a harness built by [`build_of`] for `ty`.
    pub fn from_build_of(ty: RcType, screen: Screen, build: Build) -> Result<VerilatorChipset, String> {
        Self::with_build(ty, screen, None, build)
    }

    fn with_build(ty: RcType, screen: Screen, vcd: Option<PathBuf>, build: Build) -> Result<VerilatorChipset, String> {
        let mut cmd = Command::new(&build.exe);
        cmd.arg(screen.width.to_string()).arg(screen.height.to_string());
        if let Some(p) = &vcd {
            cmd.arg(p);
        }
        let mut child = cmd
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", build.exe.display()))?;
        let stderr = Arc::new(Mutex::new(String::new()));
        {
            let log = stderr.clone();
            let mut err = child.stderr.take().expect("piped stderr");
            std::thread::spawn(move || {
                let mut buf = [0u8; 4096];
                while let Ok(n) = err.read(&mut buf) {
                    if n == 0 {
                        break;
                    }
                    let mut l = log.lock().unwrap();
                    if l.len() < 1 << 16 {
                        l.push_str(&String::from_utf8_lossy(&buf[..n]));
                    }
                }
            });
        }
        let to_sim = BufWriter::new(child.stdin.take().expect("piped stdin"));
        let from_sim = BufReader::new(child.stdout.take().expect("piped stdout"));
        let mut c = VerilatorChipset {
            screen,
            ty,
            textured: false,
            cycle: 0,
            phases: PhaseCycles::default(),
            build,
            child,
            to_sim,
            from_sim,
            stderr,
            frame_phases: Vec::new(),
            frames_started: 0,
            drive: HostDrive::default(),
            vcd_open: vcd.is_some(),
            progress: None,
        };
        c.expect("READY")?;
        Ok(c)
    }

    /// Drive the streams with random gaps and back-pressure (the same as `RtlChipset::with_drive`).
    pub fn with_drive(mut self, d: HostDrive) -> VerilatorChipset {
        self.drive = d;
        self
    }

    /// Report progress through `f(phase, done, total)`.
    pub fn with_progress(mut self, f: Progress) -> VerilatorChipset {
        self.progress = Some(f);
        self
    }

    /// Close the VCD (flushing it); it is also closed when the chipset is dropped.
    pub fn finish_vcd(&mut self) {
        if self.vcd_open {
            self.vcd_open = false;
            if self.send(b"vcd_close\n", &[]).is_ok() {
                let _ = self.expect("V");
            }
        }
    }

    /// A cycle budget that no correct frame reaches (as `RtlChipset`'s): a hang is an error.
    fn budget(&self, work: u64) -> u64 {
        1_000_000 + 64 * work
    }

    fn died(&mut self, what: &str) -> String {
        // Give the stderr reader a moment to collect the last words.
        let status = self.child.wait().map(|s| s.to_string()).unwrap_or_else(|e| e.to_string());
        std::thread::sleep(std::time::Duration::from_millis(50));
        let log = self.stderr.lock().map(|l| l.clone()).unwrap_or_default();
        format!("verilated chipset ({}) {what} ({status}):\n{}", self.build.exe.display(), tail(&log, 4000))
    }

    fn send(&mut self, line: &[u8], words: &[u32]) -> Result<(), String> {
        let mut bytes = Vec::with_capacity(line.len() + 4 * words.len());
        bytes.extend_from_slice(line);
        for w in words {
            bytes.extend_from_slice(&w.to_le_bytes());
        }
        if self.to_sim.write_all(&bytes).and_then(|_| self.to_sim.flush()).is_err() {
            return Err(self.died("stopped taking commands"));
        }
        Ok(())
    }

    /// The next reply that is not a progress report; an `E` reply is the error it carries.
    fn reply(&mut self) -> Result<Vec<String>, String> {
        loop {
            let mut line = String::new();
            match self.from_sim.read_line(&mut line) {
                Ok(0) | Err(_) => return Err(self.died("exited unexpectedly")),
                Ok(_) => {}
            }
            let line = line.trim_end();
            if let Some(m) = line.strip_prefix("E ") {
                return Err(m.to_string());
            }
            if let Some(p) = line.strip_prefix("P ") {
                let mut it = p.splitn(3, ' ');
                let done = it.next().and_then(|s| s.parse().ok()).unwrap_or(0);
                let total = it.next().and_then(|s| s.parse().ok()).unwrap_or(0);
                let phase = it.next().unwrap_or("").to_string();
                if let Some(f) = self.progress.as_mut() {
                    f(&phase, done, total);
                }
                continue;
            }
            return Ok(line.split(' ').map(str::to_string).collect());
        }
    }

    /// The next reply, which must have tag `tag`; returns its numeric fields.
    fn expect(&mut self, tag: &str) -> Result<Vec<i64>, String> {
        let f = self.reply()?;
        if f.first().map(String::as_str) != Some(tag) {
            return Err(format!("verilated chipset: expected a '{tag}' reply, got '{}'", f.join(" ")));
        }
        f[1..].iter().map(|s| s.parse::<i64>().map_err(|_| format!("verilated chipset: bad field '{s}' in '{}'", f.join(" ")))).collect()
    }

    fn words(&mut self, n: usize) -> Result<Vec<u32>, String> {
        let mut bytes = vec![0u8; 4 * n];
        if self.from_sim.read_exact(&mut bytes).is_err() {
            return Err(self.died("exited in the middle of a reply"));
        }
        Ok(bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect())
    }
}

impl Drop for VerilatorChipset {
    fn drop(&mut self) {
        let _ = self.to_sim.write_all(b"quit\n").and_then(|_| self.to_sim.flush());
        // The harness exits on `quit` (closing its VCD); do not leave it behind if it hangs.
        for _ in 0..200 {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A packed port word as 32-bit words, bit 0 first (Verilator's VlWide layout).
fn push_words<const N: usize>(b: Bits<N>, count: usize, out: &mut Vec<u32>) {
    assert!(32 * count >= N, "{N} bits do not fit {count} words");
    for k in 0..count {
        let mut w = 0u32;
        for j in 0..32 {
            let i = 32 * k + j;
            if i < N && b.get_bit(i) {
                w |= 1 << j;
            }
        }
        out.push(w);
    }
}

/// An RC result word (`RcResult`'s bits) in the golden model's terms; `None` for end of frame.
pub fn result_of(word: u32) -> Option<TriResult> {
    let r = RcResult::default();
    let bit = |o: usize| (word >> o) & 1 == 1;
    if bit(r.get_my_offset_eof()) {
        return None;
    }
    let (zero_area, culled) = (bit(r.get_my_offset_zero_area()), bit(r.get_my_offset_culled()));
    Some(TriResult {
        index: (word >> r.get_my_offset_index()) & ((1 << r.get_my_width_index()) - 1),
        culled: if zero_area {
            Some(Culled::ZeroArea)
        } else if culled {
            Some(Culled::Facing)
        } else {
            None
        },
        visible: bit(r.get_my_offset_visible()),
    })
}

impl Chipset for VerilatorChipset {
    fn run(&mut self, jobs: &[FrameJob], host: &mut dyn LowerPipeline) -> Result<Vec<FrameOut>, String> {
        let mut frames = Vec::with_capacity(jobs.len());
        for job in jobs {
            let fr = FrameRun::new(job, self.frames_started < 2, self.textured)?;
            self.frames_started += 1;
            let mut words = Vec::with_capacity(RC_WORDS * (fr.words.len() + 6 * fr.config.len()));
            for w in &fr.words {
                push_words(Bits::<{ RcCommand::BITS }>::from(*w), RC_WORDS, &mut words);
            }
            for c in &fr.config {
                // The same packing as the RustHDL backend's ports (`config_ports`), as 32-bit words.
                let ((le, la, ld), (_, ma, ms, md)) = config_ports(Some(*c));
                let (kind, address, slot, data) = if le { (0, la, 0, ld) } else { (1, ma, ms, md) };
                words.extend_from_slice(&[kind, address as u32, slot as u32, data as u32, (data >> 32) as u32, (data >> 64) as u32]);
            }
            self.send(format!("frame {} {} {} {}\n", fr.words.len(), fr.background, fr.phong as u8, fr.config.len()).as_bytes(), &words)?;
            if let Some(t) = &fr.tex {
                let size = t.banks[0].len();
                let mut words = Vec::with_capacity(1 + t.bases.len() + 4 * size);
                words.push(size as u32);
                words.extend_from_slice(&t.bases);
                for b in t.banks.iter() {
                    words.extend(b.iter().map(|&w| crate::cs::pack::tdata_of(w)));
                }
                self.send(format!("texture {} {} {} {} {}\n", t.w0_log2, t.h0_log2, t.bases.len(), t.filter, t.clamp as u8).as_bytes(), &words)?;
            }
            frames.push(fr);
        }
        let nf = frames.len();
        let n = self.screen.pixels();
        let work: u64 = jobs.iter().map(|j| n as u64 + 128 * j.tris.len() as u64).sum();
        let visible_bit = 1u32 << RcResult::default().get_my_offset_visible();
        let d = self.drive;
        let seed = crate::common::Rng::new(d.seed).seed();
        let budget = self.budget(work) * (1 + d.gap_percent.max(d.stall_percent) / 10);
        self.send(format!("run {budget} {visible_bit} {seed} {} {}\n", d.gap_percent, d.stall_percent).as_bytes(), &[])?;
        let mut outs: Vec<Option<FrameOut>> = vec![None; nf];
        let mut host_error: Option<String> = None;
        loop {
            let f = match self.reply() {
                Ok(f) => f,
                // The harness stopped because the host failed: the host's reason, not the harness's.
                Err(e) => return Err(host_error.unwrap_or(e)),
            };
            let num = |k: usize| -> Result<i64, String> { f.get(k).and_then(|s| s.parse().ok()).ok_or_else(|| format!("verilated chipset: bad reply '{}'", f.join(" "))) };
            match f[0].as_str() {
                "Q" => {
                    let (fi, position) = (num(1)? as usize, num(2)? as usize);
                    let answer = if self.textured { 1 + SETUP_WORDS + TEX_WORDS } else { 1 + SETUP_WORDS };
                    match host.visible(fi, position).and_then(|c| Ok((SetupCmd::from_command(&c)?, c.tex))) {
                        Ok((c, tex)) => {
                            let mut words = vec![1u32];
                            let b: Bits<{ hdl::cs::SetupCommand::BITS }> = command_of(&c).into();
                            push_words(b, SETUP_WORDS, &mut words);
                            if self.textured {
                                let t: Bits<{ hdl::cs::TexValues::BITS }> = crate::cs::pack::tex_values_of(&tex.unwrap_or_default()).into();
                                push_words(t, TEX_WORDS, &mut words);
                            }
                            self.send(b"", &words)?;
                        }
                        Err(e) => {
                            host_error = Some(e);
                            self.send(b"", &vec![0u32; answer])?;
                        }
                    }
                }
                "R" => {
                    let (fi, count) = (num(1)? as usize, num(2)? as usize);
                    let words = self.words(count)?;
                    let ib = self.words(n)?;
                    let zb = match self.ty {
                        RcType::IV => depths_as_seen(&ib, &self.words(n)?),
                        RcType::III => {
                            let w = self.words(6 << 16)?;
                            let v = |k: usize| (w[k] as u64 | (w[k + 1] as u64) << 32) as i64;
                            let tdbv: Vec<Plane> = (0..1usize << 16).map(|i| Plane { a: v(6 * i), b: v(6 * i + 2), c: v(6 * i + 4) }).collect();
                            crate::rc::bench::regenerated_depths(self.screen, &ib, &tdbv)
                        }
                    };
                    let fr = frames.get_mut(fi).ok_or("verilated chipset: a frame it was not sent")?;
                    for &w in &words {
                        let r = result_of(w).ok_or("verilated chipset: an end-of-frame word among the results")?;
                        fr.result(r)?;
                    }
                    if fr.results.len() != fr.tris.len() {
                        return Err(format!("chipset: {} results for {} triangles", fr.results.len(), fr.tris.len()));
                    }
                    outs[fi] = Some(FrameOut { results: std::mem::take(&mut fr.results), scan: ScanOut { rgb: Vec::new(), ibuf: ib, zbuf: zb }, rc_counts: None, texture_counts: None });
                }
                "O" => {
                    let (fi, count) = (num(1)? as usize, num(2)? as usize);
                    let tdata = self.words(count)?;
                    if tdata.len() != n {
                        return Err(format!("chipset: scan-out produced {} of {n} pixels", tdata.len()));
                    }
                    let out = outs.get_mut(fi).and_then(|o| o.as_mut()).ok_or("verilated chipset: a scan-out before its frame's end of frame")?;
                    out.scan.rgb = tdata.iter().flat_map(|&t| rgb_of(t)).collect();
                }
                "F" => {
                    let fi = num(1)? as usize;
                    let fields = if self.textured { 28 } else { 23 };
                    let st = (2..fields).map(num).collect::<Result<Vec<i64>, String>>()?;
                    let o = |v: i64| (v >= 0).then_some(v as u64);
                    let fr = frames.get_mut(fi).ok_or("verilated chipset: a frame it was not sent")?;
                    (fr.start, fr.first_tri_taken, fr.last_cmd_taken, fr.eof) = (o(st[0]), o(st[1]), st[2] as u64, o(st[3]));
                    (fr.clear_writes, fr.z_reads, fr.setup_first, fr.drawn) = (st[4] as u64, st[5] as u64, o(st[6]), o(st[7]));
                    (fr.scan_begin, fr.scan_taken, fr.scan_done) = (o(st[8]), o(st[9]), o(st[10]));
                    fr.traffic = PortTraffic::from_slice(&st[11..21].iter().map(|&v| v as u64).collect::<Vec<u64>>());
                    if let [rd, wr, words, footprints, covered] = st[21..] {
                        fr.tex_traffic = TexTraffic { tdbt_reads: rd as u64, tdbt_writes: wr as u64, bank_words: words as u64, footprints: footprints as u64, covered_reads: covered as u64 };
                    }
                }
                "D" => {
                    self.cycle = num(1)? as u64;
                    break;
                }
                _ => return Err(format!("verilated chipset: unexpected reply '{}'", f.join(" "))),
            }
        }
        self.frame_phases = (0..nf).map(|f| frames[f].phases(if f > 0 { frames[f - 1].scan_taken } else { None })).collect();
        self.phases = self.frame_phases.last().cloned().unwrap_or_default();
        for (o, fr) in outs.iter_mut().zip(&frames) {
            if let Some(o) = o.as_mut() {
                o.texture_counts = fr.texture_counts();
            }
        }
        outs.into_iter().map(|o| o.ok_or_else(|| "verilated chipset: a frame without output".to_string())).collect()
    }
}
