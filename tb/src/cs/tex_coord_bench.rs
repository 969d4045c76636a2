//! Bench of `hdl::cs::tex_coord` (the per-pixel texture coordinate): the planes of random triangles
//! set up as the host and colour setup do (w ratios up to 100, coordinates up to +-2048 textures,
//! slivers that need the host's `fit`), at pixels inside and around them, and raw planes at the ends
//! of their ranges (Q zero, negative or above 2^41; S far beyond what s can hold); a pixel in most
//! cycles. The RustHDL simulation against `golden::texcoord::TexPlanes::coord` delayed by the block's
//! latency, on every output port in every cycle; the same vectors recorded for the Verilog replay.

use crate::common::Rng;
use crate::cs::pack::BitVector;
use crate::cs::pipeline::Pipeline;
use crate::cs::replay::{port, PortSpec, Recording};
use golden::format::{Plane, WinVertex, SUBPIXEL_ONE};
use golden::texcoord::{fit, setup, vertex_values, Coords, PixelCoord, TexPlanes};
use hdl::common::from_i64;
use hdl::cs::tex_coord::{TexCoord, TEX_COORD_LATENCY};

/// One cycle's inputs.
#[derive(Copy, Clone, Debug, Default)]
pub struct CoordIn {
    pub valid: bool,
    pub x: u32,
    pub y: u32,
    pub planes: TexPlanes,
}

/// What the block must show in a cycle, given the inputs `TEX_COORD_LATENCY` cycles earlier.
pub fn expected(earlier: Option<&CoordIn>) -> Option<PixelCoord> {
    match earlier {
        Some(i) if i.valid => Some(i.planes.coord(i.x, i.y)),
        _ => None,
    }
}

/// The output ports' values (all 0 for no pixel): valid, s, t, m, e.
fn outputs(c: Option<PixelCoord>) -> (bool, u64, u64, u64, u64) {
    match c {
        None => (false, 0, 0, 0, 0),
        Some(c) => (true, c.s as u32 as u64, c.t as u32 as u64, c.m as u64, c.e as u64),
    }
}

pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    let mut i = vec![port("valid_in", 1), port("x", 11), port("y", 11)];
    for p in ["sw", "tw", "q"] {
        i.push(port(&format!("{p}_a"), 40));
        i.push(port(&format!("{p}_b"), 40));
        i.push(port(&format!("{p}_c"), 56));
    }
    (i, vec![port("valid_out", 1), port("s", 32), port("t", 32), port("m", 25), port("e", 6)])
}

