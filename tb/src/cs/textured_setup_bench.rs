//! Every-cycle bench of colour setup and texture setup on one command stream
//! (`hdl::cs::textured_setup::TexturedSetup` against `golden::cycle::tex_setup::TexturedSetupModel`):
//! a command and its texture values are presented together (with random gaps, held until taken), and
//! every output port of both write ports is compared in every cycle; the vectors are recorded for the
//! Verilog replay.

use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use crate::cs::pack::{command_of, entry_of, tex_planes_of, tex_values_of, BitVector};
use crate::cs::replay::{port, PortSpec, Recording};
use golden::cycle::colour_setup::{SetupCmd, SetupOutputs, SETUP_LATENCY};
use golden::cycle::tex_setup::{TexSetupOutputs, TexturedSetupModel};
use hdl::cs::textured_setup::TexturedSetup;
use rust_hdl::prelude::*;

/// A command and its texture values.
pub type Command = (SetupCmd, [[i64; 3]; 3]);

/// Ports of the `textured_setup` top in the replay's order.
pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![port("cmd$valid", 1), port("cmd$data", hdl::cs::SETUP_COMMAND_BITS), port("tex", hdl::cs::TEX_VALUES_BITS)],
        vec![
            port("cmd$ready", 1),
            port("busy", 1),
            port("tdbs_write_enable", 1),
            port("tdbs_write_address", 16),
            port("tdbs_write_data", hdl::cs::TDBS_RECORD_BITS),
            port("tdbt_write_enable", 1),
            port("tdbt_write_address", 16),
            port("tdbt_write_data", hdl::cs::TDBT_RECORD_BITS),
        ],
    )
}

