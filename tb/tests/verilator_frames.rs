//! Whole frames through the generated Verilog of the `chipset` top (and of the Type III `chipset3`)
//! under Verilator (`tb::verilator::VerilatorChipset`), driven by the golden model's host program: equal
//! to the algorithmic golden model byte for byte, and cycle for cycle equal to the RustHDL simulation
//! of the same top (`tb::chipset::RtlChipsetOf`). A missing `verilator` fails each test
//! (`tb::common::require_tools`; the test script installs it).

use golden::format::Screen;
use golden::render::{render, render_frames_with, render_with, Frame, RenderOptions};
use golden::scene::builtin;
use golden::shade::Shading;
use golden::raster::RcType;
use tb::chipset::{mixed_frames, ChipsetTop, HostDrive, RtlChipset, RtlChipsetOf};
use tb::chipset::PhaseCycles;
use tb::common::{require_tools, vcd_path};
use tb::verilator::VerilatorChipset;
use hdl::chipset::chipset3::Chipset3;
use hdl::chipset::Chipset;
use tb::chipset::VcdScope;

fn verilator_missing(test: &str) -> bool {
    !require_tools(test, &["verilator"])
}

/// The first difference between two frames, named by buffer and pixel.
fn first_difference(a: &Frame, b: &Frame) -> Option<String> {
    let w = a.screen.width as usize;
    for (what, x, y) in [("I-buffer", &a.hw_index, &b.hw_index), ("Z-buffer", &a.zbuf, &b.zbuf), ("index", &a.index, &b.index)] {
        if x.len() != y.len() {
            return Some(format!("{what}: {} words vs {}", x.len(), y.len()));
        }
        if let Some(i) = (0..x.len()).find(|&i| x[i] != y[i]) {
            return Some(format!("{what} at ({}, {}): {:#x} vs {:#x}", i % w, i / w, x[i], y[i]));
        }
    }
    if a.rgb.len() != b.rgb.len() {
        return Some(format!("image: {} bytes vs {}", a.rgb.len(), b.rgb.len()));
    }
    if let Some(i) = (0..a.rgb.len() / 3).find(|&i| a.rgb[3 * i..3 * i + 3] != b.rgb[3 * i..3 * i + 3]) {
        return Some(format!("colour at ({}, {}): {:?} vs {:?}", i % w, i / w, &a.rgb[3 * i..3 * i + 3], &b.rgb[3 * i..3 * i + 3]));
    }
    if a.results != b.results {
        let k = a.results.iter().zip(&b.results).position(|(p, q)| p != q).unwrap_or(a.results.len().min(b.results.len()));
        return Some(format!("per-triangle result {k}: {:?} vs {:?}", a.results.get(k), b.results.get(k)));
    }
    if a.stats != b.stats {
        return Some(format!("statistics: {:?} vs {:?}", a.stats, b.stats));
    }
    None
}

#[test]
fn teapot_at_320x200_through_the_verilated_chipset_equals_the_golden_frame() {
    if verilator_missing("teapot through Verilator") {
        return;
    }
    let screen = Screen::new(320, 200).unwrap();
    let mesh = builtin::teapot(builtin::TEAPOT_GRID);
    let opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
    let golden = render(&mesh, &opts).unwrap();
    let mut chip = VerilatorChipset::new(screen, None).unwrap();
    let t0 = std::time::Instant::now();
    let vl = render_with(&mesh, &opts, &mut chip).unwrap_or_else(|e| panic!("teapot: Verilator run failed: {e}"));
    let secs = t0.elapsed().as_secs_f64();
    if let Some(d) = first_difference(&golden, &vl) {
        panic!("teapot through Verilator differs from the golden model (golden vs Verilator): {d}");
    }
    let p = &chip.phases;
    assert_eq!(p.clear, screen.pixels() as u64, "the first frame clears every pixel once");
    assert!(p.total >= p.rasterization + p.scan_out && p.total < p.rasterization + p.colour_setup + p.scan_out, "colour setup beside rasterization: {p:?}");
    assert!(vl.stats.flagged_visible > 0, "nothing flagged visible");
    eprintln!(
        "teapot 320x200 through Verilator: {p:?}; {secs:.2} s for the frame ({:.0} cycles/s), harness build {:.1} s (fresh: {})",
        p.total as f64 / secs,
        chip.build.seconds,
        chip.build.fresh
    );
}

