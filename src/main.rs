//! `idxrender`: render scenes through the index-rendering chipset, generate its Verilog, analyse it.
//!
//! Every failure is an error message naming the problem and a non-zero exit, never a panic; outputs
//! are written only after the frame is complete, each file replaced atomically, so a failed run leaves
//! what an earlier run produced intact.

mod analyze;
mod bench;
mod cli;
mod fpga;
mod output;
mod proof;
mod render;
mod vcd_diff;
mod verilog;

use clap::Parser;

/// Print a line to stdout; a closed pipe (e.g. `| head`) is not an error worth a panic.
#[macro_export]
macro_rules! say {
    ($($t:tt)*) => {{
        use std::io::Write;
        let _ = writeln!(std::io::stdout(), $($t)*);
    }};
}

fn main() {
    let args = cli::Cli::parse();
    if let Err(e) = cli::run(args) {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
