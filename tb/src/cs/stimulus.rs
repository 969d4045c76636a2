//! Random stimulus of colour setup and the Color Shader, shared by their tests and the mutation
//! cover (`crate::mutation`): commands, TdbS records, I-buffers and Phong constants at the formats'
//! limits, and the recordings the Verilog replays use.

use super::color_shader_bench::{self as csb, CsDrive, FrameSpec};
use super::colour_setup_bench::{self as setb, SetupDrive};
use super::replay::Recording;
use crate::common::Rng;
use golden::cycle::color_shader::{phong_config, CsConfigWrite, CsMemories};
use golden::cycle::colour_setup::SetupCmd;
use golden::format::{Plane, WINDOW_MAX, WINDOW_MIN};
use golden::format::{CS_GLOSS_LOG2_MAX, CS_LIGHTS, CS_MATERIALS};
use golden::shade::{normal_q14, PhongLights, PhongMaterial, TdbsEntry};

pub fn rand_i16(rng: &mut Rng, lo: i32, hi: i32) -> i16 {
    (lo + rng.below((hi - lo) as u64) as i32) as i16
}

/// Random colour-setup commands: flat ones, zero-area ones, realistic Gouraud and Phong ones, tiny
/// triangles with steep gradients (A/B saturation), and full-range fields (20-bit coordinates, 16-bit
/// values: C saturation).
pub fn random_commands(n: usize, rng: &mut Rng) -> Vec<SetupCmd> {
    (0..n)
        .map(|i| {
            let index = 1 + rng.below(65535) as u16;
            let material = rng.below(4) as u16;
            let mut c = SetupCmd { index, material, ..Default::default() };
            let kind = rng.below(10);
            let (lo, hi, span) = match kind {
                0 | 1 => (WINDOW_MIN, WINDOW_MAX, WINDOW_MAX - WINDOW_MIN),
                2 => (-4000 * 16, 8000 * 16, 4),
                _ => (-5120 * 16, 10240 * 16, 4000 * 16),
            };
            let x0 = lo + rng.below((hi - lo) as u64) as i32;
            let y0 = lo + rng.below((hi - lo) as u64) as i32;
            for k in 0..3 {
                let dx = rng.below(2 * span as u64 + 1) as i32 - span;
                let dy = rng.below(2 * span as u64 + 1) as i32 - span;
                c.x[k] = (x0 + if k == 0 { 0 } else { dx }).clamp(WINDOW_MIN, WINDOW_MAX);
                c.y[k] = (y0 + if k == 0 { 0 } else { dy }).clamp(WINDOW_MIN, WINDOW_MAX);
            }
            for k in 0..3 {
                for ch in 0..3 {
                    c.values[k][ch] = match kind {
                        0 | 2 => rand_i16(rng, -32768, 32767),
                        4 => rand_i16(rng, -16384, 16385),
                        _ => rand_i16(rng, 0, 256),
                    };
                }
            }
            if kind == 3 {
                // Zero area: vertex 2 on the line through vertices 0 and 1 (or all three equal).
                let t = if i % 2 == 0 { 2 } else { 0 };
                c.x[2] = (c.x[0] + t * (c.x[1] - c.x[0])).clamp(WINDOW_MIN, WINDOW_MAX);
                c.y[2] = (c.y[0] + t * (c.y[1] - c.y[0])).clamp(WINDOW_MIN, WINDOW_MAX);
                if t == 0 {
                    c.x[1] = c.x[0];
                    c.y[1] = c.y[0];
                }
            }
            if kind == 5 {
                c.flat = true;
                c.flat_rgb = [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8];
            }
            c
        })
        .collect()
}

/// A random plane: mostly within the formats' useful range, sometimes at the extremes.
pub fn random_plane(rng: &mut Rng) -> Plane {
    let pick = |rng: &mut Rng, bits: u32, frac_of: u64| -> i64 {
        match rng.below(8) {
            0 => -(1i64 << (bits - 1)),
            1 => (1i64 << (bits - 1)) - 1,
            2 => (rng.next_u64() as i64) >> (64 - bits),
            _ => (rng.below(2 * frac_of + 1) as i64) - frac_of as i64,
        }
    };
    Plane { a: pick(rng, 40, 3 << 16), b: pick(rng, 40, 3 << 16), c: pick(rng, 56, 300 << 16) }
}