/// The acceptance: every built-in scene at both sizes. 640x480 is where triangles get edges of
/// 256 pixels and more (the polyhedron's two triangles do), which 320x200 never has; a width bug in the
/// RC's generated Verilog hid there until this ran.
#[test]
fn every_builtin_scene_at_320x200_and_640x480_through_the_verilated_chipset_equals_the_golden_frame() {
    if verilator_missing("every scene through Verilator") {
        return;
    }
    let mut failures = Vec::new();
    for (w, h) in [(320, 200), (640, 480)] {
        let screen = Screen::new(w, h).unwrap();
        let mut chip = VerilatorChipset::new(screen, None).unwrap();
        for name in builtin::SCENES {
            for shading in [Shading::Gouraud, Shading::Phong] {
                let mesh = builtin::scene(name).unwrap();
                let opts = RenderOptions::for_scene(&mesh, screen, shading);
                let golden = render(&mesh, &opts).unwrap();
                match render_with(&mesh, &opts, &mut chip) {
                    Err(e) => failures.push(format!("{name} {w}x{h} {shading:?}: Verilator run failed: {e}")),
                    Ok(vl) => match first_difference(&golden, &vl).map_or_else(|| traffic_equals_the_models(&chip.phases, &golden, RcType::IV), Err) {
                        Err(d) => failures.push(format!("{name} {w}x{h} {shading:?} (golden vs Verilator): {d}")),
                        Ok(()) => eprintln!("{name} {w}x{h} {shading:?}: equal to golden; {:?}", chip.phases),
                    },
                }
            }
        }
    }
    assert!(failures.is_empty(), "frames through Verilator that differ from the golden model:\n{}", failures.join("\n"));
}

#[test]
fn polyhedron_cycles_per_phase_through_verilator_equal_the_rusthdl_simulations() {
    if verilator_missing("polyhedron cycles, Verilator vs RustHDL") {
        return;
    }
    let screen = Screen::new(64, 48).unwrap();
    let mesh = builtin::polyhedron();
    for shading in [Shading::Gouraud, Shading::Phong] {
        let opts = RenderOptions::for_scene(&mesh, screen, shading);
        let mut rtl = RtlChipset::new(screen, None).unwrap();
        let a = render_with(&mesh, &opts, &mut rtl).unwrap();
        let mut vl = VerilatorChipset::new(screen, None).unwrap();
        let b = render_with(&mesh, &opts, &mut vl).unwrap();
        if let Some(d) = first_difference(&a, &b) {
            panic!("polyhedron 64x48 {shading:?}: RustHDL vs Verilator: {d}");
        }
        assert_eq!(rtl.phases, vl.phases, "{shading:?} cycles per phase: RustHDL (left) vs Verilator (right)");
        assert_eq!(rtl.cycle, vl.cycle, "cycles since reset");
        let golden = render(&mesh, &opts).unwrap();
        assert!(first_difference(&golden, &b).is_none(), "polyhedron 64x48 {shading:?} through Verilator differs from golden");
        eprintln!("polyhedron 64x48 {shading:?}: {:?} in both simulations", vl.phases);
    }
}

/// Five frames of four scenes and all three shadings back to back through the Verilated chipset, driven
/// with `drive`: each frame equals its golden frame, and every frame's cycle accounting equals the
/// RustHDL run's (`tb::chipset::mixed_frames`).
fn five_frames_back_to_back(drive: HostDrive) {
    five_frames_of_type_back_to_back::<Chipset>(drive)
}

