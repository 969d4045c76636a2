//! Measures the chipset's figures for the README: `cargo run --release -p tb --bin chipset_figures`
//! (`-- --verilator` for the generated Verilog under Verilator: the same cycles, in seconds instead of
//! half an hour). Every built-in scene at 320x200, Gouraud and Phong, three frames back to back on one
//! chipset (each frame checked against the golden model): cycles per phase (frames 1 and 2 clear their
//! I-buffer bank, frame 3 is the steady state), the frame interval, CS pixels per clock, RC fragments
//! per clock, colour-setup span per visible triangle; and the host's operation counts with enhanced
//! deferred lighting against seed 001's Type I and Type II.

use golden::format::Screen;
use golden::render::{render, RenderOptions};
use golden::scene::builtin;
use golden::shade::Shading;
use tb::backend::{render_timed_frames, CycleChipset};
use tb::chipset::RtlChipset;
use tb::verilator::VerilatorChipset;

/// Frames per run, back to back.
const FRAMES: usize = 3;

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    let screen = Screen::new(320, 200)?;
    let verilator = std::env::args().any(|a| a == "--verilator");
    let mut cycles = String::from(
        "| scene | shading | frame | clear | geometry transfer | rasterization | colour setup span | scan-out | total | frame interval | fragments/clk in rasterization | CS px/clk |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut speed = String::from("| scene | shading | cycles (3 frames) | sim s | cycles/s |\n|---|---|---|---|---|\n");
    let mut host = String::from(
        "| scene | shading | (a) in | (b) after culling | flagged visible | (c) in image | vertex lightings deferred / Type I / Type II | host cost, deferred | Type I | Type II | saved vs Type I | saved vs Type II |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (shading, name) in [Shading::Gouraud, Shading::Phong].into_iter().flat_map(|s| builtin::SCENES.iter().map(move |n| (s, *n))) {
        let mesh = builtin::scene(name)?;
        let opts = RenderOptions::for_scene(&mesh, screen, shading);
        let golden = render(&mesh, &opts)?;
        let mut chip: Box<dyn CycleChipset> = if verilator { Box::new(VerilatorChipset::new(screen, None)?) } else { Box::new(RtlChipset::new(screen, None)?) };
        let runs = render_timed_frames(&mesh, &opts, FRAMES, chip.as_mut());
        let secs = runs[0].secs;
        for (k, run) in runs.into_iter().enumerate() {
            let frame = k + 1;
            let rtl = run.frame?;
            if rtl.rgb != golden.rgb || rtl.hw_index != golden.hw_index || rtl.zbuf != golden.zbuf {
                return Err(format!("{name} frame {frame}: the RTL frame differs from the golden model's"));
            }
            let p = run.phases.ok_or("no cycle counts")?;
            cycles += &format!(
                "| {name} | {shading:?} | {frame} | {} | {} | {} | {} | {} | {} | {} | {:.3} | {:.4} |\n",
                p.clear,
                p.geometry_transfer,
                p.rasterization,
                p.colour_setup,
                p.scan_out,
                p.total,
                p.frame_interval.map(|i| i.to_string()).unwrap_or("-".into()),
                rtl.stats.rc.fragments as f64 / p.rasterization as f64,
                screen.pixels() as f64 / p.scan_out as f64,
            );
            eprintln!("{name} {shading:?} frame {frame}: {p:?}");
        }
        let c = chip.cycles();
        speed += &format!("| {name} | {shading:?} | {c} | {secs:.1} | {:.0} |\n", c as f64 / secs);
        let s = &golden.stats;
        let (d, t1, t2) = (s.host_ops.cost(), s.host_type_i.ops().cost(), s.host_type_ii.ops().cost());
        host += &format!(
            "| {name} | {shading:?} | {} | {} | {} | {} | {} / {} / {} | {d} | {t1} | {t2} | {:.1}% | {:.1}% |\n",
            s.triangles_in,
            s.after_culling,
            s.flagged_visible,
            s.visible_final,
            s.host.lighting,
            s.host_type_i.lighting,
            s.host_type_ii.lighting,
            100.0 * (t1 as f64 - d as f64) / t1 as f64,
            100.0 * (t2 as f64 - d as f64) / t2 as f64
        );
    }
    println!("{} simulation\n\n{cycles}\n{speed}\n{host}", if verilator { "Verilator" } else { "RustHDL" });
    Ok(())
}