/// Memories with random TdbS records and a random I-buffer of `w` x `h` (a quarter background).
pub fn random_memories(rng: &mut Rng, w: u32, h: u32, records: usize) -> CsMemories {
    let tdbs: Vec<TdbsEntry> =
        (0..records).map(|_| TdbsEntry { planes: [random_plane(rng), random_plane(rng), random_plane(rng)], material: rng.below(65536) as u16 }).collect();
    let ibuf = (0..w * h).map(|_| if rng.chance(25) { 0 } else { 1 + rng.below(records as u64 - 1) as u16 }).collect();
    let zbuf = (0..w * h).map(|_| rng.below(1 << 24) as u32).collect();
    CsMemories::new(ibuf, zbuf, tdbs)
}

/// Random Phong constants at the RTL's limits: [`CS_LIGHTS`] lights (unit L and H, sometimes any
/// 16-bit vector), [`CS_MATERIALS`] materials with coefficients anywhere in 16 bits and every gloss.
pub fn random_lights(rng: &mut Rng) -> PhongLights {
    let vector = |rng: &mut Rng| -> [i64; 3] {
        if rng.chance(15) {
            [0, 1, 2].map(|_| rng.below(65536) as i64 - 32768)
        } else {
            let v = [0, 1, 2].map(|_| rng.below(2001) as f64 - 1000.0);
            normal_q14([v[0], v[1], v[2] + 0.5])
        }
    };
    let l = (0..CS_LIGHTS).map(|_| vector(rng)).collect();
    let h = (0..CS_LIGHTS).map(|_| vector(rng)).collect();
    let c = |rng: &mut Rng| [0, 1, 2].map(|_| if rng.chance(10) { 65535 } else { rng.below(1 << 15) as i64 });
    let materials = (0..CS_MATERIALS)
        .map(|_| PhongMaterial {
            ambient: c(rng),
            diffuse: (0..CS_LIGHTS).map(|_| c(rng)).collect(),
            specular: (0..CS_LIGHTS).map(|_| c(rng)).collect(),
            gloss_log2: rng.below(CS_GLOSS_LOG2_MAX as u64 + 1) as u32,
        })
        .collect();
    PhongLights { l, h, materials }
}

/// Writes the CS must ignore: light addresses past its units, material slots past its lights.
pub fn ignored_writes(rng: &mut Rng) -> Vec<CsConfigWrite> {
    let mut w = vec![CsConfigWrite::Light { address: CS_LIGHTS as u32, l: [123, -5, 77], h: [-1, -2, -3] }];
    for slot in CS_LIGHTS as u32 + 1..8 {
        w.push(CsConfigWrite::Material { address: rng.below(CS_MATERIALS as u64) as u32, slot, words: [0xffff; 6] });
    }
    w
}

/// Normal planes of unit scale (Q14 at the plane's centre): x, y and z each start within +-20000 and
/// step at most `step` per pixel, with no fraction bits.
fn unit_normal_planes(rng: &mut Rng, step: u64) -> [Plane; 3] {
    [0, 1, 2].map(|_| Plane {
        a: (rng.below(2 * step + 1) as i64 - step as i64) << 16,
        b: (rng.below(2 * step + 1) as i64 - step as i64) << 16,
        c: (rng.below(2 * 20000 + 1) as i64 - 20000) << 16,
    })
}

/// The mutation cover's second recording of the CS (`crate::mutation`, after [`cs_replay_recording`]):
/// three Phong frames of 64x32 over records whose planes give normals of unit scale (Q14, as colour
/// setup makes them from unit vertex normals) that turn across the frame, so that the normaliser and
/// the light units see the range they meet in scenes; the replay's random planes give mostly short or
/// saturated normals. Added for the survivors of the first cover run, 28 of which were in the light
/// units.
pub fn cs_unit_normal_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let mut mem = random_memories(&mut rng, 64, 32, 200);
    for rec in mem.tdbs.iter_mut().skip(100) {
        rec.planes = unit_normal_planes(&mut rng, 400);
        rec.material = rng.below(65536) as u16;
    }
    let lights = random_lights(&mut rng);
    let mut config = ignored_writes(&mut rng);
    config.extend(phong_config(&lights)?);
    let frames = [[7, 8, 9], [255, 0, 128], [0, 255, 1]].map(|bg| FrameSpec { width: 64, height: 32, background: bg, clear_behind: false, phong: true });
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::run_rtl_vs_model("cs_unit_normals", &mut mem, &frames, &config, drive, true)?;
    run.recording.ok_or_else(|| "CS bench: no recording".to_string())
}

