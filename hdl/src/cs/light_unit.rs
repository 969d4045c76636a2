//! `light_unit`: one directional light of the Color Shader's per-pixel Phong (seed 001 eq. 4): the
//! diffuse term `Kd Il (N.L)` and the specular term `Ks Il (N.H)^gloss` of one pixel per clock, added to
//! the sum of the units before it. Bit-exact with one light's term of `golden::shade::PhongLights::intensity`.
//!
//! ```text
//!                     +------------------------------------------------------------+
//!  u_x,u_y,u_z ------>| L1 u.L, u.H: 6 products 16x16                             |
//!  (cycle c, Q1.14)   | L2 nl = clamp(round(u.L/2^14), 0, 2^14); sp = nl>0 ? same  |
//!  gloss_log2 (c+2) ->|    for u.H : 0                                             |
//!                     | L3..L6 gloss_square x 4: sp = round(sp^2/2^14) while the   |
//!                     |    stage is below log2 of the gloss                        |
//!  material (c+5) --->|  coefficient memory (2^MB words) read: Kd Il, Ks Il        |
//!                     | L7 Kd Il * nl, Ks Il * sp: 6 products 16x15                |
//!                     | L8 own = diffuse + specular per channel                    |
//!  acc_in_r/g/b ----->| (c+8) acc_out = acc_in + own  (combinational)             |--> acc_out_r/g/b
//!  vectors_write_* -->| L, H registers                                             |
//!  coeff_write_* ---->| coefficient memory write port                              |
//!  clock ------------>|                                                            |
//!                     +------------------------------------------------------------+
//! ```
//!
//! Formats: u, L, H in Q1.14; dot products rounded to Q1.14 and clamped to [0, 1] (so every square
//! stays in [0, 1]); coefficients colour x 255 with 8 fraction bits (16 bits unsigned); `own` carries
//! 14 + 8 fraction bits. The specular term is 0 where N.L <= 0, as in the golden model.

