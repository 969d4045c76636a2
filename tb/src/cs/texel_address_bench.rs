//! Bench of `hdl::cs::texel_address` (the texture path's address unit): random coordinates (inside
//! the texture, at texel centres and edges, far outside, at the i32 ends), level sizes 1 to 1024 each
//! way, both filters and both wrap modes, a pixel in most cycles; the RustHDL simulation against
//! `golden::texbank::footprint` delayed by the block's latency, on every output port in every cycle;
//! the same vectors recorded for the Verilog replay. A chain test puts the address unit, a four-bank
//! memory and `texel_filter` together and checks the colours against `Texture::sample_level`.

use crate::common::Rng;
use crate::cs::pack::BitVector;
use crate::cs::pipeline::Pipeline;
use crate::cs::replay::{port, PortSpec, Recording};
use golden::texbank::{footprint, Footprint, LevelGeom};
use golden::texture::Wrap;
use hdl::cs::texel_address::{TexelAddress, TEXEL_ADDRESS_LATENCY};

/// One cycle's inputs.
#[derive(Copy, Clone, Debug)]
pub struct AddressIn {
    pub valid: bool,
    pub s: i32,
    pub t: i32,
    pub geom: LevelGeom,
    pub bilinear: bool,
    pub wrap: Wrap,
}

impl Default for AddressIn {
    fn default() -> Self {
        AddressIn { valid: false, s: 0, t: 0, geom: LevelGeom { w_log2: 0, h_log2: 0, base: 0 }, bilinear: false, wrap: Wrap::Repeat }
    }
}

/// What the block must show in a cycle, given the inputs `TEXEL_ADDRESS_LATENCY` cycles earlier.
pub fn expected(earlier: Option<&AddressIn>) -> Option<Footprint> {
    match earlier {
        Some(i) if i.valid => Some(footprint(i.geom, i.s, i.t, i.bilinear, i.wrap)),
        _ => None,
    }
}

/// The output ports' values for a footprint (all 0 for no pixel).
fn outputs(f: Option<Footprint>) -> (bool, u64, [u64; 4], u64, u64, u64) {
    match f {
        None => (false, 0, [0; 4], 0, 0, 0),
        Some(f) => {
            let rd = (0..4).map(|k| (f.read[k] as u64) << k).sum();
            let route = (0..4).map(|k| (f.route[k] as u64) << (2 * k)).sum();
            (true, rd, f.addr.map(|a| a as u64), route, f.fx as u64, f.fy as u64)
        }
    }
}

pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![port("valid_in", 1), port("s", 32), port("t", 32), port("w_log2", 4), port("h_log2", 4), port("base", 20), port("bilinear", 1), port("clamp", 1)],
        vec![port("valid_out", 1), port("rd", 4), port("addr0", 20), port("addr1", 20), port("addr2", 20), port("addr3", 20), port("route", 8), port("fx", 8), port("fy", 8)],
    )
}

/// A coordinate: anywhere in i32 (1 in 8), within four textures of 0 (half), or on a texel's centre
/// or edge of a 2^log2 texture, or one LSB either side of one (the rest).
fn coordinate(rng: &mut Rng, log2: u32) -> i32 {
    match rng.below(8) {
        0 => rng.next_u64() as i32,
        1 => [i32::MIN, i32::MAX, -1, 0][rng.below(4) as usize],
        2..=4 => (rng.below(8 << 16) as i64 - (4 << 16)) as i32,
        _ => {
            let n = 1i64 << log2;
            let i = rng.below(3 * n as u64) as i64 - n;
            let edge = (i << 16) >> log2;
            let centre = edge + (1 << 15 >> log2);
            let base = if rng.chance(50) { edge } else { centre };
            (base + rng.below(3) as i64 - 1) as i32
        }
    }
}

/// Random inputs: a pixel in `valid_percent` of the cycles.
pub fn stimulus(rng: &mut Rng, cycles: usize, valid_percent: u64) -> Vec<AddressIn> {
    (0..cycles)
        .map(|_| {
            let (w_log2, h_log2) = (rng.below(11) as u32, rng.below(11) as u32);
            AddressIn {
                valid: rng.chance(valid_percent),
                s: coordinate(rng, w_log2),
                t: coordinate(rng, h_log2),
                geom: LevelGeom { w_log2, h_log2, base: rng.below((1 << 20) - (1 << 18)) as u32 },
                bilinear: rng.chance(60),
                wrap: if rng.chance(50) { Wrap::ClampToEdge } else { Wrap::Repeat },
            }
        })
        .collect()
}

/// Drive one cycle's inputs.
fn drive(uut: &mut TexelAddress, inp: &AddressIn) {
    uut.valid_in.next = inp.valid;
    uut.s.next = (inp.s as u32 as u64).into();
    uut.t.next = (inp.t as u32 as u64).into();
    uut.w_log2.next = (inp.geom.w_log2 as u64).into();
    uut.h_log2.next = (inp.geom.h_log2 as u64).into();
    uut.base.next = (inp.geom.base as u64).into();
    uut.bilinear.next = inp.bilinear;
    uut.clamp.next = inp.wrap == Wrap::ClampToEdge;
}