/// The mutation cover's third part of the CS stimulus (`crate::mutation`, after
/// [`cs_unit_normal_recording`]): `sets` recordings, each from reset with its own random lights and
/// materials: a Phong frame of 48x24 over unit-scale normals, then a 3x1000 frame in Phong and one in
/// Gouraud, so that the plane products see pixel rows up to 999 (the other frames stop at row 31).
/// One light set per recording left light 1's units and the colour products seeing few values: 44 of
/// the 200 mutants drawn on 2026-11-29 survived the first two recordings, most of them there.
pub fn cs_light_set_recordings(seed: u64, sets: usize) -> Result<Vec<Recording>, String> {
    let mut rng = Rng::new(seed);
    (0..sets)
        .map(|k| {
            let mut mem = random_memories(&mut rng, 3, 1000, 150);
            for rec in mem.tdbs.iter_mut().skip(1) {
                rec.planes = unit_normal_planes(&mut rng, 600);
            }
            let lights = random_lights(&mut rng);
            let config = phong_config(&lights)?;
            let bg = [0, 1, 2].map(|_| rng.below(256) as u8);
            let frames = [
                FrameSpec { width: 48, height: 24, background: bg, clear_behind: false, phong: true },
                FrameSpec { width: 3, height: 1000, background: bg, clear_behind: false, phong: true },
                FrameSpec { width: 3, height: 1000, background: bg, clear_behind: false, phong: false },
            ];
            let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed: seed + k as u64 };
            let run = csb::run_rtl_vs_model(&format!("cs_light_set_{k}"), &mut mem, &frames, &config, drive, true)?;
            run.recording.ok_or_else(|| "CS bench: no recording".to_string())
        })
        .collect()
}

/// A colour plane's gradient: at most 1/4 per pixel either way, every fraction bit random.
fn quarter_step(rng: &mut Rng) -> i64 {
    rng.below(2 * (1 << 14) + 1) as i64 - (1 << 14)
}

/// The mutation cover's last part of the CS stimulus: Gouraud frames (48x24, 3x1000, 1000x3) over
/// colour planes that stay inside 0..=255 across them, with every fraction bit random, so that the
/// plane products' and the constants' low bits reach the rounding. The other recordings' Gouraud
/// planes are random over the whole range and saturate within a few pixels, and in Phong a plane's
/// fraction bits rarely move the 8-bit colour.
pub fn cs_gouraud_fraction_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let mut mem = random_memories(&mut rng, 3, 1000, 150);
    // A start in 0..=255 (c): a frame edge of 1000 pixels can still leave the range, which the clamp
    // then also sees.
    for rec in mem.tdbs.iter_mut().skip(1) {
        rec.planes = [0, 1, 2].map(|_| Plane { a: quarter_step(&mut rng), b: quarter_step(&mut rng), c: rng.below(256 << 16) as i64 });
    }
    let bg = [9, 99, 199];
    let frames = [(48, 24), (3, 1000), (1000, 3)].map(|(width, height)| FrameSpec { width, height, background: bg, clear_behind: false, phong: false });
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::run_rtl_vs_model("cs_gouraud_fractions", &mut mem, &frames, &[], drive, true)?;
    run.recording.ok_or_else(|| "CS bench: no recording".to_string())
}

/// Memories for a w x h frame where pixel p shows record p + 1 of `tdbs` (entry 0 is the
/// background's), with random depths.
fn record_per_pixel_memories(rng: &mut Rng, w: u32, h: u32, tdbs: Vec<TdbsEntry>) -> CsMemories {
    let ibuf: Vec<u16> = (1..=w * h).map(|p| p as u16).collect();
    let zbuf = (0..w * h).map(|_| rng.below(1 << 24) as u32).collect();
    CsMemories::new(ibuf, zbuf, tdbs)
}

