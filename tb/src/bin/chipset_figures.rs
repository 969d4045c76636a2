//! Measures the chipset's figures for the README: `cargo run --release -p tb --bin chipset_figures`.
//! Every built-in scene at 320x200, Gouraud and Phong, through the RustHDL simulation of the `chipset` top (each
//! frame checked against the golden model): cycles per phase for the first frame after reset (which
//! clears the buffers) and for a second frame of the same scene (buffers cleared behind the first
//! scan-out), CS pixels per clock, RC fragments per clock, colour-setup cycles per triangle; and the
//! host's operation counts with enhanced deferred lighting against seed 001's Type I and Type II.

use golden::format::Screen;
use golden::render::{render, RenderOptions};
use golden::scene::builtin;
use golden::shade::Shading;
use tb::backend::render_timed;
use tb::chipset::RtlChipset;

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    let screen = Screen::new(320, 200)?;
    let mut cycles = String::from(
        "| scene | shading | frame | clear | geometry transfer | rasterization | colour setup | scan-out | total | fragments/clk in rasterization | setup cycles/visible triangle | CS px/clk | sim s | cycles/s |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut host = String::from(
        "| scene | shading | (a) in | (b) after culling | flagged visible | (c) in image | vertex lightings deferred / Type I / Type II | host cost, deferred | Type I | Type II | saved vs Type I | saved vs Type II |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (shading, name) in [Shading::Gouraud, Shading::Phong].into_iter().flat_map(|s| builtin::SCENES.iter().map(move |n| (s, *n))) {
        let mesh = builtin::scene(name)?;
        let opts = RenderOptions::for_scene(&mesh, screen, shading);
        let golden = render(&mesh, &opts)?;
        let mut chip = RtlChipset::new(screen, None)?;
        for frame in [1, 2] {
            let run = render_timed(&mesh, &opts, &mut chip);
            let (rtl, secs) = (run.frame?, run.secs);
            if rtl.rgb != golden.rgb || rtl.hw_index != golden.hw_index || rtl.zbuf != golden.zbuf {
                return Err(format!("{name} frame {frame}: the RTL frame differs from the golden model's"));
            }
            let p = chip.phases.clone();
            let s = &rtl.stats;
            cycles += &format!(
                "| {name} | {shading:?} | {frame} | {} | {} | {} | {} | {} | {} | {:.3} | {:.1} | {:.4} | {:.1} | {:.0} |\n",
                p.clear,
                p.geometry_transfer,
                p.rasterization,
                p.colour_setup,
                p.scan_out,
                p.total,
                s.rc.fragments as f64 / p.rasterization as f64,
                p.colour_setup as f64 / s.tdbs_writes.max(1) as f64,
                screen.pixels() as f64 / p.scan_out as f64,
                secs,
                p.total as f64 / secs
            );
            eprintln!("{name} {shading:?} frame {frame}: {p:?} ({secs:.1} s)");
        }
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
    println!("{cycles}\n{host}");
    Ok(())
}