use crate::common::{signed_bit_cast_safe, FastRAM, MulS, MulU};
use crate::cs::gloss_square::GlossSquare;
use crate::cs::{LightVectors, MaterialWord, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

/// Clocks from `u` on the inputs to `acc_out` depending on it.
pub const LIGHT_UNIT_LATENCY: usize = 8;
/// The cycle (after `u`) in which `gloss_log2` must be on its input.
pub const LIGHT_UNIT_GLOSS_AT: usize = 2;
/// The cycle (after `u`) in which `material` must be on its input (the coefficient memory's address).
pub const LIGHT_UNIT_MATERIAL_AT: usize = 5;

#[derive(LogicBlock)]
pub struct LightUnit {
    pub clock: Signal<In, Clock>,
    // From the normalizer
    /// The unit normal, Q1.14.
    pub u_x: Signal<In, Signed<16>>,
    pub u_y: Signal<In, Signed<16>>,
    pub u_z: Signal<In, Signed<16>>,
    // From the material memory and the pixel's record
    /// log2 of the pixel's gloss, [`LIGHT_UNIT_GLOSS_AT`] cycles after its `u`.
    pub gloss_log2: Signal<In, Bits<3>>,
    /// The pixel's material, [`LIGHT_UNIT_MATERIAL_AT`] cycles after its `u`.
    pub material: Signal<In, Bits<CS_MATERIAL_BITS>>,
    // The chain of light units
    /// The sum of the ambient term and the units before this one, 14 + 8 fraction bits.
    pub acc_in_r: Signal<In, Bits<34>>,
    pub acc_in_g: Signal<In, Bits<34>>,
    pub acc_in_b: Signal<In, Bits<34>>,
    /// `acc_in` plus this light's term of the pixel whose `u` came [`LIGHT_UNIT_LATENCY`] cycles ago.
    pub acc_out_r: Signal<Out, Bits<34>>,
    pub acc_out_g: Signal<Out, Bits<34>>,
    pub acc_out_b: Signal<Out, Bits<34>>,
    // Configuration (write while the CS is idle)
    /// Load L and H.
    pub vectors_write_enable: Signal<In, Bit>,
    pub vectors_write_data: Signal<In, LightVectors>,
    /// Write this light's coefficients (diffuse `w0..w2`, specular `w3..w5`) of one material.
    pub coeff_write_enable: Signal<In, Bit>,
    pub coeff_write_address: Signal<In, Bits<CS_MATERIAL_BITS>>,
    pub coeff_write_data: Signal<In, MaterialWord>,

    coeff: FastRAM<MaterialWord, CS_MATERIAL_BITS>,
    vectors: DFF<LightVectors>,
    m_lx: MulS<16, 16, 32>,
    m_ly: MulS<16, 16, 32>,
    m_lz: MulS<16, 16, 32>,
    m_hx: MulS<16, 16, 32>,
    m_hy: MulS<16, 16, 32>,
    m_hz: MulS<16, 16, 32>,
    squares: [GlossSquare; 4],
    m_dr: MulU<16, 15, 31>,
    m_dg: MulU<16, 15, 31>,
    m_db: MulU<16, 15, 31>,
    m_sr: MulU<16, 15, 31>,
    m_sg: MulU<16, 15, 31>,
    m_sb: MulU<16, 15, 31>,
    // L1
    pl_x: DFF<Signed<32>>,
    pl_y: DFF<Signed<32>>,
    pl_z: DFF<Signed<32>>,
    ph_x: DFF<Signed<32>>,
    ph_y: DFF<Signed<32>>,
    ph_z: DFF<Signed<32>>,
    // L2..L6
    nl2: DFF<Bits<15>>,
    sp2: DFF<Bits<15>>,
    // L7, L8
    pd_r: DFF<Bits<31>>,
    pd_g: DFF<Bits<31>>,
    pd_b: DFF<Bits<31>>,
    ps_r: DFF<Bits<31>>,
    ps_g: DFF<Bits<31>>,
    ps_b: DFF<Bits<31>>,
    own_r: DFF<Bits<32>>,
    own_g: DFF<Bits<32>>,
    own_b: DFF<Bits<32>>,
    // Combinational
    dl_a: Signal<Local, Signed<34>>,
    dl_b: Signal<Local, Signed<34>>,
    dl_c: Signal<Local, Signed<34>>,
    dh_a: Signal<Local, Signed<34>>,
    dh_b: Signal<Local, Signed<34>>,
    dh_c: Signal<Local, Signed<34>>,
    dl_u: Signal<Local, Bits<34>>,
    dh_u: Signal<Local, Bits<34>>,
    dl_mag: Signal<Local, Bits<19>>,
    dh_mag: Signal<Local, Bits<19>>,
    nl: Signal<Local, Bits<15>>,
    nh: Signal<Local, Bits<15>>,
    wd_r: Signal<Local, Bits<32>>,
    wd_g: Signal<Local, Bits<32>>,
    wd_b: Signal<Local, Bits<32>>,
    own34_r: Signal<Local, Bits<34>>,
    own34_g: Signal<Local, Bits<34>>,
    own34_b: Signal<Local, Bits<34>>,
    khalf_34: Constant<Signed<34>>,
    kone_19: Constant<Bits<19>>,
    kone_15: Constant<Bits<15>>,
    k0_15: Constant<Bits<15>>,
    kstage: [Constant<Bits<3>>; 4],
}

impl Default for LightUnit {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            u_x: Default::default(),
            u_y: Default::default(),
            u_z: Default::default(),
            gloss_log2: Default::default(),
            material: Default::default(),
            acc_in_r: Default::default(),
            acc_in_g: Default::default(),
            acc_in_b: Default::default(),
            acc_out_r: Default::default(),
            acc_out_g: Default::default(),
            acc_out_b: Default::default(),
            vectors_write_enable: Default::default(),
            vectors_write_data: Default::default(),
            coeff_write_enable: Default::default(),
            coeff_write_address: Default::default(),
            coeff_write_data: Default::default(),
            coeff: Default::default(),
            vectors: Default::default(),
            m_lx: Default::default(),
            m_ly: Default::default(),
            m_lz: Default::default(),
            m_hx: Default::default(),
            m_hy: Default::default(),
            m_hz: Default::default(),
            m_dr: Default::default(),
            m_dg: Default::default(),
            m_db: Default::default(),
            m_sr: Default::default(),
            m_sg: Default::default(),
            m_sb: Default::default(),
            squares: Default::default(),
            pl_x: Default::default(),
            pl_y: Default::default(),
            pl_z: Default::default(),
            ph_x: Default::default(),
            ph_y: Default::default(),
            ph_z: Default::default(),
            nl2: Default::default(),
            sp2: Default::default(),
            pd_r: Default::default(),
            pd_g: Default::default(),
            pd_b: Default::default(),
            ps_r: Default::default(),
            ps_g: Default::default(),
            ps_b: Default::default(),
            own_r: Default::default(),
            own_g: Default::default(),
            own_b: Default::default(),
            dl_a: Default::default(),
            dl_b: Default::default(),
            dl_c: Default::default(),
            dh_a: Default::default(),
            dh_b: Default::default(),
            dh_c: Default::default(),
            dl_u: Default::default(),
            dh_u: Default::default(),
            dl_mag: Default::default(),
            dh_mag: Default::default(),
            nl: Default::default(),
            nh: Default::default(),
            wd_r: Default::default(),
            wd_g: Default::default(),
            wd_b: Default::default(),
            own34_r: Default::default(),
            own34_g: Default::default(),
            own34_b: Default::default(),
            khalf_34: Constant::new(Signed::<34>::from(1i64 << 13)),
            kone_19: Constant::new((1u64 << 14).into()),
            kone_15: Constant::new((1u64 << 14).into()),
            k0_15: Constant::new(0.into()),
            kstage: std::array::from_fn(|i| Constant::new((i as u64).into())),
        }
    }
}