/// Gouraud frames where every pixel has its own record whose three colour planes sit exactly at a
/// rounding edge there: `c + a*X + b*Y + 2^15` ends in 16 ones (one more rounds up) or 16 zeros
/// (one less rounds down), with random gradients. A fault worth one unit of 2^-16 anywhere in a plane
/// product or sum then changes the colour; over random planes it does so at one pixel in 2^16.
pub fn cs_rounding_edge_recordings(seed: u64) -> Result<Vec<Recording>, String> {
    let mut rng = Rng::new(seed);
    [(48u32, 24u32), (2, 1000), (1000, 2)]
        .iter()
        .enumerate()
        .map(|(k, &(w, h))| {
            let mut tdbs = vec![TdbsEntry { planes: [Plane::constant(0); 3], material: 0 }];
            for p in 0..w * h {
                let (x, y) = (p % w, p / w);
                let planes = [0, 1, 2].map(|_| {
                    let (a, b) = (quarter_step(&mut rng), quarter_step(&mut rng));
                    let up = rng.chance(50);
                    let sum = ((20 + rng.below(216) as i64) << 16) | if up { 0xffff } else { 0 };
                    Plane { a, b, c: sum - (1 << 15) - a * x as i64 - b * y as i64 }
                });
                tdbs.push(TdbsEntry { planes, material: rng.below(65536) as u16 });
            }
            let mut mem = record_per_pixel_memories(&mut rng, w, h, tdbs);
            let spec = FrameSpec { width: w, height: h, background: [0, 0, 0], clear_behind: false, phong: false };
            let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed: seed + k as u64 };
            let run = csb::run_rtl_vs_model(&format!("cs_rounding_edges_{k}"), &mut mem, &[spec], &[], drive, true)?;
            run.recording.ok_or_else(|| "CS bench: no recording".to_string())
        })
        .collect()
}

/// The largest frame the CS takes, 1024x1024 in Gouraud over random I-buffer contents, recorded from
/// the cycle model alone (1,048,576 pixels; the RustHDL simulation would take minutes). Only a frame of
/// more than 2^18 pixels sets the I-buffer address's bit 18, and one of more than 2^19 its bit 19; the
/// other recordings' largest frame has 3,000 pixels.
pub fn cs_largest_frame_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let (w, h) = (1024u32, 1024u32);
    let mut mem = random_memories(&mut rng, w, h, 150);
    let spec = FrameSpec { width: w, height: h, background: [10, 20, 30], clear_behind: false, phong: false };
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::record_model(&mut mem, &[spec], &[], drive)?;
    run.recording.ok_or_else(|| "CS model: no recording".to_string())
}

/// A record whose Phong colour sits at a rounding edge: a constant normal (planes without gradient)
/// and a material drawn again (at most `tries` times) until every light lights the normalised normal
/// (`N.L > 0`, so that every light unit's term is in the sum) and the light sum
/// (`PhongLights::intensity`) is, in channel `channel` (0 red, 1 green, 2 blue), with a colour of
/// 0..=254, within `band` units of 2^-22 of a rounding edge (`acc mod 2^22` in `[2^21 - band, 2^21 +
/// band)`): a fault that moves that sum by `band` units or less, one way or the other, changes the
/// colour. Without the lighting condition most records found are unlit normals whose sum is the
/// ambient term alone, `ambient << 14`, exactly on the edge when the ambient's low byte is 128: no
/// light unit's fault reaches them. `None` if no draw does.
pub fn phong_rounding_edge_record(rng: &mut Rng, lights: &PhongLights, channel: usize, band: i64, tries: usize) -> Option<TdbsEntry> {
    (0..tries).find_map(|_| {
        let n = [0, 1, 2].map(|_| rng.below(2 * (1 << 14) + 1) as i64 - (1 << 14));
        let material = rng.below(65536) as u16;
        let u = golden::shade::normalize_q14(n);
        if lights.l.iter().any(|&l| golden::shade::dot_q14(u, l) == 0) {
            return None;
        }
        let acc = lights.intensity(u, material % CS_MATERIALS as u16);
        let (a, f) = (acc[channel], acc[channel].rem_euclid(1 << 22) - (1 << 21));
        let on_edge = (0..=254).contains(&(a >> 22)) && -band <= f && f < band;
        on_edge.then(|| TdbsEntry { planes: n.map(|c| Plane { a: 0, b: 0, c: c << 16 }), material })
    })
}

