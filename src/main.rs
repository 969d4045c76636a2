//! `idxrender`: render scenes through the index-rendering chipset, generate its Verilog, analyse it.
//!
//! Every failure is an error message naming the problem and a non-zero exit, never a panic; outputs
//! are written only after the frame is complete, each file replaced atomically, so a failed run leaves
//! what an earlier run produced intact.

mod analyze;
mod args;
mod bench;
mod cli;
mod fpga;
mod fpga_budget;
mod output;
mod proof;
mod proof_realtime;
mod render;
mod vcd_diff;
mod verilog;

use clap::Parser;
use std::io::Write as _;
use std::sync::Mutex;

/// The first error in writing standard output, reported when the command ends. A closed pipe (e.g.
/// `| head`) is not an error: the reader wanted no more.
static STDOUT_ERROR: Mutex<Option<String>> = Mutex::new(None);

/// Keep the first error of a write to standard output (see [`STDOUT_ERROR`]).
pub fn note_stdout(r: std::io::Result<()>) {
    if let Err(e) = r {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            let mut first = STDOUT_ERROR.lock().unwrap_or_else(|p| p.into_inner());
            first.get_or_insert_with(|| e.to_string());
        }
    }
}

/// Print a line to stdout; a failed write makes the command fail at its end (a full disk behind a
/// redirection must not look like success), a closed pipe does not.
#[macro_export]
macro_rules! say {
    ($($t:tt)*) => {{
        use std::io::Write;
        $crate::note_stdout(writeln!(std::io::stdout(), $($t)*));
    }};
}

fn main() {
    // A file-size limit (`ulimit -f`) should make a write fail with an error the program reports and
    // cleans up after, not kill the process with SIGXFSZ halfway through a file.
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to SIG_IGN at start-up, before any thread exists.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
    let args = cli::Cli::parse();
    let result = cli::run(args);
    note_stdout(std::io::stdout().flush());
    if let Err(e) = result {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
    if let Some(e) = STDOUT_ERROR.lock().unwrap_or_else(|p| p.into_inner()).take() {
        eprintln!("error: cannot write to standard output: {e}");
        std::process::exit(1);
    }
}