fn five_frames_of_type_back_to_back<T: ChipsetTop>(drive: HostDrive) {
    let screen = Screen::new(96, 64).unwrap();
    let mut jobs = mixed_frames(screen);
    for (_, o) in jobs.iter_mut() {
        o.rc_type = T::TYPE;
    }
    let refs: Vec<(&golden::scene::Mesh, &RenderOptions)> = jobs.iter().map(|(m, o)| (m, o)).collect();
    let mut vl = VerilatorChipset::of_type(T::TYPE, screen, None, VcdScope::Ports).unwrap().with_drive(drive);
    let frames = render_frames_with(&refs, &mut vl).unwrap();
    for (k, ((mesh, opts), f)) in jobs.iter().zip(&frames).enumerate() {
        if let Some(d) = first_difference(&render(mesh, opts).unwrap(), f) {
            panic!("frame {} ({} {:?}) through Verilator (golden vs Verilator), {drive:?}: {d}", k + 1, mesh.name, opts.shading);
        }
    }
    let mut rtl = RtlChipsetOf::<T>::new(screen, None).unwrap().with_drive(drive);
    render_frames_with(&refs, &mut rtl).unwrap();
    assert_eq!(rtl.frame_phases, vl.frame_phases, "cycles per phase and port words of every frame, {drive:?}: RustHDL (left) vs Verilator (right)");
    assert_eq!(rtl.cycle, vl.cycle);
    assert_eq!(vl.frame_phases[2].clear, 0, "frame 3 needs no clear");
    eprintln!("{drive:?}: {} cycles for five frames", vl.cycle);
}

#[test]
fn five_verilated_frames_of_four_scenes_back_to_back_equal_golden_and_the_rusthdl_run_cycle_for_cycle() {
    if verilator_missing("frames back to back through Verilator") {
        return;
    }
    five_frames_back_to_back(HostDrive::default());
}

/// The same with random gaps before every command (RC and colour setup) and random back-pressure on
/// every stream the host takes (RC results, video): the two pipelines and the scan-out then overlap in
/// ever other ways, and the CS's output FIFO fills.
#[test]
fn five_frames_back_to_back_with_random_gaps_and_back_pressure_on_every_stream_equal_golden_in_both_simulations() {
    if verilator_missing("frames back to back with random gaps") {
        return;
    }
    five_frames_back_to_back(HostDrive::random(30, 40, 0xb2b));
}

#[test]
fn lights_beyond_the_cs_and_an_unwritable_vcd_path_are_clear_errors_through_verilator() {
    if verilator_missing("Verilator bad input") {
        return;
    }
    let screen = Screen::new(64, 48).unwrap();
    let mut vl = VerilatorChipset::new(screen, None).unwrap();
    let teapot = builtin::teapot(2);
    let mut opts = RenderOptions::for_scene(&teapot, screen, Shading::Phong);
    opts.lighting.lights = vec![opts.lighting.lights[0].clone(); 3];
    let e = render_with(&teapot, &opts, &mut vl).err().expect("three lights must be refused");
    assert!(e.contains("3 lights") && e.contains("at most 2"), "{e}");
    // An unwritable VCD path is named.
    let e = VerilatorChipset::new(screen, Some("/nonexistent-dir/x.vcd".into())).err().expect("bad VCD path must fail");
    assert!(e.contains("/nonexistent-dir/x.vcd"), "{e}");
}

/// A VCD as a list of (time, full state after that time's changes) of its variables, each variable
/// named by its path under the root scope joined with `$` (RustHDL's sub-scope `rc_cmd` with field
/// `data$kind` becomes `rc_cmd$data$kind`). Values are bit strings, most significant bit first.
struct Waves {
    names: Vec<(String, usize)>,
    states: Vec<(u64, Vec<Vec<bool>>)>,
}

