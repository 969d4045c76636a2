//! The seeds' analysis reproduced from the golden model's own counts (issue 6): pure computations, no
//! I/O. `idxrender analyze` renders the scenes, calls [`analyze`] and writes the report.
//!
//! Two numbering schemes meet here and are never mixed:
//! * **seed 000** compares four *hardware* architectures, Types I-IV ([`buffers::Arch`]): traditional,
//!   deferred shading, and two variants of index rendering (Figs. 9-12, Tables IV-VII);
//! * **seed 001** compares two traditional *host* pipelines, its Type I (cull before lighting) and
//!   Type II (cull before setup), with its proposed dual pipeline ([`cpu::CpuArch`], Tables 1-3).
//!
//! | file | seed | what |
//! |---|---|---|
//! | [`levels`] | 000 Table IV | hardware levels (triangle rate, frame rate, resolutions), numbers the paper states |
//! | [`measure`] | - | one scene at one size through the golden model, once per shading method |
//! | [`cpu`] | 001 Tables 1-3 | host operations and equivalent CPU cost |
//! | [`lighting`] | 000 Fig. 9, §IV.B.5 | lighting and texture operations per type |
//! | [`buffers`] | 000 Table VII, Fig. 10 | buffers per type and their sizes |
//! | [`bandwidth`] | 000 Figs. 11-12 | buffer traffic, worst case and simulated |

pub mod bandwidth;
pub mod buffers;
pub mod cpu;
pub mod levels;
pub mod lighting;
pub mod measure;

use bandwidth::{bytes_per_frame, mb_per_s, Traffic};
use buffers::{arch_sizes, ours, paper_widths, Arch, Buffer, Widths};
use cpu::{percent, table3, CpuRow, TriangleCounts};
use levels::HardwareLevel;
use lighting::{fig9, texture, LightingOps, TextureOps};
use measure::Measured;
use crate::shade::Shading;

/// Seed 001 simulated at 320x200 only (§4); its tables are computed at that size.
pub const SEED001_SCREEN: (u32, u32) = (320, 200);

/// The shading methods of seed 000's buffer and bandwidth figures (Figs. 10-12: Phong and Gouraud).
pub const BUFFER_SHADINGS: [Shading; 2] = [Shading::Phong, Shading::Gouraud];

/// Which bit widths a size or bandwidth is computed with.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum WidthSet {
    /// Our chipset's formats (golden::format).
    Ours,
    /// The paper's stated widths, reconstructed where it states none (see [`buffers::paper_widths`]).
    Paper,
}

impl WidthSet {
    pub fn widths(self, level: &HardwareLevel, shading: Shading) -> Widths {
        match self {
            WidthSet::Ours => ours(level, shading),
            WidthSet::Paper => paper_widths(level, shading),
        }
    }
}

/// Seed 001 Tables 1 and 3 for one scene.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct CpuScene {
    pub scene: String,
    pub width: u32,
    pub height: u32,
    /// Table 1: (a), (b), (c) with (c) visible in the final image, as the paper defines it.
    pub counts: TriangleCounts,
    /// Triangles the RC flagged visible when drawn: what our host actually lights.
    pub flagged: u64,
    /// Seed 001's visible ratios (c)/(b) and (c)/(a), percent.
    pub visible_of_b: f64,
    pub visible_of_a: f64,
    /// Table 3 with the paper's formula and (c).
    pub table3: [CpuRow; 3],
    /// The pipeline as built: the golden host's measured operations (Gouraud), cost and percentages.
    pub as_built: CpuRow,
}

/// Fig. 9 and the texture operations for one scene at one size.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct LightingRow {
    pub scene: String,
    pub width: u32,
    pub height: u32,
    pub flat: LightingOps,
    pub gouraud: LightingOps,
    pub phong: LightingOps,
    pub texture: TextureOps,
}

/// Fig. 10: one type's buffers at one level and size.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct BufferRow {
    pub level: &'static str,
    pub width: u32,
    pub height: u32,
    pub shading: Shading,
    pub widths: WidthSet,
    pub arch: Arch,
    /// Bytes per buffer.
    pub buffers: Vec<(Buffer, f64)>,
    pub total_bytes: f64,
}