/// A Phong frame of 24x16 where every pixel has its own [`phong_rounding_edge_record`] (band 16;
/// red, green and blue in turn) under random lights and materials. Over the other recordings'
/// normals a fault of a few units in the light sum changes a colour at about one pixel channel in
/// 2^22 / (2 band); here at every pixel.
pub fn cs_phong_rounding_edge_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let lights = random_lights(&mut rng);
    let config = phong_config(&lights)?;
    let (w, h) = (24u32, 16u32);
    let mut tdbs = vec![TdbsEntry { planes: [Plane::constant(0); 3], material: 0 }];
    for p in 0..w * h {
        // Red, green and blue in turn (about 300,000 draws per record).
        let rec = phong_rounding_edge_record(&mut rng, &lights, p as usize % 3, 16, 10_000_000);
        tdbs.push(rec.ok_or("no Phong record at a rounding edge in 10,000,000 draws")?);
    }
    let mut mem = record_per_pixel_memories(&mut rng, w, h, tdbs);
    let spec = FrameSpec { width: w, height: h, background: [1, 2, 3], clear_behind: false, phong: true };
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::run_rtl_vs_model("cs_phong_rounding_edges", &mut mem, &[spec], &config, drive, true)?;
    run.recording.ok_or_else(|| "CS bench: no recording".to_string())
}

/// Which of a light unit's two rounded dot products a [`phong_dot_edge_record`] puts on its edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Dot {
    /// N.L, the diffuse term's (and the specular term's gate, N.L > 0).
    L,
    /// N.H, the specular term's base.
    H,
}

/// A record whose normal puts light `light`'s N.L or N.H (`dot`) exactly on its Q1.14 rounding edge,
/// and whose material then makes that rounding visible in the colour. The raw sum `u.v` (`u` the
/// normalised normal, `v` the light's L or H) ends, after the light unit adds 2^13, in 14 ones (one
/// unit of 2^-28 more rounds up) or 14 zeros (one less rounds down), with the rounded product in
/// 1..2^14 (not clamped; for N.H the light also lights the normal, N.L > 0, so that the specular term
/// is in the sum); and the colour of some channel changes when the rounded product moves by that one
/// unit of 2^-14 across the edge, a change of `Kd Il` (N.L) or of `Ks Il` times the change of
/// `(N.H)^gloss` (N.H) in the light sum. A fault of any size below 2^14 units that moves a product or
/// sum of the unit's dot product across the edge then changes the colour; over random normals a
/// rounded dot product sits on its edge at one normal in 2^13. The normal is drawn at most `tries`
/// times, then the 16 material slots tried for each normal on the edge; `None` if no draw does.
pub fn phong_dot_edge_record(rng: &mut Rng, lights: &PhongLights, light: usize, dot: Dot, tries: usize) -> Option<TdbsEntry> {
    let one = 1i64 << 14;
    (0..tries).find_map(|_| {
        let n = [0, 1, 2].map(|_| rng.below(2 * (1 << 14) + 1) as i64 - (1 << 14));
        let u = golden::shade::normalize_q14(n);
        let v = match dot {
            Dot::L => lights.l[light],
            Dot::H => lights.h[light],
        };
        let s = golden::shade::dot_raw(u, v) + (1 << 13);
        let step = match s.rem_euclid(one) {
            r if r == one - 1 => 1,
            0 => -1,
            _ => return None,
        };
        let d = s.div_euclid(one);
        // Both sides of the edge unclamped, and above 0 (N.L then stays the specular term's open gate).
        if !(1..one).contains(&d) || !(1..=one).contains(&(d + step)) {
            return None;
        }
        if dot == Dot::H && golden::shade::dot_q14(u, lights.l[light]) == 0 {
            return None;
        }
        let slot = rng.below(CS_MATERIALS as u64) as usize;
        (0..CS_MATERIALS).map(|k| (slot + k) % CS_MATERIALS).find_map(|m| {
            let mat = &lights.materials[m];
            let acc = lights.intensity(u, m as u16);
            let delta: [i64; 3] = match dot {
                Dot::L => mat.diffuse[light].map(|kd| kd * step),
                Dot::H => {
                    let dsp = golden::shade::power_q14(d + step, mat.gloss_log2) - golden::shade::power_q14(d, mat.gloss_log2);
                    mat.specular[light].map(|ks| ks * dsp)
                }
            };
            let rgb = golden::shade::rgb_of_intensity(acc);
            let rgb_moved = golden::shade::rgb_of_intensity([0, 1, 2].map(|k| acc[k] + delta[k]));
            (rgb != rgb_moved).then(|| {
                let material = (m + CS_MATERIALS * rng.below((65536 / CS_MATERIALS) as u64) as usize) as u16;
                TdbsEntry { planes: n.map(|c| Plane { a: 0, b: 0, c: c << 16 }), material }
            })
        })
    })
}

