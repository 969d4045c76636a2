//! Shared testbench helpers.

use rust_hdl::core::vcd_probe::VCDProbe;
use rust_hdl::prelude::*;
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// A direct-drive bench's waveform (GUIDE §5): the VCD of the unit under test, written change by
/// change while the bench runs, and its path for the failure messages. Every every-cycle bench keeps
/// one beside its unit; `None` writes nothing.
pub struct Trace {
    vcd: Option<VCDProbe<BufWriter<File>>>,
    path: Option<PathBuf>,
}

impl Trace {
    /// A VCD of `uut` at `vcd` (its header and the initial values), or no VCD.
    pub fn new<U: Block>(uut: &U, vcd: Option<&Path>) -> Result<Trace, String> {
        let probe = match vcd {
            Some(p) => {
                let f = File::create(p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
                Some(write_vcd_dump(write_vcd_header(BufWriter::new(f), uut), uut))
            }
            None => None,
        };
        Ok(Trace { vcd: probe, path: vcd.map(Path::to_path_buf) })
    }

    /// Record what changed in `uut` at time `t` (call after it settled).
    pub fn dump<U: Block>(&mut self, uut: &U, t: u64) -> Result<(), String> {
        if let Some(mut v) = self.vcd.take() {
            v.timestamp(t).map_err(|e| format!("vcd: {e}"))?;
            self.vcd = Some(write_vcd_change(v, uut));
        }
        Ok(())
    }

    /// Close the waveform with a last timestamp at `t`, so that viewers show the final cycle whole.
    pub fn end(&mut self, t: u64) {
        if let Some(v) = self.vcd.as_mut() {
            let _ = v.timestamp(t);
        }
    }

    /// A failure in cycle `cycle`, naming the waveform when there is one.
    pub fn fail(&self, cycle: u64, what: String) -> String {
        match &self.path {
            Some(p) => format!("cycle {cycle}: {what} (waveform: {})", p.display()),
            None => format!("cycle {cycle}: {what} (no waveform was written: VCD=1 for a test, --vcd for render, writes one)"),
        }
    }
}

/// The benches' progress watchdog (issue 18): a run in which nothing moves at the ports (no
/// transaction, no memory access, no output) for longer than any one unit of work can need ends at
/// once, with the phase, the cycle and the waveform, instead of running on to a cycle budget.
pub struct Watchdog {
    limit: u64,
    last: u64,
}

impl Watchdog {
    /// No progress for more than `limit` cycles is a failure.
    pub fn new(limit: u64) -> Watchdog {
        Watchdog { limit, last: 0 }
    }
    /// A watchdog that counts from `cycle` (a run whose streaming starts after configuration writes:
    /// those cycles are not a stall).
    pub fn from_cycle(limit: u64, cycle: u64) -> Watchdog {
        Watchdog { limit, last: cycle }
    }
    /// Call once per cycle: `progress` says whether anything moved in `cycle`. The error says what
    /// stopped (`phase`) and names the waveform through `trace` when there is one.
    pub fn check(&mut self, cycle: u64, progress: bool, phase: impl FnOnce() -> String, trace: Option<&Trace>) -> Result<(), String> {
        if progress {
            self.last = cycle;
            return Ok(());
        }
        if cycle.saturating_sub(self.last) <= self.limit {
            return Ok(());
        }
        let what = format!("no progress for {} cycles in {}", self.limit, phase());
        Err(match trace {
            Some(t) => t.fail(cycle, what),
            None => format!("cycle {cycle}: {what}"),
        })
    }
}

/// Where a simulation test leaves its waveform: `target/vcd/<block>/<test>.vcd` under the workspace.
pub fn vcd_path(block: &str, test: &str) -> PathBuf {
    let dir = workspace_target().join("vcd").join(block);
    let _ = std::fs::create_dir_all(&dir);
    dir.join(format!("{test}.vcd"))
}

/// A scratch directory for generated Verilog and tool runs: `target/hdl/<what>`.
pub fn scratch_dir(what: &str) -> PathBuf {
    let dir = workspace_target().join("hdl").join(what);
    let _ = std::fs::create_dir_all(&dir);
    dir
}

/// The workspace's `target/` directory (CARGO_TARGET_DIR if set).
pub fn workspace_target() -> PathBuf {
    if let Ok(t) = std::env::var("CARGO_TARGET_DIR") {
        return PathBuf::from(t);
    }
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("target")
}

/// Whether VCDs should be written (set `VCD=1`; failing comparisons always write theirs).
pub fn vcd_wanted() -> bool {
    std::env::var("VCD").map(|v| v != "0").unwrap_or(false)
}

/// A small, seeded random source for stimulus (xorshift64*): reproducible runs without a dependency
/// in the synthesizable path. Seed from `SEED` in the environment when set, so a failure's printed
/// seed can be replayed.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(default_seed: u64) -> Rng {
        let seed = std::env::var("SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(default_seed);
        Rng(seed.max(1))
    }
    pub fn seed(&self) -> u64 {
        self.0
    }
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545F4914F6CDD1D)
    }
    /// True with probability `percent`/100.
    pub fn chance(&mut self, percent: u64) -> bool {
        self.next_u64() % 100 < percent
    }
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
}