impl Logic for LightUnit {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, vectors, pl_x, pl_y, pl_z, ph_x, ph_y, ph_z, nl2, sp2, pd_r, pd_g, pd_b, ps_r, ps_g, ps_b, own_r, own_g, own_b
        );
        self.coeff.read_clock.next = self.clock.val();
        self.coeff.write_clock.next = self.clock.val();
        self.coeff.write_enable.next = self.coeff_write_enable.val();
        self.coeff.write_address.next = self.coeff_write_address.val();
        self.coeff.write_data.next = self.coeff_write_data.val();
        self.coeff.read_address.next = self.material.val();
        if self.vectors_write_enable.val() {
            self.vectors.d.next = self.vectors_write_data.val();
        }

        // L1: u.L and u.H products.
        self.m_lx.a.next = self.u_x.val();
        self.m_lx.b.next = signed_cast(self.vectors.q.val().l_x);
        self.m_ly.a.next = self.u_y.val();
        self.m_ly.b.next = signed_cast(self.vectors.q.val().l_y);
        self.m_lz.a.next = self.u_z.val();
        self.m_lz.b.next = signed_cast(self.vectors.q.val().l_z);
        self.m_hx.a.next = self.u_x.val();
        self.m_hx.b.next = signed_cast(self.vectors.q.val().h_x);
        self.m_hy.a.next = self.u_y.val();
        self.m_hy.b.next = signed_cast(self.vectors.q.val().h_y);
        self.m_hz.a.next = self.u_z.val();
        self.m_hz.b.next = signed_cast(self.vectors.q.val().h_z);
        self.pl_x.d.next = self.m_lx.p.val();
        self.pl_y.d.next = self.m_ly.p.val();
        self.pl_z.d.next = self.m_lz.p.val();
        self.ph_x.d.next = self.m_hx.p.val();
        self.ph_y.d.next = self.m_hy.p.val();
        self.ph_z.d.next = self.m_hz.p.val();

        // L2: dot products rounded to Q1.14, clamped to [0, 2^14].
        self.dl_a.next = signed_bit_cast_safe::<34, 32>(self.pl_x.q.val()) + signed_bit_cast_safe::<34, 32>(self.pl_y.q.val());
        self.dl_b.next = self.dl_a.val() + signed_bit_cast_safe::<34, 32>(self.pl_z.q.val());
        self.dl_c.next = self.dl_b.val() + self.khalf_34.val();
        self.dh_a.next = signed_bit_cast_safe::<34, 32>(self.ph_x.q.val()) + signed_bit_cast_safe::<34, 32>(self.ph_y.q.val());
        self.dh_b.next = self.dh_a.val() + signed_bit_cast_safe::<34, 32>(self.ph_z.q.val());
        self.dh_c.next = self.dh_b.val() + self.khalf_34.val();
        self.dl_u.next = unsigned_cast(self.dl_c.val());
        self.dh_u.next = unsigned_cast(self.dh_c.val());
        self.dl_mag.next = self.dl_u.val().get_bits::<19>(14);
        self.dh_mag.next = self.dh_u.val().get_bits::<19>(14);
        self.nl.next = self.dl_mag.val().get_bits::<15>(0);
        if self.dl_mag.val() > self.kone_19.val() {
            self.nl.next = self.kone_15.val();
        }
        if self.dl_c.val().get_bit(33) {
            self.nl.next = self.k0_15.val();
        }
        self.nh.next = self.dh_mag.val().get_bits::<15>(0);
        if self.dh_mag.val() > self.kone_19.val() {
            self.nh.next = self.kone_15.val();
        }
        if self.dh_c.val().get_bit(33) | (self.nl.val() == self.k0_15.val()) {
            self.nh.next = self.k0_15.val();
        }
        self.nl2.d.next = self.nl.val();
        self.sp2.d.next = self.nh.val();

        // L3..L6: the gloss (a power of two) by repeated squaring, one squaring per stage while the
        // stage is below log2 of the gloss.
        for i in 0..4 {
            self.squares[i].clock.next = self.clock.val();
            self.squares[i].stage.next = self.kstage[i].val();
        }
        self.squares[0].sp_in.next = self.sp2.q.val();
        self.squares[0].nl_in.next = self.nl2.q.val();
        self.squares[0].gloss_in.next = self.gloss_log2.val();
        for i in 1..4 {
            self.squares[i].sp_in.next = self.squares[i - 1].sp_out.val();
            self.squares[i].nl_in.next = self.squares[i - 1].nl_out.val();
            self.squares[i].gloss_in.next = self.squares[i - 1].gloss_out.val();
        }

        // L7: the coefficients of the pixel's material (read in L6) times the terms.
        self.m_dr.a.next = self.coeff.read_data.val().w0;
        self.m_dr.b.next = self.squares[3].nl_out.val();
        self.m_dg.a.next = self.coeff.read_data.val().w1;
        self.m_dg.b.next = self.squares[3].nl_out.val();
        self.m_db.a.next = self.coeff.read_data.val().w2;
        self.m_db.b.next = self.squares[3].nl_out.val();
        self.m_sr.a.next = self.coeff.read_data.val().w3;
        self.m_sr.b.next = self.squares[3].sp_out.val();
        self.m_sg.a.next = self.coeff.read_data.val().w4;
        self.m_sg.b.next = self.squares[3].sp_out.val();
        self.m_sb.a.next = self.coeff.read_data.val().w5;
        self.m_sb.b.next = self.squares[3].sp_out.val();
        self.pd_r.d.next = self.m_dr.p.val();
        self.pd_g.d.next = self.m_dg.p.val();
        self.pd_b.d.next = self.m_db.p.val();
        self.ps_r.d.next = self.m_sr.p.val();
        self.ps_g.d.next = self.m_sg.p.val();
        self.ps_b.d.next = self.m_sb.p.val();

        // L8: this light's term per channel.
        self.wd_r.next = bit_cast::<32, 31>(self.pd_r.q.val());
        self.wd_g.next = bit_cast::<32, 31>(self.pd_g.q.val());
        self.wd_b.next = bit_cast::<32, 31>(self.pd_b.q.val());
        self.own_r.d.next = self.wd_r.val() + bit_cast::<32, 31>(self.ps_r.q.val());
        self.own_g.d.next = self.wd_g.val() + bit_cast::<32, 31>(self.ps_g.q.val());
        self.own_b.d.next = self.wd_b.val() + bit_cast::<32, 31>(self.ps_b.q.val());

        // The chain: acc_out = acc_in + own.
        self.own34_r.next = bit_cast::<34, 32>(self.own_r.q.val());
        self.own34_g.next = bit_cast::<34, 32>(self.own_g.q.val());
        self.own34_b.next = bit_cast::<34, 32>(self.own_b.q.val());
        self.acc_out_r.next = self.acc_in_r.val() + self.own34_r.val();
        self.acc_out_g.next = self.acc_in_g.val() + self.own34_g.val();
        self.acc_out_b.next = self.acc_in_b.val() + self.own34_b.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn light_unit_passes_the_rust_hdl_checks_and_generates_verilog() {
        let mut uut = LightUnit::default();
        uut.connect_all();
        let v = crate::common::verilog_named(&uut, "light_unit").unwrap();
        assert!(v.contains("module light_unit("));
    }
}