/// Figs. 11-12: one type's bandwidth at one level and size, worst case or one scene.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct BandwidthRow {
    pub level: &'static str,
    pub width: u32,
    pub height: u32,
    pub fps: u32,
    /// "worst case" or the scene's name.
    pub case: String,
    pub shading: Shading,
    pub widths: WidthSet,
    pub arch: Arch,
    /// MB/s per buffer.
    pub buffers: Vec<(Buffer, f64)>,
    pub total_mbs: f64,
    /// Without TdbV, which the paper puts on chip (§IV.C.2).
    pub off_chip_mbs: f64,
    /// Total with a one-record TdbS cache in the shader (Types III and IV; the same as `total_mbs` for
    /// the others and for the worst case, which assumes no locality).
    pub cached_mbs: f64,
}

/// A range of percentages or sizes, min and max over the cases named.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Range {
    pub min: f64,
    pub max: f64,
}

impl Range {
    fn of(v: impl IntoIterator<Item = f64>) -> Range {
        let mut r = Range { min: f64::INFINITY, max: f64::NEG_INFINITY };
        for x in v {
            r.min = r.min.min(x);
            r.max = r.max.max(x);
        }
        if r.min > r.max {
            Range { min: f64::NAN, max: f64::NAN }
        } else {
            r
        }
    }
}

/// The claims' numbers for one scene (ranges over the resolutions and, for bandwidth, levels and
/// shading methods).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SceneClaims {
    pub scene: String,
    pub lighting_saved_flat_gouraud: Range,
    pub lighting_saved_flat_gouraud_ideal: Range,
    pub lighting_saved_phong: Range,
    pub bandwidth_saved_simulated: Range,
    pub bandwidth_saved_simulated_cached: Range,
    /// Seed 001 at 320x200 (absent when that size was not analysed).
    pub cpu_percent_of_type_ii: Option<f64>,
    pub cpu_percent_of_type_i: Option<f64>,
    pub cpu_as_built_percent_of_type_ii: Option<f64>,
}

/// Our results against the papers' headline claims (percent saved, or sizes).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Claims {
    /// Lighting operations index rendering saves against seed 000 Type I, flat and Gouraud (the paper: 10-70%).
    pub lighting_saved_flat_gouraud: Range,
    /// The same if only final-visible triangles were lit.
    pub lighting_saved_flat_gouraud_ideal: Range,
    /// Phong (the paper: 30-95%).
    pub lighting_saved_phong: Range,
    /// Buffer size saved by Types III and IV against Type II (the paper: 70%), our widths and the paper's.
    pub buffer_saved_ours: Range,
    pub buffer_saved_paper_widths: Range,
    /// Simulated bandwidth saved by Types III and IV against Type II (the paper: 50-70%), our widths.
    pub bandwidth_saved_simulated: Range,
    /// The same counting only off-chip traffic for Type III (TdbV on chip).
    pub bandwidth_saved_simulated_off_chip: Range,
    /// Simulated, with a one-record TdbS cache in the shader of Types III and IV.
    pub bandwidth_saved_simulated_cached: Range,
    pub bandwidth_saved_worst: Range,
    pub bandwidth_saved_worst_off_chip: Range,
    /// Seed 001: proposed cost in percent of its Type II (the paper: 36.6-52.6%) and Type I (56.1-78.4%).
    pub cpu_percent_of_type_ii: Range,
    pub cpu_percent_of_type_i: Range,
    /// The same for the pipeline as built (lighting the flagged triangles).
    pub cpu_as_built_percent_of_type_ii: Range,
    /// Low-end index rendering (Types III, IV): buffer kB and simulated MB/s (the paper: 130-224 kB,
    /// 15-81 MB/s), with our widths and with the paper's.
    pub low_end_buffer_kb_ours: Range,
    pub low_end_buffer_kb_paper_widths: Range,
    pub low_end_bandwidth_mbs_ours: Range,
    pub low_end_bandwidth_mbs_paper_widths: Range,
    /// The same per scene.
    pub per_scene: Vec<SceneClaims>,
}

/// The whole analysis.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Analysis {
    pub levels: Vec<HardwareLevel>,
    /// Depth complexity assumed for the worst case of Fig. 11.
    pub worst_depth_complexity: f64,
    pub measured: Vec<Measured>,
    pub cpu: Vec<CpuScene>,
    pub lighting: Vec<LightingRow>,
    pub buffers: Vec<BufferRow>,
    pub worst_bandwidth: Vec<BandwidthRow>,
    pub simulated_bandwidth: Vec<BandwidthRow>,
    pub claims: Claims,
}

