//! Bench of `hdl::cs::tex_lod` (the per-pixel level of detail): pixels of random triangles (the
//! planes and `coord` of `tex_coord_bench`'s triangles) with texture sizes 1x1 to 1024x1024, and raw
//! inputs at the ends of their ranges (gradients of 0 or of 40 bits, s and t at the i32 ends, every
//! exponent of 1/Q); a pixel in most cycles. The RustHDL simulation against
//! `golden::texcoord::TexPlanes::lod` delayed by the block's latency, on every output port in every
//! cycle; the same vectors recorded for the Verilog replay.

use crate::common::Rng;
use crate::cs::pack::BitVector;
use crate::cs::pipeline::Pipeline;
use crate::cs::replay::{port, PortSpec, Recording};
use crate::cs::tex_coord_bench::{raw, triangle};
use golden::format::Plane;
use golden::texcoord::{PixelCoord, TexPlanes};
use hdl::common::from_i64;
use hdl::cs::tex_lod::{TexLod, TEX_LOD_LATENCY};

/// One cycle's inputs.
#[derive(Copy, Clone, Debug, Default)]
pub struct LodIn {
    pub valid: bool,
    pub coord: PixelCoord,
    pub w_log2: u32,
    pub h_log2: u32,
    pub planes: TexPlanes,
}

/// What the block must show in a cycle, given the inputs `TEX_LOD_LATENCY` cycles earlier.
pub fn expected(earlier: Option<&LodIn>) -> Option<u8> {
    match earlier {
        Some(i) if i.valid => Some(i.planes.lod(i.coord, i.w_log2, i.h_log2)),
        _ => None,
    }
}

pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    let mut i = vec![port("valid_in", 1), port("s", 32), port("t", 32), port("m", 25), port("e", 6), port("w_log2", 4), port("h_log2", 4)];
    for p in ["sw_a", "sw_b", "tw_a", "tw_b", "q_a", "q_b"] {
        i.push(port(p, 40));
    }
    (i, vec![port("valid_out", 1), port("lod", 8)])
}

/// Random inputs: runs of pixels of one triangle, and one pixel in five with raw inputs; a pixel in
/// `valid_percent` of the cycles.
pub fn stimulus(rng: &mut Rng, cycles: usize, valid_percent: u64) -> Vec<LodIn> {
    let mut out = Vec::with_capacity(cycles);
    while out.len() < cycles {
        let (planes, b) = triangle(rng);
        let (w_log2, h_log2) = (rng.below(11) as u32, rng.below(11) as u32);
        for _ in 0..1 + rng.below(40) {
            let (x, y) = (b[0] + rng.below((b[1] - b[0] + 1) as u64) as u32, b[2] + rng.below((b[3] - b[2] + 1) as u64) as u32);
            let mut i = LodIn { valid: rng.chance(valid_percent), coord: planes.coord(x, y), w_log2, h_log2, planes };
            if rng.chance(20) {
                // Gradients of 0 (one in four) or at random widths up to 40 bits.
                let mut g = || if rng.chance(25) { 0 } else { let bits = 1 + rng.below(40) as u32; raw(rng, bits) };
                i.planes = TexPlanes {
                    sw: Plane { a: g(), b: g(), c: 0 },
                    tw: Plane { a: g(), b: g(), c: 0 },
                    q: Plane { a: g(), b: g(), c: 0 },
                };
                let mut st = || match rng.below(4) {
                    0 => [i32::MIN, i32::MAX, 0, -1][rng.below(4) as usize],
                    _ => { let bits = 1 + rng.below(32) as u32; raw(rng, bits) as i32 }
                };
                i.coord = PixelCoord { s: st(), t: st(), m: (1 << 23) + rng.below((1 << 23) + 1) as u32, e: rng.below(41) as u32 };
                i.w_log2 = rng.below(11) as u32;
                i.h_log2 = rng.below(11) as u32;
            }
            out.push(i);
        }
    }
    out.truncate(cycles);
    out
}