fn parse_vcd(text: &str) -> Waves {
    let (head, body) = text.split_at(text.find("$enddefinitions").expect("no $enddefinitions"));
    let mut scopes: Vec<String> = Vec::new();
    let mut names = Vec::new();
    let mut codes: std::collections::HashMap<String, Vec<usize>> = Default::default();
    let tokens: Vec<&str> = head.split_whitespace().collect();
    let mut i = 0;
    while i < tokens.len() {
        match tokens[i] {
            "$scope" => {
                scopes.push(tokens[i + 2].to_string());
                i += 3;
            }
            "$upscope" => {
                scopes.pop();
                i += 1;
            }
            "$var" => {
                let (width, code, name) = (tokens[i + 2].parse::<usize>().unwrap(), tokens[i + 3], tokens[i + 4]);
                let path: Vec<&str> = scopes[1..].iter().map(String::as_str).chain([name]).collect();
                codes.entry(code.to_string()).or_default().push(names.len());
                names.push((path.join("$"), width));
                i += 5;
            }
            _ => i += 1,
        }
    }
    let mut state: Vec<Vec<bool>> = names.iter().map(|(_, w)| vec![false; *w]).collect();
    let mut states = Vec::new();
    let mut time: Option<u64> = None;
    let set = |state: &mut Vec<Vec<bool>>, code: &str, bits: &str| {
        for &k in codes.get(code).unwrap_or_else(|| panic!("unknown VCD code {code}")) {
            let w = state[k].len();
            let v: Vec<bool> = bits.chars().map(|c| c == '1').collect();
            // Left-extend with zeros (VCD drops leading zeros).
            state[k] = (0..w).map(|j| if j + v.len() >= w { v[j + v.len() - w] } else { false }).collect();
        }
    };
    let mut toks = body.split_whitespace().skip(2);
    while let Some(t) = toks.next() {
        if let Some(ts) = t.strip_prefix('#') {
            if let Some(prev) = time {
                states.push((prev, state.clone()));
            }
            time = Some(ts.parse().unwrap());
        } else if let Some(bits) = t.strip_prefix('b') {
            set(&mut state, toks.next().unwrap(), bits);
        } else if let Some(code) = t.strip_prefix(['0', '1']) {
            set(&mut state, code, &t[..1]);
        }
    }
    if let Some(prev) = time {
        states.push((prev, state));
    }
    Waves { names, states }
}

impl Waves {
    /// The value of a port at each time: the variables named `port` or `port$field...`, concatenated
    /// in declaration order, first one in the least significant bits (LogicStruct packing).
    fn port(&self, port: &str) -> Vec<(u64, Vec<bool>)> {
        let parts: Vec<usize> = (0..self.names.len()).filter(|&k| self.names[k].0 == port || self.names[k].0.starts_with(&format!("{port}$"))).collect();
        assert!(!parts.is_empty(), "no variable for port {port}");
        self.states
            .iter()
            .map(|(t, s)| {
                // LSB first: each field's bits reversed, fields in order.
                let lsb_first: Vec<bool> = parts.iter().flat_map(|&k| s[k].iter().rev().copied()).collect();
                (*t, lsb_first)
            })
            .collect()
    }
}

#[test]
fn the_verilated_chipsets_port_waveforms_equal_the_rusthdl_simulations_at_every_half_cycle() {
    if verilator_missing("Verilator vs RustHDL waveforms") {
        return;
    }
    port_waveforms_equal::<Chipset>(53);
}

#[test]
fn the_verilated_type_iii_chipsets_port_waveforms_equal_the_rusthdl_simulations_at_every_half_cycle() {
    if verilator_missing("Verilator vs RustHDL waveforms, Type III") {
        return;
    }
    // The Z-buffer's 6 ports give way to TdbV's 10.
    port_waveforms_equal::<Chipset3>(57);
}