/// `lights` with every component of every L and H made odd (at most one unit of 2^-14 moved): then
/// the low bit of each of a dot product's products follows the normal's component, and the raw sum
/// takes odd and even values. With an even component the product's low bit is always 0, and with all
/// three even the sum never ends in 14 ones: a fault in those bits could not be seen (the first light
/// set drawn for [`cs_phong_dot_edge_recording`] had light 1's L all even).
pub fn odd_lights(mut lights: PhongLights) -> PhongLights {
    for v in lights.l.iter_mut().chain(lights.h.iter_mut()) {
        for c in v.iter_mut() {
            *c |= 1;
        }
    }
    lights
}

/// A Phong frame of 24x16 where every pixel has its own [`phong_dot_edge_record`]: light 0's N.L,
/// light 1's N.L, light 0's N.H and light 1's N.H in turn, under random lights and materials. The light
/// sum at a rounding edge ([`cs_phong_rounding_edge_recording`]) shows a fault in the sum after the
/// dot products are rounded; this shows one in the dot products' own products and sums, which the
/// rounding to Q1.14 hides unless the sum sits on its edge.
pub fn cs_phong_dot_edge_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let lights = odd_lights(random_lights(&mut rng));
    let config = phong_config(&lights)?;
    let (w, h) = (24u32, 16u32);
    let mut tdbs = vec![TdbsEntry { planes: [Plane::constant(0); 3], material: 0 }];
    for p in 0..w * h {
        let (light, dot) = (p as usize % CS_LIGHTS, if (p as usize / CS_LIGHTS) % 2 == 0 { Dot::L } else { Dot::H });
        let rec = phong_dot_edge_record(&mut rng, &lights, light, dot, 10_000_000);
        tdbs.push(rec.ok_or_else(|| format!("no normal with light {light}'s N.{dot:?} on its rounding edge in 10,000,000 draws"))?);
    }
    let mut mem = record_per_pixel_memories(&mut rng, w, h, tdbs);
    let spec = FrameSpec { width: w, height: h, background: [4, 5, 6], clear_behind: false, phong: true };
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::run_rtl_vs_model("cs_phong_dot_edges", &mut mem, &[spec], &config, drive, true)?;
    run.recording.ok_or_else(|| "CS bench: no recording".to_string())
}

#[cfg(test)]
mod rounding_edge_tests {
    use super::*;

    /// The Phong construction on golden's shading: the light sum moved by the band changes a colour.
    #[test]
    fn a_phong_rounding_edge_record_changes_colour_when_the_light_sum_moves_by_its_band() {
        let mut rng = Rng::new(0x9e0);
        let lights = random_lights(&mut rng);
        for channel in [0, 1, 2, 0, 1, 2] {
            let rec = phong_rounding_edge_record(&mut rng, &lights, channel, 16, 10_000_000).expect("a record at a rounding edge");
            let n = rec.planes.map(|p| p.eval(0, 0));
            let acc = lights.intensity(golden::shade::normalize_q14(n), rec.material % CS_MATERIALS as u16);
            let rgb = golden::shade::rgb_of_intensity(acc);
            assert_eq!(rgb, lights.shade(n, rec.material % CS_MATERIALS as u16));
            let moved = [16, -16].iter().any(|&d| golden::shade::rgb_of_intensity(acc.map(|a| a + d))[channel] != rgb[channel]);
            assert!(moved, "channel {channel}: {acc:?}");
            // Every light unit's term is in the sum.
            let u = golden::shade::normalize_q14(n);
            assert!(lights.l.iter().all(|&l| golden::shade::dot_q14(u, l) > 0));
        }
    }

