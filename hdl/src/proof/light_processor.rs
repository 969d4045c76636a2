//! A light-source processor (seed 002 §5.2.2, Fig. 3): adds one light's diffuse and specular terms,
//! `I(i+1) = Kd Il (N.L) + Ks Il (N.H)^m + I(i)`, to every entry passing through, one entry per clock.
//! The paper's diffuse and specular processor of a light share this pipeline because the specular term
//! only exists where N.L > 0. Cycle behaviour: `golden::proof::cycle_shade` (stages A, P1..P4, M).
//!
//! ```text
//!            +------------------------------------------------------------+
//!  prev   ──▶| A: N.L, N.H ─▶ P1..P4: x = x^2 while k <= log2 m ─▶ M: I += |──▶ work
//!  adv    ──▶|  (light registers L, H)         material table ─▶ Kd, Ks    |
//!  cfg_*  ──▶|  vec_write: L, H    mat_write: Kd, Ks of material cfg_addr  |
//!            +------------------------------------------------------------+
//! ```
//! All registers load when `adv` is high (the shading stage's global stall). The material table is read
//! with the address of the entry in P3, so its word is there when the entry is in P4.

use super::table_ram::TableRam;
use super::types::ShadeWork;
use crate::common::{signed_bit_cast_safe, MulS, MulU};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct LightProcessor {
    pub clock: Signal<In, Clock>,
    // From the shading stage's control
    /// Move every register one stage on at this edge.
    pub adv: Signal<In, Bit>,
    // From the previous processor (the ambient processor or the previous light)
    /// The entry entering stage A.
    pub prev: Signal<In, ShadeWork>,
    // From the host
    /// Load L and H (`cfg_data`: Lx, Ly, Lz, Hx, Hy, Hz, Q1.14) at this edge.
    pub vec_write: Signal<In, Bit>,
    /// Write Kd Il, Ks Il (`cfg_data`: 6 x 16 bits) of material `cfg_addr` at this edge.
    pub mat_write: Signal<In, Bit>,
    pub cfg_addr: Signal<In, Bits<8>>,
    pub cfg_data: Signal<In, Bits<96>>,
    // To the next processor (or the output stage)
    /// The entry leaving stage M.
    pub work: Signal<Out, ShadeWork>,

    // Registers (pub: the bench compares them with the model).
    pub a: DFF<ShadeWork>,
    pub p1: DFF<ShadeWork>,
    pub p2: DFF<ShadeWork>,
    pub p3: DFF<ShadeWork>,
    pub p4: DFF<ShadeWork>,
    pub m: DFF<ShadeWork>,
    pub lh: DFF<Bits<96>>,
    pub mat_ram: TableRam<Bits<96>>,
    // Multipliers: dot products, squarings, constants.
    dl0: MulS<16, 16, 32>,
    dl1: MulS<16, 16, 32>,
    dl2: MulS<16, 16, 32>,
    dh0: MulS<16, 16, 32>,
    dh1: MulS<16, 16, 32>,
    dh2: MulS<16, 16, 32>,
    sq1: MulU<15, 15, 30>,
    sq2: MulU<15, 15, 30>,
    sq3: MulU<15, 15, 30>,
    sq4: MulU<15, 15, 30>,
    kd_r: MulU<16, 15, 31>,
    kd_g: MulU<16, 15, 31>,
    kd_b: MulU<16, 15, 31>,
    ks_r: MulU<16, 15, 31>,
    ks_g: MulU<16, 15, 31>,
    ks_b: MulU<16, 15, 31>,
    // Combinational temporaries.
    e0: Signal<Local, Signed<34>>,
    e1: Signal<Local, Signed<34>>,
    e2: Signal<Local, Signed<34>>,
    s01: Signal<Local, Signed<34>>,
    sl: Signal<Local, Signed<34>>,
    tl: Signal<Local, Bits<34>>,
    nl: Signal<Local, Bits<15>>,
    f0: Signal<Local, Signed<34>>,
    f1: Signal<Local, Signed<34>>,
    f2: Signal<Local, Signed<34>>,
    h01: Signal<Local, Signed<34>>,
    sh: Signal<Local, Signed<34>>,
    th: Signal<Local, Bits<34>>,
    nh: Signal<Local, Bits<15>>,
    q1: Signal<Local, Bits<30>>,
    q2: Signal<Local, Bits<30>>,
    q3: Signal<Local, Bits<30>>,
    q4: Signal<Local, Bits<30>>,
    ud_r: Signal<Local, Bits<40>>,
    ud_g: Signal<Local, Bits<40>>,
    ud_b: Signal<Local, Bits<40>>,
    us_r: Signal<Local, Bits<40>>,
    us_g: Signal<Local, Bits<40>>,
    us_b: Signal<Local, Bits<40>>,
    v_r: Signal<Local, Bits<40>>,
    v_g: Signal<Local, Bits<40>>,
    v_b: Signal<Local, Bits<40>>,
    round34: Constant<Signed<34>>,
    round30: Constant<Bits<30>>,
    one20: Constant<Bits<20>>,
    one15: Constant<Bits<15>>,
    zero15: Constant<Bits<15>>,
    g1: Constant<Bits<3>>,
    g2: Constant<Bits<3>>,
    g3: Constant<Bits<3>>,
    g4: Constant<Bits<3>>,
}