/// The traffic counts of a measured frame; `cached`: the shader keeps the last TdbS record.
pub fn traffic(m: &Measured, cached: bool) -> Traffic {
    Traffic {
        pixels: m.pixels() as f64,
        fragments: m.rc.fragments as f64,
        z_passes: m.rc.z_passes as f64,
        covered: m.covered_pixels as f64,
        triangles: m.set_up as f64,
        visible_triangles: m.tdbs_writes as f64,
        tdbv_reads: m.tdbv_reads as f64,
        tdbs_reads: if cached { m.tdbs_fetches_cached } else { m.covered_pixels } as f64,
    }
}

fn cpu_scene(m: &Measured) -> CpuScene {
    let counts = TriangleCounts { a: m.a, b: m.b, c: m.c };
    let rows = table3(counts, m.lights);
    let measured = m.gouraud.host.ops();
    let cost = measured.cost();
    let as_built = CpuRow {
        arch: cpu::CpuArch::Proposed,
        operations: m.gouraud.host,
        instructions: measured,
        cost,
        percent_of_type_i: percent(cost, rows[0].cost),
        percent_of_type_ii: percent(cost, rows[1].cost),
    };
    let (vb, va) = counts.visible_ratios();
    CpuScene { scene: m.scene.clone(), width: m.width, height: m.height, counts, flagged: m.flagged, visible_of_b: vb, visible_of_a: va, table3: rows, as_built }
}

/// Which configuration a bandwidth row is for.
struct Config<'a> {
    level: &'static HardwareLevel,
    size: (u32, u32),
    case: &'a str,
    shading: Shading,
    ws: WidthSet,
}

fn bandwidth_row(c: &Config, arch: Arch, t: &Traffic, cached: &Traffic) -> BandwidthRow {
    let Config { level, size: (w, h), case, shading, ws } = *c;
    let widths = ws.widths(level, shading);
    let fps = level.frames_per_second;
    let buffers: Vec<(Buffer, f64)> = bytes_per_frame(arch, &widths, t).into_iter().map(|(b, x)| (b, mb_per_s(x, fps))).collect();
    let total_mbs = buffers.iter().map(|x| x.1).sum();
    let off_chip_mbs = buffers.iter().filter(|x| x.0 != Buffer::TdbV).map(|x| x.1).sum();
    let cached_mbs = bytes_per_frame(arch, &widths, cached).into_iter().map(|(_, x)| mb_per_s(x, fps)).sum();
    BandwidthRow { level: level.name, width: w, height: h, fps, case: case.to_string(), shading, widths: ws, arch, buffers, total_mbs, off_chip_mbs, cached_mbs }
}

/// Percent saved by `x` against `of`.
fn saved(x: f64, of: f64) -> f64 {
    if of == 0.0 {
        0.0
    } else {
        100.0 * (1.0 - x / of)
    }
}

/// Savings of Types III and IV (their `total`) against Type II's full total, over groups of rows that
/// differ only in the type.
fn savings<'a>(rows: impl Iterator<Item = &'a BandwidthRow> + Clone, total: impl Fn(&BandwidthRow) -> f64) -> Range {
    let mut v = Vec::new();
    for r in rows.clone().filter(|r| r.arch == Arch::TypeII) {
        for o in rows.clone().filter(|o| matches!(o.arch, Arch::TypeIII | Arch::TypeIV)) {
            if (o.level, o.width, o.height, &o.case, o.shading, o.widths) == (r.level, r.width, r.height, &r.case, r.shading, r.widths) {
                v.push(saved(total(o), r.total_mbs));
            }
        }
    }
    Range::of(v)
}

