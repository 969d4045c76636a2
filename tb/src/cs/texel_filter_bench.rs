//! Bench of `hdl::cs::texel_filter` (the texture path's bilinear blend and MODULATE): random
//! footprints, weights (their ends 0 and 255 often) and colours, a pixel in most cycles; the RustHDL
//! simulation against `golden::texture::{bilinear, modulate}` delayed by the block's latency, on both
//! output ports in every cycle; the same vectors recorded for the Verilog replay.

use crate::common::Rng;
use crate::cs::pack::{rgb888 as pack, BitVector};
use crate::cs::pipeline::Pipeline;
use crate::cs::replay::{port, PortSpec, Recording};
use golden::texture::{bilinear, modulate};
use hdl::cs::texel_filter::{TexelFilter, TEXEL_FILTER_LATENCY};

/// One cycle's inputs.
#[derive(Copy, Clone, Debug, Default)]
pub struct FilterIn {
    pub valid: bool,
    pub texels: [[u8; 3]; 4],
    pub fx: u8,
    pub fy: u8,
    pub colour: [u8; 3],
}


/// What the block must show in a cycle, given the inputs `TEXEL_FILTER_LATENCY` cycles earlier.
pub fn expected(earlier: Option<&FilterIn>) -> (bool, u64) {
    match earlier {
        Some(i) if i.valid => (true, pack(modulate(bilinear(i.texels, i.fx as u32, i.fy as u32), i.colour))),
        _ => (false, 0),
    }
}

pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![port("valid_in", 1), port("t00", 24), port("t10", 24), port("t01", 24), port("t11", 24), port("fx", 8), port("fy", 8), port("colour", 24)],
        vec![port("valid_out", 1), port("rgb_out", 24)],
    )
}

/// Random inputs: a pixel in `valid_percent` of the cycles; weights and channels at their ends in
/// about a quarter of the draws.
pub fn stimulus(rng: &mut Rng, cycles: usize, valid_percent: u64) -> Vec<FilterIn> {
    let byte = |rng: &mut Rng| -> u8 {
        match rng.below(8) {
            0 => 0,
            1 => 255,
            _ => rng.below(256) as u8,
        }
    };
    (0..cycles)
        .map(|_| FilterIn {
            valid: rng.chance(valid_percent),
            texels: std::array::from_fn(|_| [byte(rng), byte(rng), byte(rng)]),
            fx: byte(rng),
            fy: byte(rng),
            colour: [byte(rng), byte(rng), byte(rng)],
        })
        .collect()
}

/// Drive one cycle's inputs.
fn drive(uut: &mut TexelFilter, inp: &FilterIn) {
    uut.valid_in.next = inp.valid;
    uut.t00.next = pack(inp.texels[0]).into();
    uut.t10.next = pack(inp.texels[1]).into();
    uut.t01.next = pack(inp.texels[2]).into();
    uut.t11.next = pack(inp.texels[3]).into();
    uut.fx.next = (inp.fx as u64).into();
    uut.fy.next = (inp.fy as u64).into();
    uut.colour.next = pack(inp.colour).into();
}

/// One cycle's replay vectors.
fn vectors(inp: &FilterIn, want: &(bool, u64)) -> (BitVector, BitVector) {
    let mut vin = BitVector::default();
    vin.push(inp.valid as u128, 1);
    for k in 0..4 {
        vin.push(pack(inp.texels[k]) as u128, 24);
    }
    vin.push(inp.fx as u128, 8);
    vin.push(inp.fy as u128, 8);
    vin.push(pack(inp.colour) as u128, 24);
    let mut vout = BitVector::default();
    vout.push(want.0 as u128, 1);
    vout.push(want.1 as u128, 24);
    (vin, vout)
}

/// Run `inputs` through the RustHDL block, comparing every cycle with the reference (the block
/// computes `model` of the inputs; `golden` passes [`expected`]). Returns the recording.
pub fn run(inputs: &[FilterIn], model: &dyn Fn(Option<&FilterIn>) -> (bool, u64), vcd: Option<&std::path::Path>) -> Result<Recording, String> {
    Pipeline {
        name: "texel_filter",
        latency: TEXEL_FILTER_LATENCY as usize,
        drive,
        clock: |u: &mut TexelFilter, c: bool| u.clock.next = c.into(),
        read: |u: &TexelFilter| (u.valid_out.val(), u.rgb_out.val().to_u64()),
        outputs: "(valid_out, rgb_out)",
        vectors,
        ports: replay_ports(),
    }
    .run(inputs, model, vcd)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted};
    use crate::cs::replay::replay_iverilog;

    fn vectors(seed: u64) -> Vec<FilterIn> {
        let mut rng = Rng::new(seed);
        println!("texel_filter: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        stimulus(&mut rng, 4000, 85)
    }

    #[test]
    fn the_texel_filter_equals_golden_bilinear_and_modulate_in_every_cycle() {
        let vcd = vcd_wanted().then(|| vcd_path("texel_filter", "every_cycle"));
        run(&vectors(0x7E7), &expected, vcd.as_deref()).unwrap();
    }

    #[test]
    fn the_texel_filter_bench_fails_when_the_reference_is_wrong() {
        // The comparison can fail: a reference without the bilinear rounding is caught.
        let unrounded = |earlier: Option<&FilterIn>| match earlier {
            Some(i) if i.valid => {
                let t = i.texels;
                let (fx, fy) = (i.fx as u32, i.fy as u32);
                let texel: [u8; 3] = std::array::from_fn(|c| {
                    ((t[0][c] as u32 * (256 - fx) * (256 - fy) + t[1][c] as u32 * fx * (256 - fy) + t[2][c] as u32 * (256 - fx) * fy + t[3][c] as u32 * fx * fy) >> 16) as u8
                });
                (true, pack(modulate(texel, i.colour)))
            }
            _ => (false, 0),
        };
        let e = run(&vectors(0x7E7), &unrounded, None).unwrap_err();
        assert!(e.contains("rgb_out"), "{e}");
    }

    #[test]
    fn the_texel_filter_verilog_replays_the_vectors_and_a_changed_rounding_constant_is_caught() {
        if !require_tools("the_texel_filter_verilog_replays_the_vectors_and_a_changed_rounding_constant_is_caught", &["iverilog"]) {
            return;
        }
        let rec = run(&vectors(0x7E7), &expected, None).unwrap();
        let v = hdl::cs::texel_filter::verilog().unwrap();
        let r = replay_iverilog(&v, "texel_filter", &rec, &scratch_dir("cs/texel_filter_replay")).unwrap();
        println!("texel_filter Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        let half = "26'h8000";
        assert!(v.contains(half), "the rounding constant {half} is not in the Verilog");
        let e = replay_iverilog(&v.replacen(half, "26'h0", 1), "texel_filter", &rec, &scratch_dir("cs/texel_filter_replay_broken")).unwrap_err();
        assert!(e.contains("rgb_out"), "{e}");
    }

    #[test]
    fn the_texel_filter_passes_verilator_lint() {
        if !require_tools("the_texel_filter_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::texel_filter::verilog().unwrap();
        crate::lint::lint(&v, "texel_filter", &scratch_dir("cs/lint_texel_filter")).unwrap_or_else(|e| panic!("{e}"));
    }
}