impl LightProcessor {
    pub fn new() -> LightProcessor {
        LightProcessor {
            clock: Default::default(),
            adv: Default::default(),
            prev: Default::default(),
            vec_write: Default::default(),
            mat_write: Default::default(),
            cfg_addr: Default::default(),
            cfg_data: Default::default(),
            work: Default::default(),
            a: Default::default(),
            p1: Default::default(),
            p2: Default::default(),
            p3: Default::default(),
            p4: Default::default(),
            m: Default::default(),
            lh: Default::default(),
            mat_ram: TableRam::new(8).unwrap(),
            dl0: Default::default(),
            dl1: Default::default(),
            dl2: Default::default(),
            dh0: Default::default(),
            dh1: Default::default(),
            dh2: Default::default(),
            sq1: Default::default(),
            sq2: Default::default(),
            sq3: Default::default(),
            sq4: Default::default(),
            kd_r: Default::default(),
            kd_g: Default::default(),
            kd_b: Default::default(),
            ks_r: Default::default(),
            ks_g: Default::default(),
            ks_b: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            e2: Default::default(),
            s01: Default::default(),
            sl: Default::default(),
            tl: Default::default(),
            nl: Default::default(),
            f0: Default::default(),
            f1: Default::default(),
            f2: Default::default(),
            h01: Default::default(),
            sh: Default::default(),
            th: Default::default(),
            nh: Default::default(),
            q1: Default::default(),
            q2: Default::default(),
            q3: Default::default(),
            q4: Default::default(),
            ud_r: Default::default(),
            ud_g: Default::default(),
            ud_b: Default::default(),
            us_r: Default::default(),
            us_g: Default::default(),
            us_b: Default::default(),
            v_r: Default::default(),
            v_g: Default::default(),
            v_b: Default::default(),
            round34: Constant::new(crate::common::from_i64::<34>(1 << 13)),
            round30: Constant::new((1u64 << 13).into()),
            one20: Constant::new((1u64 << 14).into()),
            one15: Constant::new((1u64 << 14).into()),
            zero15: Constant::new(0.into()),
            g1: Constant::new(1.into()),
            g2: Constant::new(2.into()),
            g3: Constant::new(3.into()),
            g4: Constant::new(4.into()),
        }
    }
}

impl Default for LightProcessor {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for LightProcessor {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, a, p1, p2, p3, p4, m, lh);
        self.mat_ram.clock.next = self.clock.val();
        self.work.next = self.m.q.val();
        if self.vec_write.val() {
            self.lh.d.next = self.cfg_data.val();
        }
        self.mat_ram.write_enable.next = self.mat_write.val();
        self.mat_ram.write_address.next = bit_cast::<16, 8>(self.cfg_addr.val());
        self.mat_ram.write_data.next = self.cfg_data.val();
        self.mat_ram.read_address.next = bit_cast::<16, 8>(self.p3.q.val().mat);
        self.mat_ram.read_enable.next = self.adv.val();

        // ---- A: N.L and N.H, rounded to Q1.14 and clamped to [0, 1].
        self.dl0.a.next = signed_cast(self.prev.val().nx);
        self.dl1.a.next = signed_cast(self.prev.val().ny);
        self.dl2.a.next = signed_cast(self.prev.val().nz);
        self.dl0.b.next = signed_cast(self.lh.q.val().get_bits::<16>(0));
        self.dl1.b.next = signed_cast(self.lh.q.val().get_bits::<16>(16));
        self.dl2.b.next = signed_cast(self.lh.q.val().get_bits::<16>(32));
        self.dh0.a.next = signed_cast(self.prev.val().nx);
        self.dh1.a.next = signed_cast(self.prev.val().ny);
        self.dh2.a.next = signed_cast(self.prev.val().nz);
        self.dh0.b.next = signed_cast(self.lh.q.val().get_bits::<16>(48));
        self.dh1.b.next = signed_cast(self.lh.q.val().get_bits::<16>(64));
        self.dh2.b.next = signed_cast(self.lh.q.val().get_bits::<16>(80));
        self.e0.next = signed_bit_cast_safe::<34, 32>(self.dl0.p.val());
        self.e1.next = signed_bit_cast_safe::<34, 32>(self.dl1.p.val());
        self.e2.next = signed_bit_cast_safe::<34, 32>(self.dl2.p.val());
        self.s01.next = self.e0.val() + self.e1.val();
        self.sl.next = self.s01.val() + self.e2.val();
        self.tl.next = unsigned_cast(self.sl.val() + self.round34.val());
        self.nl.next = self.tl.val().get_bits::<15>(14);
        if self.tl.val().get_bits::<20>(14) > self.one20.val() {
            self.nl.next = self.one15.val();
        }
        if self.tl.val().get_bit(33) {
            self.nl.next = self.zero15.val();
        }
        self.f0.next = signed_bit_cast_safe::<34, 32>(self.dh0.p.val());
        self.f1.next = signed_bit_cast_safe::<34, 32>(self.dh1.p.val());
        self.f2.next = signed_bit_cast_safe::<34, 32>(self.dh2.p.val());
        self.h01.next = self.f0.val() + self.f1.val();
        self.sh.next = self.h01.val() + self.f2.val();
        self.th.next = unsigned_cast(self.sh.val() + self.round34.val());
        self.nh.next = self.th.val().get_bits::<15>(14);
        if self.th.val().get_bits::<20>(14) > self.one20.val() {
            self.nh.next = self.one15.val();
        }
        if self.th.val().get_bit(33) | (self.nl.val() == self.zero15.val()) {
            self.nh.next = self.zero15.val();
        }

