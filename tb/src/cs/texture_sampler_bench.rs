//! Bench of `hdl::cs::texture_sampler` (level choice, address unit, four banks, texel filter,
//! trilinear blend, MODULATE): a random texture in four bank memories (read latency 1, a disabled
//! bank returns noise), its level table loaded through the block's port, then pixels with random
//! gaps, held while `ready` is low. Every cycle the bench checks `ready`, the bank ports and the
//! result against the cycle model `golden::cycle::texture_sampler` (its timing: the footprint of the
//! level issued three cycles earlier, the colour `modulate(Texture::sample(..), colour)` of the pixel
//! accepted eight cycles earlier; a trilinear pixel between two levels takes two cycles).

use crate::common::{Rng, Trace};
use crate::cs::pack::{rgb888 as pack, BitVector};
use crate::cs::replay::{port, PortSpec, Recording};
use golden::cycle::texture_sampler::{SamplerPixel, TextureSamplerModel};
use golden::texbank::{banks, layout, LevelGeom, TEXTURE_BANKS};
use golden::texture::{Filter, Texture, Wrap, LOD_FRAC};
use hdl::cs::texture_sampler::TextureSampler;
use rust_hdl::prelude::*;

/// A run: the texture, its settings and the pixels, each offered after `gap` idle cycles.
pub struct Run {
    pub texture: Texture,
    pub filter: Filter,
    pub wrap: Wrap,
    pub pixels: Vec<(usize, SamplerPixel)>,
}

impl Run {
    /// The cycle model of this run's texture and settings.
    pub fn model(&self) -> TextureSamplerModel {
        TextureSamplerModel::new(self.texture.clone(), self.filter, self.wrap)
    }
}

/// What the run measured at the ports.
#[derive(Clone, Debug, Default)]
pub struct Measured {
    /// Cycles from the end of the level table's load to the last result, inclusive.
    pub cycles: u64,
    pub pixels: u64,
    /// Bank words read (read enables seen on `tex_rd`).
    pub bank_words: u64,
}


pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![
            port("valid_in", 1),
            port("s", 32),
            port("t", 32),
            port("lod", 8),
            port("colour", 24),
            port("textured", 1),
            port("w0_log2", 4),
            port("h0_log2", 4),
            port("last_level", 4),
            port("filter", 2),
            port("clamp", 1),
            port("base_we", 1),
            port("base_sel", 4),
            port("base_data", 20),
            port("tex_data0", 24),
            port("tex_data1", 24),
            port("tex_data2", 24),
            port("tex_data3", 24),
        ],
        vec![port("ready", 1), port("tex_rd", 4), port("tex_addr0", 20), port("tex_addr1", 20), port("tex_addr2", 20), port("tex_addr3", 20), port("valid_out", 1), port("rgb_out", 24)],
    )
}

/// Random pixels: coordinates within a few textures of 0 or anywhere, levels of detail over the whole
/// range (fractions 0 often, so whole-level trilinear occurs), a gap before a pixel in `gap_percent`.
pub fn pixels(rng: &mut Rng, n: usize, gap_percent: u64) -> Vec<(usize, SamplerPixel)> {
    (0..n)
        .map(|_| {
            let gap = if rng.chance(gap_percent) { 1 + rng.below(3) as usize } else { 0 };
            let coord = |rng: &mut Rng| if rng.chance(10) { rng.next_u64() as i32 } else { (rng.below(6 << 16) as i64 - (2 << 16)) as i32 };
            let lod = if rng.chance(25) { (rng.below(12) << LOD_FRAC) as u8 } else { rng.below(176) as u8 };
            let colour = [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8];
            // One in ten passes untextured (the CS's background), whatever its coordinates say.
            (gap, SamplerPixel { s: coord(rng), t: coord(rng), lod, colour, textured: !rng.chance(10) })
        })
        .collect()
}

/// The `filter` port's code of a filter (`texture_sampler`, `cs_tex`).
pub fn filter_code(f: Filter) -> u64 {
    match f {
        Filter::Nearest => 0,
        Filter::Bilinear => 1,
        Filter::Trilinear => 2,
    }
}