/// Run the analysis on measured frames. `levels` are the hardware levels to report; a level's
/// resolutions must be among the measured sizes for the simulated figures (missing ones are skipped).
/// Seed 001's tables use the frames at [`SEED001_SCREEN`].
pub fn analyze(levels: &[&'static HardwareLevel], measured: &[Measured], worst_depth: f64) -> Analysis {
    let cpu: Vec<CpuScene> = measured.iter().filter(|m| (m.width, m.height) == SEED001_SCREEN).map(cpu_scene).collect();
    let lighting: Vec<LightingRow> = measured
        .iter()
        .map(|m| LightingRow {
            scene: m.scene.clone(),
            width: m.width,
            height: m.height,
            flat: fig9(m, Shading::Flat),
            gouraud: fig9(m, Shading::Gouraud),
            phong: fig9(m, Shading::Phong),
            texture: texture(m),
        })
        .collect();

    let mut buffers = Vec::new();
    let mut worst = Vec::new();
    let mut simulated = Vec::new();
    for &level in levels {
        let n = level.triangles_per_frame();
        for (w, h) in level.resolutions {
            let pixels = w as u64 * h as u64;
            for ws in [WidthSet::Ours, WidthSet::Paper] {
                for shading in BUFFER_SHADINGS {
                    let widths = ws.widths(level, shading);
                    for arch in Arch::ALL {
                        let b = arch_sizes(arch, &widths, pixels, n);
                        let total_bytes = b.iter().map(|x| x.1).sum();
                        buffers.push(BufferRow { level: level.name, width: w, height: h, shading, widths: ws, arch, buffers: b, total_bytes });
                        let t = Traffic::worst_case(pixels, n, worst_depth);
                        let worst_case = Config { level, size: (w, h), case: "worst case", shading, ws };
                        worst.push(bandwidth_row(&worst_case, arch, &t, &t));
                        for m in measured.iter().filter(|m| (m.width, m.height) == (w, h)) {
                            let scene = Config { case: &m.scene, ..worst_case };
                            simulated.push(bandwidth_row(&scene, arch, &traffic(m, false), &traffic(m, true)));
                        }
                    }
                }
            }
        }
    }

    let buffer_saved = |ws: WidthSet| {
        let mut v = Vec::new();
        for r in buffers.iter().filter(|r| r.widths == ws && r.arch == Arch::TypeII) {
            for o in buffers.iter().filter(|o| o.widths == ws && matches!(o.arch, Arch::TypeIII | Arch::TypeIV)) {
                if (o.level, o.width, o.height, o.shading) == (r.level, r.width, r.height, r.shading) {
                    v.push(saved(o.total_bytes, r.total_bytes));
                }
            }
        }
        Range::of(v)
    };
    let ours_only = |rows: &[BandwidthRow]| rows.iter().filter(|r| r.widths == WidthSet::Ours).cloned().collect::<Vec<_>>();
    let sim_ours = ours_only(&simulated);
    let worst_ours = ours_only(&worst);
    let index_types = |a: Arch| matches!(a, Arch::TypeIII | Arch::TypeIV);
    let low_buf = |ws: WidthSet| Range::of(buffers.iter().filter(|r| r.level == "low" && r.widths == ws && index_types(r.arch)).map(|r| r.total_bytes / 1000.0));
    let low_bw = |ws: WidthSet| Range::of(simulated.iter().filter(|r| r.level == "low" && r.widths == ws && index_types(r.arch)).map(|r| r.total_mbs));
    let mut scene_names: Vec<String> = Vec::new();
    for m in measured {
        if !scene_names.contains(&m.scene) {
            scene_names.push(m.scene.clone());
        }
    }
    let per_scene = scene_names
        .iter()
        .map(|sc| {
            let rows = || lighting.iter().filter(move |r| &r.scene == sc);
            let sim = || sim_ours.iter().filter(move |r| &r.case == sc);
            let cpu_row = cpu.iter().find(|c| &c.scene == sc);
            SceneClaims {
                scene: sc.clone(),
                lighting_saved_flat_gouraud: Range::of(rows().flat_map(|r| [r.flat, r.gouraud]).map(|l| 100.0 - l.type_iii_iv_percent)),
                lighting_saved_flat_gouraud_ideal: Range::of(rows().flat_map(|r| [r.flat, r.gouraud]).map(|l| 100.0 - l.ideal_percent)),
                lighting_saved_phong: Range::of(rows().map(|r| 100.0 - r.phong.type_iii_iv_percent)),
                bandwidth_saved_simulated: savings(sim(), |r| r.total_mbs),
                bandwidth_saved_simulated_cached: savings(sim(), |r| r.cached_mbs),
                cpu_percent_of_type_ii: cpu_row.map(|c| c.table3[2].percent_of_type_ii),
                cpu_percent_of_type_i: cpu_row.map(|c| c.table3[2].percent_of_type_i),
                cpu_as_built_percent_of_type_ii: cpu_row.map(|c| c.as_built.percent_of_type_ii),
            }
        })
        .collect();
    let claims = Claims {
        lighting_saved_flat_gouraud: Range::of(lighting.iter().flat_map(|r| [r.flat, r.gouraud]).map(|l| 100.0 - l.type_iii_iv_percent)),
        lighting_saved_flat_gouraud_ideal: Range::of(lighting.iter().flat_map(|r| [r.flat, r.gouraud]).map(|l| 100.0 - l.ideal_percent)),
        lighting_saved_phong: Range::of(lighting.iter().map(|r| 100.0 - r.phong.type_iii_iv_percent)),
        buffer_saved_ours: buffer_saved(WidthSet::Ours),
        buffer_saved_paper_widths: buffer_saved(WidthSet::Paper),
        bandwidth_saved_simulated: savings(sim_ours.iter(), |r| r.total_mbs),
        bandwidth_saved_simulated_off_chip: savings(sim_ours.iter(), |r| r.off_chip_mbs),
        bandwidth_saved_simulated_cached: savings(sim_ours.iter(), |r| r.cached_mbs),
        bandwidth_saved_worst: savings(worst_ours.iter(), |r| r.total_mbs),
        bandwidth_saved_worst_off_chip: savings(worst_ours.iter(), |r| r.off_chip_mbs),
        cpu_percent_of_type_ii: Range::of(cpu.iter().map(|c| c.table3[2].percent_of_type_ii)),
        cpu_percent_of_type_i: Range::of(cpu.iter().map(|c| c.table3[2].percent_of_type_i)),
        cpu_as_built_percent_of_type_ii: Range::of(cpu.iter().map(|c| c.as_built.percent_of_type_ii)),
        low_end_buffer_kb_ours: low_buf(WidthSet::Ours),
        low_end_buffer_kb_paper_widths: low_buf(WidthSet::Paper),
        low_end_bandwidth_mbs_ours: low_bw(WidthSet::Ours),
        low_end_bandwidth_mbs_paper_widths: low_bw(WidthSet::Paper),
        per_scene,
    };
    Analysis {
        levels: levels.iter().map(|&l| l.clone()).collect(),
        worst_depth_complexity: worst_depth,
        measured: measured.to_vec(),
        cpu,
        lighting,
        buffers,
        worst_bandwidth: worst,
        simulated_bandwidth: simulated,
        claims,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::Screen;
    use crate::host::{Camera, Lighting};
    use crate::raster::{CullMode, FrontFace};
    use crate::render::RenderOptions;
    use crate::scene::builtin;

    fn measure_at(mesh: &crate::scene::Mesh, w: u32, h: u32) -> Measured {
        let opts = RenderOptions {
            screen: Screen::new(w, h).unwrap(),
            camera: Camera::framing(mesh, [0.3, 0.45, 1.0], 40.0),
            shading: Shading::Gouraud,
            cull: CullMode::Back,
            front: FrontFace::Ccw,
            lighting: Lighting::default(),
            index_bits: 16,
            rc_type: crate::raster::RcType::IV,
            texturing: None,
            background: [0, 0, 0],
        };
        measure::measure(mesh, &opts).unwrap()
    }

    #[test]
    fn golden_host_counts_match_seed_001_table_2_for_types_i_and_ii() {
        let mesh = builtin::dolphins();
        let m = measure_at(&mesh, 320, 200);
        let t = TriangleCounts { a: m.a, b: m.b, c: m.c };
        assert_eq!(m.gouraud.host_type_i, cpu::table2(cpu::CpuArch::Seed001TypeI, t, 1));
        assert_eq!(m.gouraud.host_type_ii, cpu::table2(cpu::CpuArch::Seed001TypeII, t, 1));
        // The pipeline as built is Table 2's proposed column with (c) replaced by the flagged count.
        let flagged = TriangleCounts { c: m.flagged, ..t };
        assert_eq!(m.gouraud.host, cpu::table2(cpu::CpuArch::Proposed, flagged, 1));
    }

    #[test]
    fn analysis_of_one_low_end_scene_has_every_figure() {
        let mesh = builtin::castle();
        let ms: Vec<Measured> = [(320, 200), (160, 100)].iter().map(|&(w, h)| measure_at(&mesh, w, h)).collect();
        let a = analyze(&[&levels::TABLE_IV[2]], &ms, 4.0);
        assert_eq!(a.cpu.len(), 1);
        assert_eq!(a.lighting.len(), 2);
        // 2 sizes x 2 width sets x 2 shadings x 4 types.
        assert_eq!(a.buffers.len(), 32);
        assert_eq!(a.worst_bandwidth.len(), 32);
        assert_eq!(a.simulated_bandwidth.len(), 32);
        // Deferred shading's buffers are the largest, whatever the widths.
        for r in a.buffers.iter().filter(|r| r.arch == Arch::TypeII) {
            assert!(a.buffers.iter().filter(|o| (o.width, o.shading, o.widths) == (r.width, r.shading, r.widths)).all(|o| o.total_bytes <= r.total_bytes));
        }
        let c = &a.claims;
        assert!(c.lighting_saved_phong.min > 0.0 && c.lighting_saved_phong.max < 100.0);
        assert!(c.cpu_percent_of_type_ii.min < 100.0);
        assert!(c.cpu_as_built_percent_of_type_ii.min >= c.cpu_percent_of_type_ii.min);
    }
}