fn port_waveforms_equal<T: ChipsetTop>(ports: usize) {
    // Phong, so that the Phong-constant write ports carry traffic too.
    let screen = Screen::new(16, 8).unwrap();
    let mesh = builtin::polyhedron();
    // Three frames back to back, so that the bank swaps and both pipelines at once are on the ports.
    let mut opts = RenderOptions::for_scene(&mesh, screen, Shading::Phong);
    opts.rc_type = T::TYPE;
    let jobs = [(&mesh, &opts), (&mesh, &opts), (&mesh, &opts)];
    let ty = T::TYPE.name();
    let (pr, pv) = (vcd_path("chipset_verilator", &format!("polyhedron_16x8_type{ty}_rusthdl")), vcd_path("chipset_verilator", &format!("polyhedron_16x8_type{ty}_verilator")));
    // Random gaps and back-pressure, so that every handshake's both sides show on the ports.
    let drive = HostDrive::random(25, 25, 0x5eed);
    let mut rtl = RtlChipsetOf::<T>::new(screen, Some(pr.clone())).unwrap().with_drive(drive);
    render_frames_with(&jobs, &mut rtl).unwrap();
    rtl.finish_vcd();
    let mut vl = VerilatorChipset::of_type(T::TYPE, screen, Some(pv.clone()), VcdScope::Ports).unwrap().with_drive(drive);
    render_frames_with(&jobs, &mut vl).unwrap();
    vl.finish_vcd();
    let (a, b) = (parse_vcd(&std::fs::read_to_string(&pr).unwrap()), parse_vcd(&std::fs::read_to_string(&pv).unwrap()));
    assert_eq!(b.names.len(), ports, "the Verilator VCD holds the {ports} ports and nothing else: {:?}", b.names);
    assert!(b.port("draw_bank").iter().any(|(_, v)| v[0]) && b.port("draw_bank").iter().any(|(_, v)| !v[0]), "the banks never swapped");
    for (port, width) in &b.names {
        let (x, y) = (a.port(port), b.port(port));
        assert_eq!(x.len(), y.len(), "{port}: {} vs {} timestamps", x.len(), y.len());
        for ((t, u), (s, v)) in x.iter().zip(&y) {
            assert_eq!(t, s, "{port}: timestamps differ");
            assert_eq!(u.len(), *width, "{port}: RustHDL fields make {} bits, the Verilog port {width}", u.len());
            if u != v {
                let hex = |bits: &Vec<bool>| (0..bits.len().div_ceil(4)).rev().map(|d| char::from_digit((0..4).filter(|j| bits.get(4 * d + j) == Some(&true)).map(|j| 1 << j).sum(), 16).unwrap()).collect::<String>();
                panic!("{port} at time {t}: RustHDL {} Verilator {} ({} and {})", hex(u), hex(v), pr.display(), pv.display());
            }
        }
    }
    // The last rising edge of the frame is at 10 * (cycles - 1) + 5 in both.
    assert_eq!(b.states.last().map(|s| s.0), Some(10 * (vl.cycle - 1) + 5), "last VCD time vs {} cycles", vl.cycle);
    eprintln!("{} ports equal at {} timestamps ({} cycles)", b.names.len(), b.states.len(), vl.cycle);
}

/// Issue 18: a run that stops making progress ends at once, naming the phase and the cycle, in both
/// backends. Here the host never takes an RC result (back-pressure always on), so the RC stalls after
/// its first triangle; the run stops one watchdog period later, not after the cycle budget.
#[test]
fn a_run_that_stops_making_progress_ends_at_once_naming_the_phase_and_cycle() {
    if verilator_missing("watchdog") {
        return;
    }
    let screen = Screen::new(32, 20).unwrap();
    let mesh = builtin::polyhedron();
    let opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
    let stuck = HostDrive { seed: 1, gap_percent: 0, stall_percent: 100 };
    let watchdog = tb::chipset::watchdog_cycles(screen);
    let mut rtl = RtlChipset::new(screen, None).unwrap().with_drive(stuck);
    let e = render_with(&mesh, &opts, &mut rtl).err().expect("a stuck run must fail");
    assert!(e.contains("no progress") && e.contains("frame 1's rasterization") && e.contains("render --vcd"), "{e}");
    // The first frame's clear (W*H cycles of writes), the first triangle (at most W*H candidates), then
    // one watchdog period of silence; the cycle budget would have been over a million.
    assert!(rtl.cycle <= 2 * screen.pixels() as u64 + watchdog + 200, "stopped after {} cycles", rtl.cycle);
    let mut vl = VerilatorChipset::new(screen, None).unwrap().with_drive(stuck);
    let e2 = render_with(&mesh, &opts, &mut vl).err().expect("a stuck Verilator run must fail");
    assert!(e2.contains("no progress") && e2.contains("frame 1's rasterization"), "{e2}");
    assert_eq!(e.split("at cycle").nth(1).map(|t| t.split(':').next()), e2.split("at cycle").nth(1).map(|t| t.split(':').next()), "both stop in the same cycle");
}