fn got(uut: &TexelAddress) -> (bool, u64, [u64; 4], u64, u64, u64) {
    (
        uut.valid_out.val(),
        uut.rd.val().to_u64(),
        [uut.addr0.val().to_u64(), uut.addr1.val().to_u64(), uut.addr2.val().to_u64(), uut.addr3.val().to_u64()],
        uut.route.val().to_u64(),
        uut.fx.val().to_u64(),
        uut.fy.val().to_u64(),
    )
}

/// One cycle's replay vectors.
fn vectors(inp: &AddressIn, want: &(bool, u64, [u64; 4], u64, u64, u64)) -> (BitVector, BitVector) {
    let mut vin = BitVector::default();
    vin.push(inp.valid as u128, 1);
    vin.push(inp.s as u32 as u128, 32);
    vin.push(inp.t as u32 as u128, 32);
    vin.push(inp.geom.w_log2 as u128, 4);
    vin.push(inp.geom.h_log2 as u128, 4);
    vin.push(inp.geom.base as u128, 20);
    vin.push(inp.bilinear as u128, 1);
    vin.push((inp.wrap == Wrap::ClampToEdge) as u128, 1);
    let mut vout = BitVector::default();
    vout.push(want.0 as u128, 1);
    vout.push(want.1 as u128, 4);
    for a in want.2 {
        vout.push(a as u128, 20);
    }
    vout.push(want.3 as u128, 8);
    vout.push(want.4 as u128, 8);
    vout.push(want.5 as u128, 8);
    (vin, vout)
}