/// Whether an external tool is on PATH (the test script installs verilator, iverilog, yosys, nextpnr-ice40).
pub fn have_tool(name: &str) -> bool {
    std::process::Command::new("sh").arg("-c").arg(format!("command -v {name}")).output().map(|o| o.status.success()).unwrap_or(false)
}

/// The environment variable that turns a missing tool from a test failure into a recorded skip
/// (`IDXRENDER_ALLOW_MISSING_TOOLS=1`; `scripts/test-allow-missing.sh` sets it and lists the skips at the
/// end; `scripts/test.sh` and `.ci/run` clear it). See docs/verification.md.
pub const ALLOW_MISSING_TOOLS: &str = "IDXRENDER_ALLOW_MISSING_TOOLS";

/// Where skipped tests are recorded, one line each: `target/skipped-tests.txt`.
pub fn skipped_tests_file() -> PathBuf {
    workspace_target().join("skipped-tests.txt")
}

/// The one rule for tests that need external tools: true when every tool in `tools` is on PATH. A
/// missing tool fails the test (a panic naming the tool and how to install it) unless
/// [`ALLOW_MISSING_TOOLS`] is `1`; then the test is recorded in [`skipped_tests_file`] and this returns
/// false, and the caller returns at once.
pub fn require_tools(test: &str, tools: &[&str]) -> bool {
    let allow = std::env::var(ALLOW_MISSING_TOOLS).as_deref() == Ok("1");
    require_tools_with(test, tools, allow, &skipped_tests_file())
}

/// [`require_tools`] with the opt-out and the record file given (what its tests drive).
pub fn require_tools_with(test: &str, tools: &[&str], allow_missing: bool, record: &std::path::Path) -> bool {
    let missing: Vec<&str> = tools.iter().copied().filter(|t| !have_tool(t)).collect();
    if missing.is_empty() {
        return true;
    }
    let install = format!("apt-get install {} (or run `bash scripts/test.sh`, which installs them)", missing.join(" "));
    if !allow_missing {
        panic!("{test}: {} not on PATH: {install}; {ALLOW_MISSING_TOOLS}=1 turns this into a recorded skip", missing.join(", "));
    }
    let line = format!("{test}: missing {}\n", missing.join(", "));
    let _ = std::fs::create_dir_all(record.parent().unwrap_or(std::path::Path::new(".")));
    use std::io::Write;
    if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open(record) {
        let _ = f.write_all(line.as_bytes());
    }
    eprintln!("skipped (opt-out {ALLOW_MISSING_TOOLS}=1) {line}");
    false
}

#[cfg(test)]
mod watchdog_tests {
    use super::Watchdog;

    #[test]
    fn the_watchdog_fires_one_cycle_after_its_limit_without_progress_and_never_while_things_move() {
        let mut w = Watchdog::new(10);
        for c in 0..1000 {
            w.check(c, c % 10 == 0 || c == 999, || "moving".into(), None).unwrap();
        }
        for c in 1000..=1009 {
            w.check(c, false, || "stuck".into(), None).unwrap();
        }
        let e = w.check(1010, false, || "the phase".into(), None).unwrap_err();
        assert_eq!(e, "cycle 1010: no progress for 10 cycles in the phase");
    }
}

#[cfg(test)]
mod tool_tests {
    use super::*;

    const NO_SUCH_TOOL: &str = "idxrender-no-such-tool";

    #[test]
    fn a_missing_tool_fails_the_test_naming_the_tool_and_how_to_install_it() {
        let record = workspace_target().join("tmp").join("skips-fail.txt");
        let e = std::panic::catch_unwind(|| require_tools_with("t", &["sh", NO_SUCH_TOOL], false, &record)).unwrap_err();
        let msg = e.downcast_ref::<String>().cloned().unwrap_or_default();
        assert!(msg.contains(NO_SUCH_TOOL) && msg.contains("apt-get install") && msg.contains(ALLOW_MISSING_TOOLS), "{msg}");
        assert!(!record.exists() || !std::fs::read_to_string(&record).unwrap().contains("t: missing"));
    }

    #[test]
    fn with_the_opt_out_a_missing_tool_is_a_recorded_skip_and_present_tools_run() {
        let record = workspace_target().join("tmp").join("skips-allow.txt");
        let _ = std::fs::remove_file(&record);
        assert!(!require_tools_with("skipped_test", &[NO_SUCH_TOOL], true, &record));
        assert!(require_tools_with("running_test", &["sh"], true, &record));
        let text = std::fs::read_to_string(&record).unwrap();
        assert_eq!(text, format!("skipped_test: missing {NO_SUCH_TOOL}\n"));
    }
}

/// A window coordinate (S11.8 subpixels, `golden::format::WINDOW_BITS` = 20 bits) as the port's raw
/// two's-complement bits.
pub fn window_bits(v: i32) -> Bits<20> {
    (v as u32 as u64 & 0xf_ffff).into()
}
