//! Textured frames through the RustHDL simulation of the `chipset_tex` top (the RC, `textured_setup`,
//! `cs_tex`, with TdbT and the four texture banks behind ports), driven by the golden model's host
//! program, equal the algorithmic golden model's frames: image, I-buffer, Z-buffer, per-triangle
//! results and every statistic, including the texture counts, which the RTL backend counts at the
//! top's ports (texture-bank words, footprints, covered pixels read by the scan-out).
//!
//! The RustHDL runs are 64x40: a RustHDL frame of the whole top at 320x200 took 369 s, so the large
//! frames (every filter at 320x200, and 640x480) run on the Verilated top, which equals the RustHDL run
//! cycle for cycle here. The RustHDL `cs_tex` alone streams a 320x200 bilinear frame equal to golden
//! (`tb::cs::tests`), and the RustHDL RC and CS draw 320x200 frames in `chipset_frames.rs`.

use golden::format::Screen;
use golden::render::{render, render_frames_with, Frame, RenderOptions, Texturing};
use golden::scene::{builtin, Mesh};
use golden::shade::Shading;
use golden::texcoord::Coords;
use golden::texture::{checker, Filter, Wrap};
use std::sync::Arc;
use tb::chipset::{HostDrive, RtlChipsetTex};

fn texturing(filter: Filter, wrap: Wrap, coords: Coords) -> Texturing {
    Texturing { texture: Arc::new(checker()), source: "built-in checker".into(), filter, coords, wrap }
}

fn options(mesh: &Mesh, screen: Screen, shading: Shading, tx: Option<Texturing>) -> RenderOptions {
    RenderOptions { texturing: tx, ..RenderOptions::for_scene(mesh, screen, shading) }
}

/// The first difference between a golden frame and the RTL's, if any.
fn difference(golden: &Frame, rtl: &Frame) -> Option<String> {
    let w = golden.screen.width as usize;
    for (what, a, b) in [("I-buffer", &golden.hw_index, &rtl.hw_index), ("Z-buffer", &golden.zbuf, &rtl.zbuf), ("index", &golden.index, &rtl.index)] {
        if let Some(i) = (0..a.len()).find(|&i| a[i] != b[i]) {
            return Some(format!("{what} at ({}, {}): golden {:#x}, RTL {:#x}", i % w, i / w, a[i], b[i]));
        }
    }
    if let Some(i) = (0..golden.rgb.len() / 3).find(|&i| golden.rgb[3 * i..3 * i + 3] != rtl.rgb[3 * i..3 * i + 3]) {
        return Some(format!("colour at ({}, {}): golden {:?}, RTL {:?}", i % w, i / w, &golden.rgb[3 * i..3 * i + 3], &rtl.rgb[3 * i..3 * i + 3]));
    }
    if golden.results != rtl.results {
        return Some("per-triangle results".into());
    }
    if golden.stats != rtl.stats {
        return Some(format!("statistics:\n golden {:?}\n RTL    {:?}", golden.stats.texture, rtl.stats.texture));
    }
    None
}

/// A frame of the RTL equals golden's, and a textured one did sample the texture.
fn assert_frame_equals_golden(what: &str, golden: &Frame, rtl: &Frame) {
    if let Some(d) = difference(golden, rtl) {
        panic!("{what}: {d}");
    }
    if let Some(t) = &rtl.stats.texture {
        assert!(t.samples > 0 && t.bank_words_read > 0, "{what}: nothing textured: {t:?}");
    }
}

/// Frames of teapot-floor (and, between them, untextured ones) back to back on one `chipset_tex`,
/// each equal to its golden frame.
fn assert_frames_equal_golden(screen: Screen, frames: &[(Shading, Option<Texturing>)], drive: HostDrive) {
    let mesh = builtin::teapot_floor();
    let jobs: Vec<RenderOptions> = frames.iter().map(|(s, t)| options(&mesh, screen, *s, t.clone())).collect();
    let refs: Vec<(&Mesh, &RenderOptions)> = jobs.iter().map(|o| (&mesh, o)).collect();
    let mut chip = RtlChipsetTex::new(screen, None).unwrap().with_drive(drive);
    let rtl = render_frames_with(&refs, &mut chip).unwrap_or_else(|e| panic!("RTL run failed: {e}"));
    for (k, (opts, r)) in jobs.iter().zip(&rtl).enumerate() {
        let golden = render(&mesh, opts).unwrap();
        let what = format!("frame {} ({:?}, {:?})", k + 1, opts.shading, opts.texturing.as_ref().map(|t| t.filter));
        assert_frame_equals_golden(&what, &golden, r);
        eprintln!("{what}: {:?}", r.stats.texture);
    }
}

#[test]
fn textured_teapot_floor_frames_through_the_rtl_chipset_tex_equal_the_golden_frames_in_every_filter() {
    let screen = Screen::new(64, 40).unwrap();
    let p = Coords::Perspective;
    assert_frames_equal_golden(
        screen,
        &[
            (Shading::Gouraud, Some(texturing(Filter::Nearest, Wrap::Repeat, p))),
            (Shading::Phong, Some(texturing(Filter::Bilinear, Wrap::ClampToEdge, p))),
            (Shading::Gouraud, None),
            (Shading::Gouraud, Some(texturing(Filter::Trilinear, Wrap::Repeat, p))),
            (Shading::Flat, Some(texturing(Filter::Bilinear, Wrap::Repeat, Coords::Affine))),
        ],
        HostDrive::default(),
    );
}