        // ---- P1..P4: repeated squaring, x = round(x^2 / 2^14) while k <= log2 m.
        self.sq1.a.next = self.a.q.val().sp;
        self.sq1.b.next = self.a.q.val().sp;
        self.sq2.a.next = self.p1.q.val().sp;
        self.sq2.b.next = self.p1.q.val().sp;
        self.sq3.a.next = self.p2.q.val().sp;
        self.sq3.b.next = self.p2.q.val().sp;
        self.sq4.a.next = self.p3.q.val().sp;
        self.sq4.b.next = self.p3.q.val().sp;
        self.q1.next = self.sq1.p.val() + self.round30.val();
        self.q2.next = self.sq2.p.val() + self.round30.val();
        self.q3.next = self.sq3.p.val() + self.round30.val();
        self.q4.next = self.sq4.p.val() + self.round30.val();

        // ---- M: I += Kd Il nl + Ks Il x, with the material table's word for the entry in P4.
        self.kd_r.a.next = self.mat_ram.read_data.val().get_bits::<16>(0);
        self.kd_g.a.next = self.mat_ram.read_data.val().get_bits::<16>(16);
        self.kd_b.a.next = self.mat_ram.read_data.val().get_bits::<16>(32);
        self.ks_r.a.next = self.mat_ram.read_data.val().get_bits::<16>(48);
        self.ks_g.a.next = self.mat_ram.read_data.val().get_bits::<16>(64);
        self.ks_b.a.next = self.mat_ram.read_data.val().get_bits::<16>(80);
        self.kd_r.b.next = self.p4.q.val().nl;
        self.kd_g.b.next = self.p4.q.val().nl;
        self.kd_b.b.next = self.p4.q.val().nl;
        self.ks_r.b.next = self.p4.q.val().sp;
        self.ks_g.b.next = self.p4.q.val().sp;
        self.ks_b.b.next = self.p4.q.val().sp;
        self.ud_r.next = bit_cast::<40, 31>(self.kd_r.p.val());
        self.ud_g.next = bit_cast::<40, 31>(self.kd_g.p.val());
        self.ud_b.next = bit_cast::<40, 31>(self.kd_b.p.val());
        self.us_r.next = bit_cast::<40, 31>(self.ks_r.p.val());
        self.us_g.next = bit_cast::<40, 31>(self.ks_g.p.val());
        self.us_b.next = bit_cast::<40, 31>(self.ks_b.p.val());
        self.v_r.next = self.p4.q.val().acc_r + self.ud_r.val();
        self.v_g.next = self.p4.q.val().acc_g + self.ud_g.val();
        self.v_b.next = self.p4.q.val().acc_b + self.ud_b.val();

        if self.adv.val() {
            self.a.d.next = self.prev.val();
            self.a.d.next.nl = self.nl.val();
            self.a.d.next.sp = self.nh.val();
            self.p1.d.next = self.a.q.val();
            if self.g1.val() <= self.a.q.val().gloss {
                self.p1.d.next.sp = self.q1.val().get_bits::<15>(14);
            }
            self.p2.d.next = self.p1.q.val();
            if self.g2.val() <= self.p1.q.val().gloss {
                self.p2.d.next.sp = self.q2.val().get_bits::<15>(14);
            }
            self.p3.d.next = self.p2.q.val();
            if self.g3.val() <= self.p2.q.val().gloss {
                self.p3.d.next.sp = self.q3.val().get_bits::<15>(14);
            }
            self.p4.d.next = self.p3.q.val();
            if self.g4.val() <= self.p3.q.val().gloss {
                self.p4.d.next.sp = self.q4.val().get_bits::<15>(14);
            }
            self.m.d.next = self.p4.q.val();
            self.m.d.next.acc_r = self.v_r.val() + self.us_r.val();
            self.m.d.next.acc_g = self.v_g.val() + self.us_g.val();
            self.m.d.next.acc_b = self.v_b.val() + self.us_b.val();
        }
    }
}