/// Drive the run through the RustHDL block, checking every port in every cycle against `model`
/// (normally [`Run::model`]).
pub fn run(r: &Run, mut model: TextureSamplerModel, seed: u64, vcd: Option<&std::path::Path>) -> Result<(Recording, Measured), String> {
    let mut uut = TextureSampler::default();
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("texture_sampler design check: {e:?}"))?;
    let mut trace = Trace::new(&uut, vcd)?;
    let (pi, po) = replay_ports();
    let mut rec = Recording::new(pi, po);
    let geoms: Vec<LevelGeom> = layout(&r.texture);
    let mem = banks(&r.texture);
    let last = geoms.len() - 1;
    let (w0, h0) = (geoms[0].w_log2, geoms[0].h_log2);
    let filter_code = filter_code(r.filter);
    let mut noise = Rng::new(seed ^ 0x5EED);
    let mut m = Measured::default();
    let mut read_prev: Option<([bool; 4], [u32; 4])> = None;
    let (mut next, mut gap_left) = (0usize, r.pixels.first().map_or(0, |p| p.0));
    let loads = geoms.len();
    let mut cyc = 0usize;
    let mut last_out = 0usize;
    loop {
        // Inputs of this cycle.
        let loading = cyc < loads;
        uut.base_we.next = loading;
        uut.base_sel.next = (cyc.min(15) as u64).into();
        uut.base_data.next = (if loading { geoms[cyc].base as u64 } else { 0 }).into();
        uut.w0_log2.next = (w0 as u64).into();
        uut.h0_log2.next = (h0 as u64).into();
        uut.last_level.next = (last as u64).into();
        uut.filter.next = filter_code.into();
        uut.clamp.next = r.wrap == Wrap::ClampToEdge;
        let offer = if !loading && next < r.pixels.len() && gap_left == 0 { Some(r.pixels[next].1) } else { None };
        let p = offer.unwrap_or(SamplerPixel { s: 0, t: 0, lod: 0, colour: [0; 3], textured: true });
        uut.valid_in.next = offer.is_some();
        uut.s.next = (p.s as u32 as u64).into();
        uut.t.next = (p.t as u32 as u64).into();
        uut.lod.next = (p.lod as u64).into();
        uut.colour.next = pack(p.colour).into();
        uut.textured.next = p.textured;
        let mut data = [0u64; 4];
        for b in 0..TEXTURE_BANKS {
            data[b] = match read_prev {
                Some((rd, a)) if rd[b] => pack(mem[b][a[b] as usize]),
                _ => noise.next_u64() & 0xff_ffff,
            };
        }
        uut.tex_data0.next = data[0].into();
        uut.tex_data1.next = data[1].into();
        uut.tex_data2.next = data[2].into();
        uut.tex_data3.next = data[3].into();
        uut.clock.next = false.into();
        if !simulate(&mut uut, 500) {
            return Err(format!("texture_sampler did not settle in cycle {cyc}"));
        }
        trace.dump(&uut, 10 * cyc as u64)?;

        // The model (the level table's load is not a model cycle: no pixel is offered then).
        let out = if loading { Default::default() } else { model.step(offer.as_ref()) };
        let ready = out.ready || loading;
        let want_fp = out.banks;
        let want = (
            ready,
            (0..4).map(|k| (want_fp.read[k] as u64) << k).sum::<u64>(),
            want_fp.addr.map(|a| a as u64),
            out.rgb.is_some(),
            out.rgb.map_or(0, pack),
        );
        let got = (
            uut.ready.val(),
            uut.tex_rd.val().to_u64(),
            [uut.tex_addr0.val().to_u64(), uut.tex_addr1.val().to_u64(), uut.tex_addr2.val().to_u64(), uut.tex_addr3.val().to_u64()],
            uut.valid_out.val(),
            uut.rgb_out.val().to_u64(),
        );
        if got != want {
            return Err(trace.fail(cyc as u64, format!("(ready, tex_rd, tex_addr0..3, valid_out, rgb_out) = {got:?}, expected {want:?} (offer {offer:?})")));
        }
        m.bank_words += want.1.count_ones() as u64;
        m.pixels += want.3 as u64;
        if want.3 {
            last_out = cyc;
        }
        read_prev = Some((want_fp.read, want_fp.addr));
        let mut vin = BitVector::default();
        vin.push(offer.is_some() as u128, 1);
        vin.push(p.s as u32 as u128, 32);
        vin.push(p.t as u32 as u128, 32);
        vin.push(p.lod as u128, 8);
        vin.push(pack(p.colour) as u128, 24);
        vin.push(p.textured as u128, 1);
        vin.push(w0 as u128, 4);
        vin.push(h0 as u128, 4);
        vin.push(last as u128, 4);
        vin.push(filter_code as u128, 2);
        vin.push((r.wrap == Wrap::ClampToEdge) as u128, 1);
        vin.push(loading as u128, 1);
        vin.push(cyc.min(15) as u128, 4);
        vin.push(if loading { geoms[cyc].base as u128 } else { 0 }, 20);
        for d in data {
            vin.push(d as u128, 24);
        }
        let mut vout = BitVector::default();
        vout.push(want.0 as u128, 1);
        vout.push(want.1 as u128, 4);
        for a in want.2 {
            vout.push(a as u128, 20);
        }
        vout.push(want.3 as u128, 1);
        vout.push(want.4 as u128, 24);
        rec.push(vin, vout);
        uut.clock.next = true.into();
        if !simulate(&mut uut, 500) {
            return Err(format!("texture_sampler did not settle in cycle {cyc}"));
        }
        trace.dump(&uut, 10 * cyc as u64 + 5)?;

        // Advance the stimulus.
        if !loading {
            if offer.is_some() && ready {
                next += 1;
                gap_left = r.pixels.get(next).map_or(0, |p| p.0);
            } else if offer.is_none() && gap_left > 0 {
                gap_left -= 1;
            }
        }
        cyc += 1;
        if next >= r.pixels.len() && model.idle() {
            break;
        }
        if cyc > 4 * r.pixels.len() + 100 {
            return Err(format!("texture_sampler: run did not end ({next} of {} pixels accepted)", r.pixels.len()));
        }
    }
    trace.end(10 * cyc as u64);
    m.cycles = (last_out + 1 - loads) as u64;
    Ok((rec, m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted};
    use crate::cs::replay::replay_iverilog;
    use hdl::cs::texture_sampler::TEXTURE_SAMPLER_LATENCY;

    fn texture(rng: &mut Rng, w: u32, h: u32) -> Texture {
        let texels = (0..w * h).map(|_| [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8]).collect();
        Texture::new(w, h, texels).unwrap()
    }

    fn runs(seed: u64) -> Vec<Run> {
        let mut rng = Rng::new(seed);
        println!("texture_sampler: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        let mut out = Vec::new();
        for (w, h) in [(64, 16), (8, 128), (1, 1)] {
            for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
                for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
                    let texture = texture(&mut rng, w, h);
                    let pixels = pixels(&mut rng, 300, 20);
                    out.push(Run { texture, filter, wrap, pixels });
                }
            }
        }
        out
    }

    #[test]
    fn the_texture_sampler_equals_golden_sample_and_modulate_on_every_port_in_every_cycle() {
        let mut back_to_back_pairs = 0;
        for (k, r) in runs(0x5A3).iter().enumerate() {
            let vcd = (vcd_wanted() && k == 0).then(|| vcd_path("texture_sampler", "every_cycle"));
            let (_, m) = run(r, r.model(), k as u64, vcd.as_deref()).unwrap_or_else(|e| panic!("run {k} ({:?} {:?}): {e}", r.filter, r.wrap));
            assert_eq!(m.pixels, r.pixels.len() as u64);
            let two = |p: &SamplerPixel| r.model().takes_two_cycles(p);
            let pairs = r.pixels.iter().filter(|p| two(&p.1)).count();
            back_to_back_pairs += r.pixels.windows(2).filter(|w| w[1].0 == 0 && two(&w[0].1) && two(&w[1].1)).count();
            // One cycle per pixel, two per trilinear pair, one per gap cycle: the block never waits
            // otherwise.
            let gaps: usize = r.pixels.iter().map(|p| p.0).sum();
            assert_eq!(m.cycles, (r.pixels.len() + pairs + gaps) as u64 + TEXTURE_SAMPLER_LATENCY, "run {k}");
            println!("run {k} {}x{} {:?} {:?}: {} pixels ({pairs} two-level) in {} cycles, {} bank words", r.texture.size().0, r.texture.size().1, r.filter, r.wrap, m.pixels, m.cycles, m.bank_words);
        }
        assert!(back_to_back_pairs > 100, "{back_to_back_pairs}");
    }

    #[test]
    fn the_texture_sampler_bench_fails_when_the_reference_is_wrong() {
        // A model told to repeat where the block clamps is caught.
        let r = runs(0x5A3).into_iter().find(|r| r.filter == Filter::Bilinear && r.wrap == Wrap::ClampToEdge && r.texture.size() == (64, 16)).unwrap();
        let wrong = TextureSamplerModel::new(r.texture.clone(), r.filter, Wrap::Repeat);
        let e = run(&r, wrong, 0, None).unwrap_err();
        assert!(e.contains("expected"), "{e}");
    }

    #[test]
    fn the_texture_sampler_verilog_replays_and_a_changed_blend_rounding_is_caught() {
        if !require_tools("the_texture_sampler_verilog_replays_and_a_changed_blend_rounding_is_caught", &["iverilog"]) {
            return;
        }
        let all = runs(0x5A3);
        let r = all.iter().find(|r| r.filter == Filter::Trilinear && r.wrap == Wrap::Repeat && r.texture.size() == (64, 16)).unwrap();
        let (rec, _) = run(r, r.model(), 1, None).unwrap();
        let v = hdl::cs::texture_sampler::verilog().unwrap();
        let dir = scratch_dir("cs/texture_sampler_replay");
        let rep = replay_iverilog(&v, "texture_sampler", &rec, &dir).unwrap();
        println!("texture_sampler Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", rep.cycles, rep.seconds);
        let eight = "localparam  k8_13 = 13'b1000;";
        assert!(v.contains(eight), "the blend's rounding constant is not in the Verilog");
        let e = replay_iverilog(&v.replacen(eight, "localparam  k8_13 = 13'b0;", 1), "texture_sampler", &rec, &scratch_dir("cs/texture_sampler_replay_broken")).unwrap_err();
        assert!(e.contains("rgb_out"), "{e}");
    }

    #[test]
    fn the_texture_sampler_passes_verilator_lint() {
        if !require_tools("the_texture_sampler_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::texture_sampler::verilog().unwrap();
        crate::lint::lint(&v, "texture_sampler", &scratch_dir("cs/lint_texture_sampler")).unwrap_or_else(|e| panic!("{e}"));
    }
}