/// Under random gaps and back-pressure on every stream: the generated Verilog of `chipset_tex` under
/// Verilator (`VerilatorChipset::textured`, the harness built with `TEXTURED`) and the RustHDL
/// simulation of the same run each equal golden in every frame, with the same cycle stamps and port
/// counts (the two host loops are one protocol).
#[test]
fn textured_frames_under_random_gaps_through_the_rusthdl_and_the_verilated_chipset_tex_equal_golden_cycle_for_cycle() {
    if !tb::common::require_tools("textured_frames_under_random_gaps_through_the_rusthdl_and_the_verilated_chipset_tex_equal_golden_cycle_for_cycle", &["verilator"]) {
        return;
    }
    use tb::backend::CycleChipset;
    use tb::verilator::VerilatorChipset;
    let screen = Screen::new(64, 40).unwrap();
    let mesh = builtin::teapot_floor();
    let p = Coords::Perspective;
    let frames = [
        (Shading::Phong, Some(texturing(Filter::Trilinear, Wrap::ClampToEdge, p))),
        (Shading::Gouraud, Some(texturing(Filter::Bilinear, Wrap::Repeat, p))),
        (Shading::Gouraud, None),
        (Shading::Gouraud, Some(texturing(Filter::Nearest, Wrap::Repeat, p))),
    ];
    let jobs: Vec<RenderOptions> = frames.iter().map(|(s, t)| options(&mesh, screen, *s, t.clone())).collect();
    let refs: Vec<(&Mesh, &RenderOptions)> = jobs.iter().map(|o| (&mesh, o)).collect();
    let drive = HostDrive::random(20, 30, 29);
    let mut v = VerilatorChipset::textured(screen, None, tb::chipset::VcdScope::Ports).unwrap().with_drive(drive);
    let vf = render_frames_with(&refs, &mut v).unwrap_or_else(|e| panic!("Verilator run failed: {e}"));
    let mut r = RtlChipsetTex::new(screen, None).unwrap().with_drive(drive);
    let rf = render_frames_with(&refs, &mut r).unwrap_or_else(|e| panic!("RustHDL run failed: {e}"));
    for (k, opts) in jobs.iter().enumerate() {
        let golden = render(&mesh, opts).unwrap();
        assert_frame_equals_golden(&format!("frame {}: Verilator", k + 1), &golden, &vf[k]);
        assert_frame_equals_golden(&format!("frame {}: RustHDL", k + 1), &golden, &rf[k]);
        assert_eq!(vf[k].stats, rf[k].stats, "frame {}: statistics of the two backends", k + 1);
    }
    assert_eq!(v.frame_phases(), r.frame_phases(), "cycle stamps and port words per frame");
    assert_eq!(v.cycles(), r.cycles(), "cycles of the run");
}

/// Whole textured frames at 320x200 in every filter and at 640x480 through the Verilated
/// `chipset_tex`, each equal to golden (image, buffers, results, texture counts at the ports).
#[test]
fn textured_frames_at_320x200_and_640x480_through_the_verilated_chipset_tex_equal_golden() {
    if !tb::common::require_tools("textured_frames_at_320x200_and_640x480_through_the_verilated_chipset_tex_equal_golden", &["verilator"]) {
        return;
    }
    use tb::verilator::VerilatorChipset;
    let mesh = builtin::teapot_floor();
    let p = Coords::Perspective;
    let cases = [
        (320, 200, Shading::Gouraud, texturing(Filter::Nearest, Wrap::Repeat, p)),
        (320, 200, Shading::Phong, texturing(Filter::Bilinear, Wrap::ClampToEdge, p)),
        (320, 200, Shading::Gouraud, texturing(Filter::Trilinear, Wrap::Repeat, p)),
        (320, 200, Shading::Gouraud, texturing(Filter::Bilinear, Wrap::Repeat, Coords::Affine)),
        (640, 480, Shading::Gouraud, texturing(Filter::Bilinear, Wrap::Repeat, p)),
        (640, 480, Shading::Phong, texturing(Filter::Trilinear, Wrap::Repeat, p)),
    ];
    for (w, h, shading, tx) in cases {
        let screen = Screen::new(w, h).unwrap();
        let opts = options(&mesh, screen, shading, Some(tx));
        let golden = render(&mesh, &opts).unwrap();
        let mut v = VerilatorChipset::textured(screen, None, tb::chipset::VcdScope::Ports).unwrap();
        let t0 = std::time::Instant::now();
        let f = render_frames_with(&[(&mesh, &opts)], &mut v).unwrap_or_else(|e| panic!("{w}x{h}: Verilator run failed: {e}"));
        let what = format!("{w}x{h} {shading:?} {:?} {:?} {:?}", opts.texturing.as_ref().unwrap().filter, opts.texturing.as_ref().unwrap().wrap, opts.texturing.as_ref().unwrap().coords);
        assert_frame_equals_golden(&what, &golden, &f[0]);
        if opts.texturing.as_ref().unwrap().filter == Filter::Bilinear {
            // Bilinear: four texels per sample, at most four bank words.
            let t = f[0].stats.texture.as_ref().unwrap();
            assert_eq!(t.texels_read, 4 * t.samples, "{what}");
            assert!(t.bank_words_read <= t.texels_read, "{what}");
        }
        eprintln!("{what}: {} cycles, scan-out {} cycles, {:.1} s; {:?}", v.cycle, v.phases.scan_out, t0.elapsed().as_secs_f64(), f[0].stats.texture);
    }
}