pub fn uniform(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

/// A signed value of `bits` bits: small, at an end of the range, or anywhere in it.
pub fn raw(rng: &mut Rng, bits: u32) -> i64 {
    let max = (1i64 << (bits - 1)) - 1;
    match rng.below(4) {
        0 => rng.below(2001) as i64 - 1000,
        1 => [max, -max - 1, 0, -1][rng.below(4) as usize],
        _ => ((rng.next_u64() as i64) << (64 - bits)) >> (64 - bits),
    }
}

/// The planes of a random triangle in a 640x480 window, as the host and colour setup make them, and
/// its bounding box.
pub fn triangle(rng: &mut Rng) -> (TexPlanes, [u32; 4]) {
    loop {
        let xs = [0; 3].map(|_| uniform(rng, 0.0, 640.0));
        let ys = [0; 3].map(|_| uniform(rng, 0.0, 480.0));
        let v = [0, 1, 2].map(|k| WinVertex { x: (xs[k] * SUBPIXEL_ONE as f64) as i32, y: (ys[k] * SUBPIXEL_ONE as f64) as i32, z: 0 });
        let range = [8.0, 8.0, 2048.0][rng.below(3) as usize];
        let st = [0; 3].map(|_| [uniform(rng, -range, range), uniform(rng, -range, range)]);
        let w = [0; 3].map(|_| uniform(rng, 1.0, 100.0));
        let coords = if rng.chance(80) { Coords::Perspective } else { Coords::Affine };
        let Ok(values) = vertex_values(w, st, coords) else { continue };
        let (values, _) = fit(&v, values);
        let p = setup(&v, values);
        let lo = |a: [f64; 3]| a.iter().cloned().fold(f64::MAX, f64::min).max(0.0) as u32;
        let hi = |a: [f64; 3], m: u32| (a.iter().cloned().fold(0.0, f64::max) as u32).min(m);
        return (p, [lo(xs), hi(xs, 639), lo(ys), hi(ys, 479)]);
    }
}

/// Random inputs: runs of pixels of one triangle (its box and a few pixels beyond), and one pixel in
/// ten on raw planes; a pixel in `valid_percent` of the cycles.
pub fn stimulus(rng: &mut Rng, cycles: usize, valid_percent: u64) -> Vec<CoordIn> {
    let mut out = Vec::with_capacity(cycles);
    while out.len() < cycles {
        let (planes, b) = triangle(rng);
        for _ in 0..1 + rng.below(40) {
            let mut i = CoordIn {
                valid: rng.chance(valid_percent),
                x: (b[0] + rng.below((b[1] - b[0] + 3) as u64) as u32).min(1023),
                y: (b[2] + rng.below((b[3] - b[2] + 3) as u64) as u32).min(1023),
                planes,
            };
            if rng.chance(10) {
                let mut p = || Plane { a: raw(rng, 40), b: raw(rng, 40), c: raw(rng, 56) };
                i.planes = TexPlanes { sw: p(), tw: p(), q: p() };
                i.x = rng.below(1024) as u32;
                i.y = rng.below(1024) as u32;
            } else if rng.chance(30) {
                // Q with its leading one at a chosen bit (0..=40) and random bits below it, S and T at
                // random magnitudes up to 56 bits.
                let e = rng.below(41) as u32;
                let c = (1i64 << e) | (rng.next_u64() as i64 & ((1i64 << e) - 1));
                i.planes.q = Plane { a: 0, b: 0, c };
                let mut st = || {
                    let bits = 1 + rng.below(56) as u32;
                    Plane { a: 0, b: 0, c: ((rng.next_u64() as i64) << (64 - bits)) >> (64 - bits) }
                };
                i.planes.sw = st();
                i.planes.tw = st();
            }
            out.push(i);
        }
    }
    out.truncate(cycles);
    out
}

/// Drive one cycle's inputs.
pub fn drive(uut: &mut TexCoord, inp: &CoordIn) {
    uut.valid_in.next = inp.valid;
    uut.x.next = (inp.x as u64).into();
    uut.y.next = (inp.y as u64).into();
    let p = &inp.planes;
    uut.sw_a.next = from_i64::<40>(p.sw.a);
    uut.sw_b.next = from_i64::<40>(p.sw.b);
    uut.sw_c.next = from_i64::<56>(p.sw.c);
    uut.tw_a.next = from_i64::<40>(p.tw.a);
    uut.tw_b.next = from_i64::<40>(p.tw.b);
    uut.tw_c.next = from_i64::<56>(p.tw.c);
    uut.q_a.next = from_i64::<40>(p.q.a);
    uut.q_b.next = from_i64::<40>(p.q.b);
    uut.q_c.next = from_i64::<56>(p.q.c);
}

fn got(uut: &TexCoord) -> (bool, u64, u64, u64, u64) {
    (uut.valid_out.val(), uut.s.val().to_u64(), uut.t.val().to_u64(), uut.m.val().to_u64(), uut.e.val().to_u64())
}

/// One cycle's replay vectors.
fn vectors(inp: &CoordIn, want: &(bool, u64, u64, u64, u64)) -> (BitVector, BitVector) {
    let mut vin = BitVector::default();
    vin.push(inp.valid as u128, 1);
    vin.push(inp.x as u128, 11);
    vin.push(inp.y as u128, 11);
    for p in [inp.planes.sw, inp.planes.tw, inp.planes.q] {
        vin.push_signed(p.a, 40);
        vin.push_signed(p.b, 40);
        vin.push_signed(p.c, 56);
    }
    let mut vout = BitVector::default();
    vout.push(want.0 as u128, 1);
    vout.push(want.1 as u128, 32);
    vout.push(want.2 as u128, 32);
    vout.push(want.3 as u128, 25);
    vout.push(want.4 as u128, 6);
    (vin, vout)
}

/// Run `inputs` through the RustHDL block, comparing every cycle with `model` (of the inputs
/// `TEX_COORD_LATENCY` cycles earlier; `golden` passes [`expected`]). Returns the recording.
pub fn run(inputs: &[CoordIn], model: &dyn Fn(Option<&CoordIn>) -> Option<PixelCoord>, vcd: Option<&std::path::Path>) -> Result<Recording, String> {
    Pipeline {
        name: "tex_coord",
        latency: TEX_COORD_LATENCY as usize,
        drive,
        clock: |u: &mut TexCoord, c: bool| u.clock.next = c.into(),
        read: got,
        outputs: "(valid_out, s, t, m, e)",
        vectors,
        ports: replay_ports(),
    }
    .run(inputs, &|earlier| outputs(model(earlier)), vcd)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted};
    use crate::cs::replay::replay_iverilog;

    fn vectors(seed: u64) -> Vec<CoordIn> {
        let mut rng = Rng::new(seed);
        println!("tex_coord: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        stimulus(&mut rng, 6000, 85)
    }

    #[test]
    fn the_texture_coordinate_unit_equals_golden_coord_in_every_cycle() {
        let v = vectors(0x7C0D);
        // The stimulus reaches each path of the datapath: Q clamped up to 1 and down to 2^41 - 1, Q's
        // leading one above 35 (its low bits dropped before the reciprocal) and below 20 (S shifted
        // left), every leading one of Q, and s saturated to 32 bits both ways.
        let valid: Vec<&CoordIn> = v.iter().filter(|i| i.valid).collect();
        let q = |i: &CoordIn| i.planes.q.raw(i.x, i.y);
        let count = |f: &dyn Fn(&CoordIn) -> bool| valid.iter().filter(|i| f(i)).count();
        let low = count(&|i| q(i) < 1);
        let high = count(&|i| q(i) >= 1 << 41);
        let dropped = count(&|i| (36..41).contains(&i.planes.coord(i.x, i.y).e));
        let left = count(&|i| i.planes.coord(i.x, i.y).e < 20);
        let sat_hi = count(&|i| i.planes.coord(i.x, i.y).s == i32::MAX);
        let sat_lo = count(&|i| i.planes.coord(i.x, i.y).s == i32::MIN);
        let inside = count(&|i| i.planes.coord(i.x, i.y).s.unsigned_abs() < 1 << 28);
        println!("Q < 1: {low}, Q >= 2^41: {high}, e 36..40: {dropped}, e < 20: {left}, s saturated high {sat_hi} low {sat_lo}, |s| < 2^12 textures: {inside}");
        let mut by_e = [0u32; 41];
        for i in &valid {
            by_e[i.planes.coord(i.x, i.y).e as usize] += 1;
        }
        println!("pixels by Q's leading one: {by_e:?}");
        assert!(by_e.iter().all(|&n| n >= 20), "some leading one of Q has fewer than 20 pixels: {by_e:?}");
        for (what, n, min) in [("Q < 1", low, 50), ("Q >= 2^41", high, 50), ("e 36..40", dropped, 1000), ("e < 20", left, 20), ("s = i32::MAX", sat_hi, 50), ("s = i32::MIN", sat_lo, 50), ("|s| < 2^28", inside, 3000)] {
            assert!(n >= min, "{what}: {n} pixels, fewer than {min}");
        }
        let vcd = vcd_wanted().then(|| vcd_path("tex_coord", "every_cycle"));
        run(&v, &expected, vcd.as_deref()).unwrap();
    }

    #[test]
    fn the_texture_coordinate_bench_fails_when_the_reference_is_wrong() {
        // The comparison can fail: a reference whose t is one LSB off on odd pixels.
        let off = |earlier: Option<&CoordIn>| {
            expected(earlier).map(|mut c| {
                if earlier.unwrap().x & 1 == 1 {
                    c.t = c.t.wrapping_add(1);
                }
                c
            })
        };
        let e = run(&vectors(0x7C0D), &off, None).unwrap_err();
        assert!(e.contains("expected"), "{e}");
    }

    #[test]
    fn the_texture_coordinate_verilog_replays_the_vectors_and_a_changed_rounding_is_caught() {
        if !require_tools("the_texture_coordinate_verilog_replays_the_vectors_and_a_changed_rounding_is_caught", &["iverilog"]) {
            return;
        }
        let rec = run(&vectors(0x7C0D), &expected, None).unwrap();
        let v = hdl::cs::tex_coord::verilog().unwrap();
        let r = replay_iverilog(&v, "tex_coord", &rec, &scratch_dir("cs/tex_coord_replay")).unwrap();
        println!("tex_coord Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        // The rounding of s and t (2^23 before >> 24) made 0: the replay must fail.
        let half = "60'h800000";
        assert!(v.contains(half), "the rounding constant {half} is not in the Verilog");
        let e = replay_iverilog(&v.replacen(half, "60'h0", 1), "tex_coord", &rec, &scratch_dir("cs/tex_coord_replay_broken")).unwrap_err();
        assert!(e.contains("port s") || e.contains("port t"), "{e}");
    }

    #[test]
    fn the_texture_coordinate_unit_passes_verilator_lint() {
        if !require_tools("the_texture_coordinate_unit_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::tex_coord::verilog().unwrap();
        crate::lint::lint(&v, "tex_coord", &scratch_dir("cs/lint_tex_coord")).unwrap_or_else(|e| panic!("{e}"));
    }
}