fn drive(uut: &mut TexLod, i: &LodIn) {
    uut.valid_in.next = i.valid;
    uut.s.next = (i.coord.s as u32 as u64).into();
    uut.t.next = (i.coord.t as u32 as u64).into();
    uut.m.next = (i.coord.m as u64).into();
    uut.e.next = (i.coord.e as u64).into();
    uut.w_log2.next = (i.w_log2 as u64).into();
    uut.h_log2.next = (i.h_log2 as u64).into();
    let p = &i.planes;
    uut.sw_a.next = from_i64::<40>(p.sw.a);
    uut.sw_b.next = from_i64::<40>(p.sw.b);
    uut.tw_a.next = from_i64::<40>(p.tw.a);
    uut.tw_b.next = from_i64::<40>(p.tw.b);
    uut.q_a.next = from_i64::<40>(p.q.a);
    uut.q_b.next = from_i64::<40>(p.q.b);
}

/// One cycle's replay vectors.
fn vectors(inp: &LodIn, want: &(bool, u64)) -> (BitVector, BitVector) {
    let mut vin = BitVector::default();
    vin.push(inp.valid as u128, 1);
    vin.push(inp.coord.s as u32 as u128, 32);
    vin.push(inp.coord.t as u32 as u128, 32);
    vin.push(inp.coord.m as u128, 25);
    vin.push(inp.coord.e as u128, 6);
    vin.push(inp.w_log2 as u128, 4);
    vin.push(inp.h_log2 as u128, 4);
    let p = &inp.planes;
    for g in [p.sw.a, p.sw.b, p.tw.a, p.tw.b, p.q.a, p.q.b] {
        vin.push_signed(g, 40);
    }
    let mut vout = BitVector::default();
    vout.push(want.0 as u128, 1);
    vout.push(want.1 as u128, 8);
    (vin, vout)
}

