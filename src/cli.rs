//! The command line: the commands and what each runs (the render arguments are in `args`).

use crate::args::{load_scene, render_options, ArchArg, RenderArgs};
use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "idxrender", version, about = "Index-rendering 3-D chipset: render, generate Verilog, analyse")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render a scene: writes frame.png, index.bin, index.png and stats.json into --out.
    Render(RenderArgs),
    /// Write the Verilog of an RTL top (or of every top) into --out.
    Verilog(crate::verilog::VerilogArgs),
    /// Reproduce the seeds' analysis (lighting operations, CPU cost, buffer sizes, bandwidth).
    Analyze(crate::analyze::AnalyzeArgs),
    /// Synthesize and place and route the tops on iCE40 UP5K/HX8K; write a utilisation and Fmax table.
    FpgaReport(crate::fpga::FpgaArgs),
    /// Compare two VCD traces of the same top cycle by cycle on its ports; report the first difference.
    VcdDiff(crate::vcd_diff::VcdDiffArgs),
    /// Measure golden, RustHDL and Verilator speed, the chipset's work per clock and frames/s at Fmax; write bench.md.
    Bench(crate::bench::BenchArgs),
}

pub fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Render(args) => run_render(&args),
        Command::Verilog(args) => crate::verilog::run(&args),
        Command::Analyze(args) => crate::analyze::run(&args),
        Command::FpgaReport(args) => crate::fpga::run(&args),
        Command::VcdDiff(args) => crate::vcd_diff::run(&args),
        Command::Bench(args) => crate::bench::run(&args),
    }
}

fn run_render(args: &RenderArgs) -> Result<(), String> {
    let mesh = load_scene(args)?;
    let opts = render_options(args, &mesh)?;
    let proof_only = [("--ops", args.ops.is_some()), ("--fifo-depth", args.fifo_depth.is_some()), ("--filter", args.filter.is_some())];
    match args.arch {
        ArchArg::Index if proof_only.iter().any(|o| o.1) => {
            let given: Vec<&str> = proof_only.iter().filter(|o| o.1).map(|o| o.0).collect();
            Err(format!("{} applies to --arch proof only", given.join(", ")))
        }
        ArchArg::Proof if args.rc_type.is_some() => Err("--type applies to --arch index only (seed 000's Types III and IV are index-rendering architectures)".into()),
        ArchArg::Proof if args.index_bits.is_some() => Err("--index-bits applies to --arch index only (PROOF keeps no triangle index)".into()),
        ArchArg::Proof if args.frames != 1 => Err("--frames applies to --arch index (the chipset); PROOF renders one frame".into()),
        ArchArg::Index if mesh.materials.iter().any(|m| !m.is_opaque()) => Err(format!(
            "{} has transparent materials (opacity {}): the index-rendering chipset keeps one triangle per pixel in its I-buffer and cannot blend; render it with --arch proof, or opaque with --opacity 1",
            mesh.name,
            mesh.materials.iter().filter(|m| !m.is_opaque()).map(|m| format!("{}", m.opacity)).collect::<Vec<_>>().join(", ")
        )),
        ArchArg::Proof => crate::proof::run_render(args, &mesh, &opts),
        ArchArg::Index => crate::render::run_render(args, &mesh, &opts),
    }
}