/// This cycle's ports, as (name, value): the model's and the RTL's are compared by these strings.
fn ports(a: &SetupOutputs, b: &TexSetupOutputs) -> [(&'static str, String); 8] {
    [
        ("cmd.ready", (a.cmd_ready && b.cmd_ready).to_string()),
        ("busy", (a.busy || b.busy).to_string()),
        ("tdbs_write_enable", a.tdbs_write.enable.to_string()),
        ("tdbs_write_address", a.tdbs_write.address.to_string()),
        ("tdbs_write_data", format!("{:?}", a.tdbs_write.data)),
        ("tdbt_write_enable", b.write_enable.to_string()),
        ("tdbt_write_address", b.write_address.to_string()),
        ("tdbt_write_data", format!("{:?}", b.write_data)),
    ]
}

fn rtl_outputs(u: &TexturedSetup) -> (SetupOutputs, TexSetupOutputs) {
    let a = SetupOutputs {
        cmd_ready: u.cmd.ready.val(),
        busy: u.busy.val(),
        tdbs_write: golden::cycle::colour_setup::TdbsWrite {
            enable: u.tdbs_write_enable.val(),
            address: u.tdbs_write_address.val().to_u64() as u16,
            data: entry_of(&u.tdbs_write_data.val()),
        },
    };
    let b = TexSetupOutputs {
        cmd_ready: u.cmd.ready.val(),
        busy: u.busy.val(),
        write_enable: u.tdbt_write_enable.val(),
        write_address: u.tdbt_write_address.val().to_u64() as u16,
        write_data: tex_planes_of(&u.tdbt_write_data.val()),
    };
    (a, b)
}

/// What a run wrote: TdbS and TdbT writes in order, and the cycles it took.
#[derive(Clone, Debug, Default)]
pub struct Run {
    pub tdbs: Vec<(u16, golden::shade::TdbsEntry)>,
    pub tdbt: Vec<(u16, golden::texcoord::TexPlanes)>,
    pub cycles: u64,
    pub recording: Option<Recording>,
}

/// Drive `cmds` through the RTL and the model with `gap_percent` idle cycles, comparing every port in
/// every cycle. `test` names the VCD (`target/vcd/cs/<test>.vcd`, with `VCD=1`).
pub fn run(test: &str, cmds: &[Command], gap_percent: u64, seed: u64, record: bool) -> Result<Run, String> {
    let path = vcd_path("cs", test);
    let mut uut = TexturedSetup::default();
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("textured_setup design check: {e:?}"))?;
    let mut trace = Trace::new(&uut, vcd_wanted().then_some(path.as_path()))?;
    let (ins, outs) = replay_ports();
    let mut rec = Recording::new(ins, outs);
    let mut rng = Rng::new(seed);
    let mut model = TexturedSetupModel::default();
    let mut out = Run::default();
    let (mut next, mut presenting, mut cycle) = (0usize, false, 0u64);
    let mut watchdog = Watchdog::new(4 * SETUP_LATENCY);
    loop {
        if !presenting && next < cmds.len() && !rng.chance(gap_percent) {
            presenting = true;
        }
        let offer = presenting.then(|| &cmds[next]);
        let (a, b) = model.step(offer.map(|(c, v)| (c, v)));
        let (c, v) = offer.copied().unwrap_or_default();
        uut.cmd.valid.next = presenting;
        uut.cmd.data.next = command_of(&c);
        uut.tex.next = tex_values_of(&v);
        uut.clock.next = false.into();
        if !simulate(&mut uut, 200) {
            return Err(format!("textured_setup did not settle in cycle {cycle}"));
        }
        trace.dump(&uut, cycle * 10)?;
        let (ra, rb) = rtl_outputs(&uut);
        for ((name, want), (_, got)) in ports(&a, &b).iter().zip(ports(&ra, &rb).iter()) {
            if want != got {
                return Err(trace.fail(cycle, format!("textured_setup differs from its cycle model (seed {seed}), port {name}:\n  expected {want}\n  actual   {got}")));
            }
        }
        if record {
            let mut vin = BitVector::default();
            vin.push(presenting as u128, 1);
            vin.push_command(&c);
            for vk in &v {
                for &x in vk {
                    vin.push_signed(x, 33);
                }
            }
            let mut vout = BitVector::default();
            vout.push((a.cmd_ready && b.cmd_ready) as u128, 1);
            vout.push((a.busy || b.busy) as u128, 1);
            vout.push(a.tdbs_write.enable as u128, 1);
            vout.push(a.tdbs_write.address as u128, 16);
            vout.push_record(&a.tdbs_write.data);
            vout.push(b.write_enable as u128, 1);
            vout.push(b.write_address as u128, 16);
            vout.push_tex_planes(&b.write_data);
            rec.push(vin, vout);
        }
        uut.clock.next = true.into();
        if !simulate(&mut uut, 200) {
            return Err(format!("textured_setup did not settle in cycle {cycle}"));
        }
        trace.dump(&uut, cycle * 10 + 5)?;
        if a.tdbs_write.enable {
            out.tdbs.push((a.tdbs_write.address, a.tdbs_write.data));
        }
        if b.write_enable {
            out.tdbt.push((b.write_address, b.write_data));
        }
        let taken = presenting && a.cmd_ready;
        if taken {
            presenting = false;
            next += 1;
        }
        let progress = taken || a.tdbs_write.enable || b.write_enable || (!presenting && next < cmds.len());
        let phase = || format!("textured setup ({next} of {} commands taken)", cmds.len());
        watchdog.check(cycle, progress, phase, Some(&trace))?;
        cycle += 1;
        if next == cmds.len() && !(a.busy || b.busy) && !taken {
            break;
        }
    }
    trace.end(cycle * 10 + 10);
    out.cycles = cycle;
    out.recording = record.then_some(rec);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{require_tools, scratch_dir};
    use crate::cs::replay::replay_iverilog;

    /// Colour setup's random commands (flat, shaded, zero area, any coordinates) with texture values
    /// of the texture setup bench's kinds.
    fn random(n: usize, seed: u64) -> Vec<Command> {
        let mut rng = Rng::new(seed);
        println!("textured_setup: seed {} (set SEED={} to replay)", rng.seed(), rng.seed());
        let colour = crate::cs::stimulus::random_commands(n, &mut rng);
        let tex = crate::cs::tex_setup_bench::random_commands(n, &mut rng);
        colour.into_iter().zip(tex).map(|(c, t)| (c, t.values)).collect()
    }

    #[test]
    fn textured_setup_writes_tdbs_and_tdbt_as_its_model_every_cycle_and_the_golden_records_of_teapot_floor() {
        let cmds = random(300, 0x7E57);
        let r = run("textured_setup_random", &cmds, 30, 1, false).unwrap();
        assert_eq!((r.tdbs.len(), r.tdbt.len()), (cmds.len(), cmds.len()));
        // The frame: every visible triangle's TdbS and TdbT records as the golden chipset made them.
        use golden::format::Screen;
        use golden::render::{render_with, GoldenChipset, RenderOptions, Texturing};
        use golden::shade::Shading;
        use golden::texture::{checker, Filter, Wrap};
        let mesh = golden::scene::builtin::teapot_floor();
        let screen = Screen::new(320, 200).unwrap();
        let texturing = Texturing { texture: std::sync::Arc::new(checker()), source: "test".into(), filter: Filter::Bilinear, coords: golden::texcoord::Coords::Perspective, wrap: Wrap::Repeat };
        let opts = RenderOptions { texturing: Some(texturing), ..RenderOptions::for_scene(&mesh, screen, Shading::Phong) };
        let mut chip = GoldenChipset::new(screen);
        render_with(&mesh, &opts, &mut chip).unwrap();
        let frame: Vec<Command> = chip.setups.iter().map(|c| (SetupCmd::from_command(c).unwrap(), c.tex.unwrap())).collect();
        let r = run("textured_setup_floor", &frame, 0, 1, false).unwrap();
        for (c, ((i, s), (j, t))) in chip.setups.iter().zip(r.tdbs.iter().zip(&r.tdbt)) {
            assert_eq!((*i as u32, *j as u32), (c.index, c.index));
            assert_eq!(*s, chip.tdbs[c.index as usize], "TdbS of triangle {}", c.index);
            assert_eq!(Some(*t), chip.tdbt[c.index as usize], "TdbT of triangle {}", c.index);
        }
        println!("textured_setup, teapot-floor Phong: {} triangles in {} cycles", frame.len(), r.cycles);
    }

    #[test]
    fn the_textured_setup_verilog_replays_the_vectors_and_a_miswired_coordinate_is_caught() {
        if !require_tools("the_textured_setup_verilog_replays_the_vectors_and_a_miswired_coordinate_is_caught", &["iverilog"]) {
            return;
        }
        let rec = run("textured_setup_replay", &random(120, 0x7E57), 30, 1, true).unwrap().recording.unwrap();
        let v = hdl::cs::textured_setup::verilog().unwrap();
        let r = replay_iverilog(&v, "textured_setup", &rec, &scratch_dir("cs/textured_setup_replay")).unwrap();
        println!("textured_setup Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        // Texture setup's y1 wired from y2: the replay must fail on TdbT.
        let wire = "texture$cmd$data[(64'h4c)+:(20)] = cmd$data[(64'h4c)+:(20)];";
        let swapped = "texture$cmd$data[(64'h4c)+:(20)] = cmd$data[(64'h74)+:(20)];";
        assert!(v.contains(wire), "the wiring of y1 (`{wire}`) is not in the Verilog");
        let e = replay_iverilog(&v.replacen(wire, swapped, 1), "textured_setup", &rec, &scratch_dir("cs/textured_setup_replay_broken")).unwrap_err();
        assert!(e.contains("port tdbt_write_data"), "{e}");
    }

    #[test]
    fn the_textured_setup_passes_verilator_lint() {
        if !require_tools("the_textured_setup_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::textured_setup::verilog().unwrap();
        crate::lint::lint(&v, "textured_setup", &scratch_dir("cs/lint_textured_setup")).unwrap_or_else(|e| panic!("{e}"));
    }
}
