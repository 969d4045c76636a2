//! Measures the RC's figures for docs/rc.md: `cargo run --release -p tb --bin rc_figures`.
//! Setup latency, cycles per frame and fragments per clock (cycle model, which the RTL equals cycle for
//! cycle), RustHDL simulation speed (RTL against the model, every port every cycle), yosys ice40 counts.

use golden::cycle::rc::RcCmd;
use golden::format::Screen;
use golden::raster::{CullMode, FrontFace};
use golden::format::WinVertex;
use tb::rc::bench::{run_model, run_rtl, Drive};
use tb::rc::stimulus::{frame, reference, scene_triangles};

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    // Setup latency: one drawn triangle; the cycle of its first Z read minus its acceptance cycle.
    let s = Screen::new(32, 32).unwrap();
    let v = |x: i32, y: i32| WinVertex { x: x * golden::format::SUBPIXEL_ONE, y: y * golden::format::SUBPIXEL_ONE, z: 100 };
    let one = RcCmd::triangle(1, [v(2, 2), v(12, 2), v(2, 12)], CullMode::None, FrontFace::Ccw)?;
    let single = run_model(s, &frame(false, vec![one]), Drive::ideal(), None)?;
    println!("single drawn triangle (10x10 px box, frame start + triangle + end of frame): {} cycles", single.cycles);
    for n in [1usize, 100] {
        let tiny: Vec<RcCmd> = (0..n).map(|i| RcCmd::triangle(i as u32 + 1, [v(2, 2), v(3, 2), v(2, 3)], CullMode::None, FrontFace::Ccw).unwrap()).collect();
        let r = run_model(s, &frame(false, tiny), Drive::ideal(), None)?;
        println!("{n} one-pixel triangles back to back: {} cycles", r.cycles);
    }
    let culled: Vec<RcCmd> = (0..100).map(|i| RcCmd::triangle(i + 1, [v(2, 2), v(2, 12), v(12, 2)], CullMode::Back, FrontFace::Cw).unwrap()).collect();
    let r = run_model(s, &frame(false, culled), Drive::ideal(), None)?;
    println!("100 culled triangles back to back: {} cycles", r.cycles);

    let screen = Screen::new(320, 200).unwrap();
    for (name, grid) in [("polyhedron", 6), ("teapot", 6)] {
        let tris = scene_triangles(name, grid, screen)?;
        for clear in [true, false] {
            let cmds = frame(clear, tris.clone());
            let run = run_model(screen, &cmds, Drive::ideal(), None)?;
            let c = reference(screen, &cmds).rast.counts;
            println!(
                "{name} (grid {grid}) 320x200 clear={clear}: {} triangles, {} cycles; {} candidates ({:.3}/clock), {} fragments Z-tested ({:.3}/clock), {} passes; traversal walked {} clocks, {:.1} % of them delivered a fragment",
                tris.len(),
                run.cycles,
                c.candidates,
                c.candidates as f64 / run.cycles as f64,
                run.z_reads,
                run.z_reads as f64 / run.cycles as f64,
                run.z_passes,
                run.walk_clocks,
                100.0 * run.walk_fragment_clocks as f64 / run.walk_clocks.max(1) as f64
            );
        }
        let cmds = frame(true, tris);
        let t = std::time::Instant::now();
        let rtl = run_rtl(&format!("figures_{name}"), screen, &cmds, Drive::ideal(), None)?;
        println!(
            "{name}: RustHDL RTL vs model, every port every cycle: {} cycles in {:.2} s = {:.0} cycles/s",
            rtl.cycles,
            t.elapsed().as_secs_f64(),
            rtl.rtl_cycles_per_second
        );
    }
    Ok(())
}