/// Run `inputs` through the RustHDL block, comparing every cycle with `model` (of the inputs
/// `TEX_LOD_LATENCY` cycles earlier; `golden` passes [`expected`]). Returns the recording.
pub fn run(inputs: &[LodIn], model: &dyn Fn(Option<&LodIn>) -> Option<u8>, vcd: Option<&std::path::Path>) -> Result<Recording, String> {
    Pipeline {
        name: "tex_lod",
        latency: TEX_LOD_LATENCY as usize,
        drive,
        clock: |u: &mut TexLod, c: bool| u.clock.next = c.into(),
        read: |u: &TexLod| (u.valid_out.val(), u.lod.val().to_u64()),
        outputs: "(valid_out, lod)",
        vectors,
        ports: replay_ports(),
    }
    .run(inputs, &|earlier| model(earlier).map_or((false, 0), |l| (true, l as u64)), vcd)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rust_hdl::prelude::*;
    use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted};
    use crate::cs::replay::replay_iverilog;

    fn vectors(seed: u64) -> Vec<LodIn> {
        let mut rng = Rng::new(seed);
        println!("tex_lod: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        let mut v = stimulus(&mut rng, 8000, 85);
        v.extend(rounding_cases(&mut rng, 100).into_iter().map(|(i, _)| i));
        v
    }

    /// Pixels whose level of detail depends on how rho is rounded when it has one fraction bit too
    /// many (E2 = -1): rho's mantissa M is odd and M + 1 carries into the bits the level of detail
    /// reads. Only ds/dx is non-zero: A_sw = R (18 bits), A_q = 0, so the largest numerator is R 2^20
    /// exactly and M = the top 18 bits of R (m >> 7); e is chosen so that E2 = -1. Each comes with
    /// the level of detail of rho rounded to nearest, (M + 1) >> 1.
    fn rounding_cases(rng: &mut Rng, n: usize) -> Vec<(LodIn, u8)> {
        let mut out = Vec::new();
        while out.len() < n {
            let r = (1u64 << 17) + rng.below(1 << 17);
            let m = (1u64 << 23) + rng.below((1 << 23) + 1);
            let p = r * (m >> 7);
            let drop = 63 - p.leading_zeros() as u64 - 17;
            let mant = p >> drop;
            if mant & 0x1fff != 0x1fff {
                continue;
            }
            // rho = R 2^20 (w_log2 = 0) times m 2^-(e + 24), carried as mant 2^(drop + 20 + 7 - e - 24).
            let e = drop + 20 + 7 - 24 + 1;
            let planes = TexPlanes { sw: Plane { a: r as i64, b: 0, c: 0 }, tw: Plane::default(), q: Plane::default() };
            let i = LodIn { valid: true, coord: PixelCoord { s: rng.next_u64() as i32, t: rng.next_u64() as i32, m: m as u32, e: e as u32 }, w_log2: 0, h_log2: rng.below(11) as u32, planes };
            out.push((i, golden::texture::lod_q4((mant + 1) >> 1)));
        }
        out
    }

    #[test]
    fn the_rounding_cases_round_rho_to_nearest_and_truncation_would_differ() {
        // The directed cases above do what they say: golden's level of detail is that of rho rounded
        // to nearest, and truncating instead would change it.
        for (i, want) in rounding_cases(&mut Rng::new(5), 100) {
            assert_eq!(i.planes.lod(i.coord, i.w_log2, i.h_log2), want, "{i:?}");
            let m18 = (i.coord.m >> 7) as u64;
            let p = i.planes.sw.a as u64 * m18;
            let mant = p >> (63 - p.leading_zeros() as u64 - 17);
            assert_ne!(golden::texture::lod_q4(mant >> 1), want, "{i:?}");
        }
    }

    #[test]
    fn the_level_of_detail_unit_equals_golden_lod_in_every_cycle() {
        let v = vectors(0x10D);
        // The stimulus spreads over the level of detail: magnified (0), the top (160), and most of the
        // values between, on both triangle pixels and raw inputs.
        let mut hist = [0u32; 256];
        for i in v.iter().filter(|i| i.valid) {
            hist[i.planes.lod(i.coord, i.w_log2, i.h_log2) as usize] += 1;
        }
        let distinct = hist.iter().filter(|&&n| n > 0).count();
        println!("lod 0: {}, lod 160: {}, distinct values: {distinct}", hist[0], hist[160]);
        assert!(hist[0] >= 300 && hist[160] >= 100 && distinct >= 120, "lod 0: {}, 160: {}, distinct {distinct}", hist[0], hist[160]);
        let vcd = vcd_wanted().then(|| vcd_path("tex_lod", "every_cycle"));
        run(&v, &expected, vcd.as_deref()).unwrap();
    }

    #[test]
    fn the_level_of_detail_bench_fails_when_the_reference_is_wrong() {
        // The comparison can fail: a reference that forgets t's texture height (h_log2 taken as w_log2).
        let wrong = |earlier: Option<&LodIn>| match earlier {
            Some(i) if i.valid => Some(i.planes.lod(i.coord, i.w_log2, i.w_log2)),
            _ => None,
        };
        let e = run(&vectors(0x10D), &wrong, None).unwrap_err();
        assert!(e.contains("expected"), "{e}");
    }

    #[test]
    fn the_level_of_detail_verilog_replays_the_vectors_and_a_changed_alignment_is_caught() {
        if !require_tools("the_level_of_detail_verilog_replays_the_vectors_and_a_changed_alignment_is_caught", &["iverilog"]) {
            return;
        }
        let rec = run(&vectors(0x10D), &expected, None).unwrap();
        let v = hdl::cs::tex_lod::verilog().unwrap();
        let r = replay_iverilog(&v, "tex_lod", &rec, &scratch_dir("cs/tex_lod_replay")).unwrap();
        println!("tex_lod Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        // The alignment 22 bits above the larger term made 21: the replay must fail.
        let align = "localparam  k22_5 = 5'b10110;";
        assert!(v.contains(align), "the alignment constant is not in the Verilog as {align}");
        let e = replay_iverilog(&v.replacen(align, "localparam  k22_5 = 5'b10101;", 1), "tex_lod", &rec, &scratch_dir("cs/tex_lod_replay_broken")).unwrap_err();
        assert!(e.contains("port lod"), "{e}");
    }

    /// A golden teapot-floor frame at 320x200 textured with `filter` (and the same frame untextured),
    /// and its covered pixels with the texture planes its colour setup made.
    fn floor_frame(filter: golden::texture::Filter, coords: golden::texcoord::Coords) -> (golden::render::Frame, golden::render::Frame, Vec<(u32, u32, TexPlanes)>) {
        use golden::format::Screen;
        use golden::render::{render, render_with, GoldenChipset, RenderOptions, Texturing};
        use golden::scene::builtin;
        use golden::shade::Shading;
        use golden::texture::{checker, Wrap};
        let mesh = builtin::teapot_floor();
        let screen = Screen::new(320, 200).unwrap();
        let plain = RenderOptions { texturing: None, ..RenderOptions::for_scene(&mesh, screen, Shading::Gouraud) };
        let texturing = Texturing { texture: std::sync::Arc::new(checker()), source: "test".into(), filter, coords, wrap: Wrap::Repeat };
        let opts = RenderOptions { texturing: Some(texturing), ..plain.clone() };
        let mut chip = GoldenChipset::new(screen);
        let frame = render_with(&mesh, &opts, &mut chip).unwrap();
        let pixels: Vec<(u32, u32, TexPlanes)> = (0..200u32)
            .flat_map(|y| (0..320u32).map(move |x| (x, y)))
            .filter_map(|(x, y)| {
                let i = frame.hw_index[(y * 320 + x) as usize];
                (i != 0).then(|| (x, y, chip.tdbt[i as usize].expect("a covered pixel's triangle has texture planes")))
            })
            .collect();
        assert!(pixels.len() > 25_000, "{} covered pixels", pixels.len());
        (render(&mesh, &plain).unwrap(), frame, pixels)
    }

    /// `tex_coord` and `tex_lod` in a chain, as they will sit in the CS (the planes' gradients wait
    /// `TEX_COORD_LATENCY` cycles beside the first block), one pixel per clock: each pixel's (s, t,
    /// lod) is checked against `TexPlanes::eval` as it leaves, and returned.
    fn chain(pixels: &[(u32, u32, TexPlanes)], w_log2: u32, h_log2: u32) -> Vec<golden::texcoord::TexCoord> {
        use crate::cs::tex_coord_bench::CoordIn;
        use hdl::cs::tex_coord::{TexCoord, TEX_COORD_LATENCY};
        let mut coord = TexCoord::default();
        let mut lod = TexLod::default();
        coord.connect_all();
        lod.connect_all();
        let (l1, total) = (TEX_COORD_LATENCY as usize, (TEX_COORD_LATENCY + TEX_LOD_LATENCY) as usize);
        let mut out = Vec::with_capacity(pixels.len());
        for t in 0..pixels.len() + total {
            let inp = pixels.get(t).map_or(CoordIn::default(), |&(x, y, planes)| CoordIn { valid: true, x, y, planes });
            crate::cs::tex_coord_bench::drive(&mut coord, &inp);
            lod.w_log2.next = (w_log2 as u64).into();
            lod.h_log2.next = (h_log2 as u64).into();
            // The gradients of the pixel that entered l1 cycles ago.
            if let Some(&(_, _, planes)) = t.checked_sub(l1).and_then(|k| pixels.get(k)) {
                lod.sw_a.next = from_i64::<40>(planes.sw.a);
                lod.sw_b.next = from_i64::<40>(planes.sw.b);
                lod.tw_a.next = from_i64::<40>(planes.tw.a);
                lod.tw_b.next = from_i64::<40>(planes.tw.b);
                lod.q_a.next = from_i64::<40>(planes.q.a);
                lod.q_b.next = from_i64::<40>(planes.q.b);
            }
            coord.clock.next = false.into();
            lod.clock.next = false.into();
            assert!(simulate(&mut coord, 200));
            // tex_lod takes tex_coord's outputs of this cycle.
            lod.valid_in.next = coord.valid_out.val();
            lod.s.next = coord.s.val();
            lod.t.next = coord.t.val();
            lod.m.next = coord.m.val();
            lod.e.next = coord.e.val();
            assert!(simulate(&mut lod, 200));
            if let Some(&(x, y, planes)) = t.checked_sub(l1).and_then(|k| pixels.get(k)) {
                let c = planes.coord(x, y);
                assert_eq!((coord.s.val().to_u64() as u32 as i32, coord.t.val().to_u64() as u32 as i32), (c.s, c.t), "tex_coord at ({x}, {y})");
            }
            if let Some(&(x, y, planes)) = t.checked_sub(total).and_then(|k| pixels.get(k)) {
                let want = planes.eval(x, y, w_log2, h_log2);
                assert!(lod.valid_out.val(), "cycle {t}");
                assert_eq!(lod.lod.val().to_u64() as u8, want.lod, "pixel ({x}, {y}), texture 2^{w_log2} x 2^{h_log2}");
                out.push(want);
            }
            coord.clock.next = true.into();
            lod.clock.next = true.into();
            assert!(simulate(&mut coord, 200) && simulate(&mut lod, 200));
        }
        assert_eq!(out.len(), pixels.len());
        out
    }

    /// The two blocks in a chain on every covered pixel of a golden teapot-floor frame (31,099 pixels,
    /// the planes its colour setup made), textures 256x256 and 1024x64, and of the frame with affine
    /// coordinates (1/w = 2^24 at every vertex): (s, t, lod) = `eval`.
    #[test]
    fn tex_coord_and_tex_lod_together_give_golden_eval_on_every_pixel_of_a_textured_frame() {
        use golden::texcoord::Coords;
        let (_, _, affine) = floor_frame(golden::texture::Filter::Trilinear, Coords::Affine);
        chain(&affine, 8, 8);
        let (_, _, pixels) = floor_frame(golden::texture::Filter::Trilinear, Coords::Perspective);
        for (w_log2, h_log2) in [(8, 8), (10, 6)] {
            let levels: std::collections::BTreeSet<u8> = chain(&pixels, w_log2, h_log2).iter().map(|c| c.lod >> 4).collect();
            println!("texture 2^{w_log2} x 2^{h_log2}: {} pixels, levels {levels:?}", pixels.len());
            assert!(levels.len() >= 4, "the frame should span several mipmap levels: {levels:?}");
        }
    }

    /// The whole per-pixel texture path in RTL: `tex_coord`, `tex_lod` and `texture_sampler` (with its
    /// four banks) give every covered pixel of the golden textured teapot-floor frame at 320x200, for
    /// nearest, bilinear and trilinear. The texture unit is checked against its cycle model on every
    /// port in every cycle (`texture_sampler_bench::run`), fed with the chain's (s, t, lod) and the
    /// untextured frame's colour, and each pixel's colour from the model is the textured frame's.
    #[test]
    fn the_rtl_texture_path_reproduces_every_pixel_of_golden_textured_frames() {
        use crate::cs::texture_sampler_bench::{run, Run};
        use golden::cycle::texture_sampler::SamplerPixel;
        use golden::texture::{checker, modulate, Filter, Wrap};
        for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
            let (plain, textured, pixels) = floor_frame(filter, golden::texcoord::Coords::Perspective);
            let coords = chain(&pixels, 8, 8);
            let colour = |x: u32, y: u32, f: &golden::render::Frame| {
                let p = 3 * (y * 320 + x) as usize;
                [f.rgb[p], f.rgb[p + 1], f.rgb[p + 2]]
            };
            let run_pixels: Vec<(usize, SamplerPixel)> = pixels.iter().zip(&coords).map(|(&(x, y, _), c)| (0, SamplerPixel { s: c.s, t: c.t, lod: c.lod, colour: colour(x, y, &plain), textured: true })).collect();
            let r = Run { texture: checker(), filter, wrap: Wrap::Repeat, pixels: run_pixels };
            let (_, m) = run(&r, r.model(), 1, None).unwrap();
            assert_eq!(m.pixels, pixels.len() as u64);
            let mut wrong = 0;
            for (&(x, y, _), c) in pixels.iter().zip(&coords) {
                let rgb = modulate(r.texture.sample(c.s, c.t, c.lod, filter, Wrap::Repeat), colour(x, y, &plain));
                wrong += (rgb != colour(x, y, &textured)) as u32;
            }
            println!("{filter:?}: {} pixels, {} cycles, {} bank words, {wrong} different from the golden frame", m.pixels, m.cycles, m.bank_words);
            assert_eq!(wrong, 0, "{filter:?}");
        }
    }

    #[test]
    fn the_level_of_detail_unit_passes_verilator_lint() {
        if !require_tools("the_level_of_detail_unit_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::tex_lod::verilog().unwrap();
        crate::lint::lint(&v, "tex_lod", &scratch_dir("cs/lint_tex_lod")).unwrap_or_else(|e| panic!("{e}"));
    }
}