/// Run `inputs` through the RustHDL block, comparing every cycle with `model` (the block computes it
/// of the inputs `TEXEL_ADDRESS_LATENCY` cycles earlier; `golden` passes [`expected`]). Returns the
/// recording.
pub fn run(inputs: &[AddressIn], model: &dyn Fn(Option<&AddressIn>) -> Option<Footprint>, vcd: Option<&std::path::Path>) -> Result<Recording, String> {
    Pipeline {
        name: "texel_address",
        latency: TEXEL_ADDRESS_LATENCY as usize,
        drive,
        clock: |u: &mut TexelAddress, c: bool| u.clock.next = c.into(),
        read: got,
        outputs: "(valid_out, rd, addr0..3, route, fx, fy)",
        vectors,
        ports: replay_ports(),
    }
    .run(inputs, &|earlier| outputs(model(earlier)), vcd)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rust_hdl::prelude::*;
    use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted};
    use crate::cs::pack::rgb888 as pack;
    use crate::cs::replay::replay_iverilog;
    use golden::texbank::{banks, layout};
    use golden::texture::{modulate, Filter, Texture};
    use hdl::cs::texel_filter::{TexelFilter, TEXEL_FILTER_LATENCY};

    fn vectors(seed: u64) -> Vec<AddressIn> {
        let mut rng = Rng::new(seed);
        println!("texel_address: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        stimulus(&mut rng, 6000, 85)
    }

    #[test]
    fn the_texel_address_unit_equals_the_golden_footprint_in_every_cycle() {
        let v = vectors(0xADD7);
        // The stimulus makes the cases that differ: bilinear footprints of four, two and one distinct
        // texels (clamped at an edge or corner, or a one-texel dimension), negative and huge
        // coordinates, one-texel levels.
        let mut reads = [0u32; 5];
        for i in v.iter().filter(|i| i.valid && i.bilinear) {
            reads[footprint(i.geom, i.s, i.t, true, i.wrap).reads() as usize] += 1;
        }
        println!("bilinear footprints by texels read (0..=4): {reads:?}");
        assert!(reads[1] >= 50 && reads[2] >= 50 && reads[4] >= 500, "bilinear footprints by texels read: {reads:?}");
        assert!(v.iter().filter(|i| i.valid && i.s < -(4 << 16)).count() >= 50);
        assert!(v.iter().filter(|i| i.valid && i.geom.w_log2 == 0).count() >= 50);
        let vcd = vcd_wanted().then(|| vcd_path("texel_address", "every_cycle"));
        run(&v, &expected, vcd.as_deref()).unwrap();
    }

    #[test]
    fn the_texel_address_bench_fails_when_the_reference_is_wrong() {
        // The comparison can fail: a reference that repeats where the block was told to clamp.
        let repeating = |earlier: Option<&AddressIn>| match earlier {
            Some(i) if i.valid => Some(footprint(i.geom, i.s, i.t, i.bilinear, Wrap::Repeat)),
            _ => None,
        };
        let e = run(&vectors(0xADD7), &repeating, None).unwrap_err();
        assert!(e.contains("expected"), "{e}");
    }

    /// The address unit, four bank memories (read latency 1) and the texel filter in a chain, as they
    /// will sit in the CS: every pixel's colour is `sample_level`'s texel, MODULATEd, for every level
    /// of a 64x16 texture, nearest and bilinear, repeat and clamp.
    #[test]
    fn the_address_unit_banks_and_texel_filter_together_give_the_samplers_colour() {
        let mut rng = Rng::new(0xC4A1);
        let texels = (0..64 * 16).map(|_| [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8]).collect();
        let tex = Texture::new(64, 16, texels).unwrap();
        let (geoms, mem) = (layout(&tex), banks(&tex));
        let inputs: Vec<(AddressIn, [u8; 3], usize)> = (0..3000)
            .map(|_| {
                let level = rng.below(geoms.len() as u64) as usize;
                let g = geoms[level];
                let a = AddressIn {
                    valid: rng.chance(90),
                    s: coordinate(&mut rng, g.w_log2),
                    t: coordinate(&mut rng, g.h_log2),
                    geom: g,
                    bilinear: rng.chance(50),
                    wrap: if rng.chance(50) { Wrap::ClampToEdge } else { Wrap::Repeat },
                };
                (a, [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8], level)
            })
            .collect();
        let mut addr = TexelAddress::default();
        let mut filt = TexelFilter::default();
        addr.connect_all();
        filt.connect_all();
        // The chain: inputs -> address (3) -> bank read (1) -> filter (3).
        let to_filter = TEXEL_ADDRESS_LATENCY as usize + 1;
        let total = to_filter + TEXEL_FILTER_LATENCY as usize;
        let mut read_q: Option<([u32; 4], u64, u64, u64, bool)> = None;
        let mut checked = 0;
        for t in 0..inputs.len() + total {
            let idle = (AddressIn::default(), [0; 3], 0);
            let inp = inputs.get(t).unwrap_or(&idle);
            drive(&mut addr, &inp.0);
            // The bank memories answer last cycle's addresses; the filter takes them with the colour
            // of the pixel that entered `to_filter` cycles ago.
            let colour = if t >= to_filter { inputs.get(t - to_filter).map_or([0; 3], |i| i.1) } else { [0; 3] };
            match read_q {
                Some((a, route, fx, fy, valid)) => {
                    let word = |slot: usize| pack(mem[((route >> (2 * slot)) & 3) as usize][a[((route >> (2 * slot)) & 3) as usize] as usize]);
                    filt.valid_in.next = valid;
                    filt.t00.next = word(0).into();
                    filt.t10.next = word(1).into();
                    filt.t01.next = word(2).into();
                    filt.t11.next = word(3).into();
                    filt.fx.next = fx.into();
                    filt.fy.next = fy.into();
                }
                None => filt.valid_in.next = false,
            }
            filt.colour.next = pack(colour).into();
            addr.clock.next = false.into();
            filt.clock.next = false.into();
            assert!(simulate(&mut addr, 200) && simulate(&mut filt, 200));
            if t >= total {
                if let Some((a, _, level)) = inputs.get(t - total).filter(|i| i.0.valid) {
                    let filter = if a.bilinear { Filter::Bilinear } else { Filter::Nearest };
                    let want = pack(modulate(tex.sample_level(*level, a.s, a.t, filter, a.wrap), inputs[t - total].1));
                    assert!(filt.valid_out.val(), "cycle {t}");
                    assert_eq!(filt.rgb_out.val().to_u64(), want, "cycle {t}: {a:?}");
                    checked += 1;
                }
            }
            let (valid, _, a, route, fx, fy) = got(&addr);
            read_q = Some((a.map(|x| x as u32), route, fx, fy, valid));
            addr.clock.next = true.into();
            filt.clock.next = true.into();
            assert!(simulate(&mut addr, 200) && simulate(&mut filt, 200));
        }
        assert!(checked > 2500, "{checked}");
    }

    #[test]
    fn the_texel_address_verilog_replays_the_vectors_and_a_changed_half_texel_step_is_caught() {
        if !require_tools("the_texel_address_verilog_replays_the_vectors_and_a_changed_half_texel_step_is_caught", &["iverilog"]) {
            return;
        }
        let rec = run(&vectors(0xADD7), &expected, None).unwrap();
        let v = hdl::cs::texel_address::verilog().unwrap();
        let r = replay_iverilog(&v, "texel_address", &rec, &scratch_dir("cs/texel_address_replay")).unwrap();
        println!("texel_address Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        // The half-texel step of bilinear (2^15) made a quarter texel: the replay must fail.
        let half = "43'h8000";
        assert!(v.contains(half), "the half-texel constant {half} is not in the Verilog");
        let e = replay_iverilog(&v.replacen(half, "43'h4000", 1), "texel_address", &rec, &scratch_dir("cs/texel_address_replay_broken")).unwrap_err();
        assert!(e.contains("addr") || e.contains("fx") || e.contains("rd") || e.contains("route"), "{e}");
    }

    #[test]
    fn the_texel_address_unit_passes_verilator_lint() {
        if !require_tools("the_texel_address_unit_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::texel_address::verilog().unwrap();
        crate::lint::lint(&v, "texel_address", &scratch_dir("cs/lint_texel_address")).unwrap_or_else(|e| panic!("{e}"));
    }
}