    /// The dot-product construction on golden's shading: moving the light's L (or H) by one unit in a
    /// component where the normal is not 0, the way that crosses the edge, changes the colour; the
    /// same move the other way does not change the rounded dot product.
    #[test]
    fn a_phong_dot_edge_record_changes_colour_when_its_light_vector_moves_by_one_unit_across_the_edge() {
        let mut rng = Rng::new(0xd07);
        let lights = odd_lights(random_lights(&mut rng));
        for (light, dot) in [(0, Dot::L), (1, Dot::L), (0, Dot::H), (1, Dot::H), (0, Dot::L), (1, Dot::H)] {
            let rec = phong_dot_edge_record(&mut rng, &lights, light, dot, 10_000_000).expect("a record on the edge");
            let n = rec.planes.map(|p| p.eval(0, 0));
            let m = rec.material % CS_MATERIALS as u16;
            let u = golden::shade::normalize_q14(n);
            let k = (0..3).filter(|&k| u[k] != 0).min_by_key(|&k| u[k].abs()).unwrap();
            let vec_of = |l: &PhongLights| if dot == Dot::L { l.l[light] } else { l.h[light] };
            let dot_of = |l: &PhongLights| golden::shade::dot_q14(u, vec_of(l));
            let with = |sign: i64| {
                let mut moved = lights.clone();
                let v = if dot == Dot::L { &mut moved.l[light] } else { &mut moved.h[light] };
                v[k] += sign * u[k].signum();
                moved
            };
            let (up, down) = (with(1), with(-1));
            // Exactly one direction moves the rounded dot product (by one unit), and it changes the colour.
            let moves = [&up, &down].map(|l| dot_of(l) - dot_of(&lights));
            assert!(moves == [1, 0] || moves == [0, -1], "light {light} N.{dot:?}: {moves:?}");
            let crossing = if moves[0] == 1 { &up } else { &down };
            assert_ne!(crossing.shade(n, m), lights.shade(n, m), "light {light} N.{dot:?}: the colour does not change");
        }
    }

    /// The edge construction itself, on golden's plane evaluation: one unit of 2^-16 up (or down)
    /// moves the rounded value.
    #[test]
    fn a_rounding_edge_plane_changes_value_with_one_unit_more_or_less() {
        let mut rng = Rng::new(5);
        for _ in 0..1000 {
            let (x, y) = (rng.below(1000) as i64, rng.below(1000) as i64);
            let (a, b) = (rng.below(1 << 15) as i64 - (1 << 14), rng.below(1 << 15) as i64 - (1 << 14));
            for (low, nudge) in [(0xffff, 1), (0, -1)] {
                let p = Plane { a, b, c: ((100 << 16) | low) - (1 << 15) - a * x - b * y };
                let q = Plane { c: p.c + nudge, ..p };
                assert_eq!(p.eval(x as u32, y as u32), 100);
                assert_eq!(q.eval(x as u32, y as u32), 100 + nudge);
            }
        }
    }
}

/// The recording that colour setup's Verilog replays: `n` random commands (the replay test sends 60)
/// with 30% input gaps, run on the RTL against the cycle model (which fails first if they differ).
pub fn colour_setup_replay_recording(seed: u64, n: usize) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let cmds = random_commands(n, &mut rng);
    let run = setb::run_rtl_vs_model("colour_setup_replay", &cmds, SetupDrive { gap_percent: 30, seed }, true)?;
    run.recording.ok_or_else(|| "colour setup bench: no recording".to_string())
}

/// The recording that the CS's Verilog replays: four frames (Phong and Gouraud, a clear behind the
/// scan-out, a 2000x1 line) over random TdbS records and constants, with ignored configuration
/// writes, 35% output stalls and starts while busy.
pub fn cs_replay_recording(seed: u64) -> Result<Recording, String> {
    let mut rng = Rng::new(seed);
    let mut mem = random_memories(&mut rng, 40, 12, 100);
    let lights = random_lights(&mut rng);
    let mut config = ignored_writes(&mut rng);
    config.extend(phong_config(&lights)?);
    let frames = [
        FrameSpec { width: 40, height: 12, background: [1, 2, 3], clear_behind: false, phong: true },
        FrameSpec { width: 40, height: 12, background: [1, 2, 3], clear_behind: true, phong: false },
        FrameSpec { width: 2000, height: 1, background: [0; 3], clear_behind: false, phong: false },
        FrameSpec { width: 40, height: 12, background: [4, 5, 6], clear_behind: false, phong: true },
    ];
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 3, seed };
    let run = csb::run_rtl_vs_model("cs_replay", &mut mem, &frames, &config, drive, true)?;
    run.recording.ok_or_else(|| "CS bench: no recording".to_string())
}