/// The words each RC memory port of the RTL moved in the frame equal the algorithmic RC's count of
/// the same type, once the clear writes are taken off (Type IV's clear writes the Z-buffer too).
fn traffic_equals_the_models(p: &PhaseCycles, golden: &Frame, ty: RcType) -> Result<(), String> {
    let (t, g) = (&p.traffic, &golden.stats.rc.traffic);
    let z_clear = if ty == RcType::IV { p.clear } else { 0 };
    let rtl = [t.z_reads, t.z_writes - z_clear, t.i_reads, t.i_writes - p.clear, t.tdbv_reads, t.tdbv_writes];
    let model = [g.z_reads, g.z_writes, g.i_reads, g.i_writes, g.tdbv_reads, g.tdbv_writes];
    if rtl != model {
        return Err(format!("RC port words (Z r/w, I r/w, TdbV r/w): RTL {rtl:?}, model {model:?}"));
    }
    if t.tdbs_writes != golden.stats.tdbs_writes {
        return Err(format!("TdbS writes: RTL {}, model {}", t.tdbs_writes, golden.stats.tdbs_writes));
    }
    Ok(())
}

/// Issue 16's acceptance for Type III: every built-in scene at both sizes through the generated
/// Verilog of `chipset3` equals the golden Type III frame (which `golden/tests/type_iii.rs` shows equal
/// to the Type IV frame), and the words its memory ports moved equal the model's counts.
#[test]
fn every_builtin_scene_at_320x200_and_640x480_through_the_verilated_type_iii_chipset_equals_the_golden_frame() {
    if verilator_missing("every scene through Verilator, Type III") {
        return;
    }
    let mut failures = Vec::new();
    for (w, h) in [(320, 200), (640, 480)] {
        let screen = Screen::new(w, h).unwrap();
        let mut chip = VerilatorChipset::of_type(RcType::III, screen, None, VcdScope::Ports).unwrap();
        for name in builtin::SCENES {
            let mesh = builtin::scene(name).unwrap();
            let mut opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
            opts.rc_type = RcType::III;
            let golden = render(&mesh, &opts).unwrap();
            match render_with(&mesh, &opts, &mut chip) {
                Err(e) => failures.push(format!("{name} {w}x{h}: Verilator run failed: {e}")),
                Ok(vl) => match first_difference(&golden, &vl).map_or_else(|| traffic_equals_the_models(&chip.phases, &golden, RcType::III), Err) {
                    Err(d) => failures.push(format!("{name} {w}x{h} (golden vs Verilator): {d}")),
                    Ok(()) => eprintln!("{name} {w}x{h} Type III: equal to golden; {:?}", chip.phases),
                },
            }
        }
    }
    assert!(failures.is_empty(), "Type III frames through Verilator that differ from the golden model:\n{}", failures.join("\n"));
}

#[test]
fn five_type_iii_frames_back_to_back_with_random_gaps_and_back_pressure_equal_golden_in_both_simulations() {
    if verilator_missing("Type III frames back to back with random gaps") {
        return;
    }
    five_frames_of_type_back_to_back::<Chipset3>(HostDrive::random(30, 40, 0x3b2b));
}