/// The built-in checker with `filter` and `wrap`, perspective-correct.
pub fn checker_texturing(filter: golden::texture::Filter, wrap: golden::texture::Wrap) -> golden::render::Texturing {
    golden::render::Texturing {
        texture: std::sync::Arc::new(golden::texture::checker()),
        source: "built-in checker".into(),
        filter,
        coords: golden::texcoord::Coords::Perspective,
        wrap,
    }
}

/// One recording of `cs_tex` over the checkered teapot-floor scene at `w` x `h`: a textured and then
/// an untextured frame with `filter`, `wrap` and `shading` (Phong: its lights and materials written
/// first), driven by `drive`. With `mirror`, the texture is mirrored in s and t (every TdbT record's
/// s/w and t/w planes negated), so that the planes' gradients take the signs the scene gives them
/// least often. The RustHDL bench checks every cycle against the cycle model while
/// recording; the textured frame is also checked against golden.
fn cs_tex_recording(test: &str, filter: golden::texture::Filter, wrap: golden::texture::Wrap, shading: golden::shade::Shading, (w, h): (u32, u32), mirror: bool, drive: CsDrive) -> Result<Recording, String> {
    let tx = checker_texturing(filter, wrap);
    let f = super::frames::record_textured(shading, &tx, w, h)?;
    let neg = |p: golden::format::Plane| golden::format::Plane { a: -p.a, b: -p.b, c: -p.c };
    let mut mem = if mirror { f.textured_memories_mapped(|t| golden::texcoord::TexPlanes { sw: neg(t.sw), tw: neg(t.tw), q: t.q }) } else { f.textured_memories() };
    let phong = shading == golden::shade::Shading::Phong;
    let config = if phong { phong_config(&f.lights)? } else { Vec::new() };
    let spec = FrameSpec { width: w, height: h, background: f.background, clear_behind: false, phong };
    let tex = csb::TexRun { texturing: tx, textured: vec![true, false] };
    let run = csb::run_tex_rtl_vs_model(test, &mut mem, &[spec; 2], &config, &tex, drive, true)?;
    // The mirrored frame is checked against the cycle model only (in every cycle, as all are).
    if !mirror && csb::frame_image(&run.frames[0], w, h)? != f.frame.rgb {
        return Err(format!("{test}: the textured {filter:?} frame differs from golden"));
    }
    run.recording.ok_or_else(|| format!("{test}: the bench recorded nothing"))
}

/// A short textured run for the Verilog replay test of `cs_tex`: two 40x24 frames of the checker,
/// trilinear between levels, Gouraud, 25% output stalls, starts offered while busy (a held offer).
pub fn cs_tex_replay_recording() -> Result<Recording, String> {
    use golden::texture::{Filter, Wrap};
    let drive = CsDrive { stall_percent: 25, start_while_busy_percent: 10, max_idle: 2, seed: 0x7E5 };
    cs_tex_recording("cs_tex_replay", Filter::Trilinear, Wrap::Repeat, golden::shade::Shading::Gouraud, (40, 24), false, drive)
}

/// The mutation cover's stimulus for `cs_tex`: one recording per filter, as the RustHDL test
/// `cs_tex_matches_its_cycle_model_...` runs them (nearest with clamping and Gouraud; bilinear with
/// repeat and Phong; trilinear with repeat and Gouraud), each 48x32, 30% stalls; and a fourth,
/// trilinear with repeat and Phong, with the texture mirrored in s and t.
pub fn cs_tex_filter_recordings(seed: u64) -> Result<Vec<Recording>, String> {
    use golden::shade::Shading;
    use golden::texture::{Filter, Wrap};
    [
        (Filter::Nearest, Wrap::ClampToEdge, Shading::Gouraud, false),
        (Filter::Bilinear, Wrap::Repeat, Shading::Phong, false),
        (Filter::Trilinear, Wrap::Repeat, Shading::Gouraud, false),
        (Filter::Trilinear, Wrap::Repeat, Shading::Phong, true),
    ]
    .into_iter()
    .enumerate()
    .map(|(k, (filter, wrap, shading, mirror))| {
        let drive = CsDrive { stall_percent: 30, start_while_busy_percent: 10, max_idle: 3, seed: seed + k as u64 };
        let name = format!("cs_tex_mutation_{filter:?}{}", if mirror { "_mirrored" } else { "" });
        cs_tex_recording(&name.to_lowercase(), filter, wrap, shading, (48, 32), mirror, drive)
    })
    .collect()
}
