//! `modulate`: OpenGL's MODULATE of a texel by a pixel's colour, texel x colour / 255 rounded to
//! nearest per channel (`golden::texture::modulate`), one registered stage. Used by the texel filter
//! and the texture unit. RGB888 packed R in 23:16, G in 15:8, B in 7:0; `rgb_out` is 0 while
//! `valid_out` is low.

use crate::common::MulLogicU;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Modulate {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    pub texel: Signal<In, Bits<24>>,
    pub colour: Signal<In, Bits<24>>,
    pub valid_out: Signal<Out, Bit>,
    pub rgb_out: Signal<Out, Bits<24>>,
    mm: [MulLogicU<8, 8, 16>; 3],
    m_p: [Signal<Local, Bits<16>>; 3],
    m_hi: [Signal<Local, Bits<16>>; 3],
    m_sum: [Signal<Local, Bits<16>>; 3],
    out: [DFF<Bits<8>>; 3],
    valid: DFF<Bit>,
    packed: [Signal<Local, Bits<24>>; 3],
    k128_16: Constant<Bits<16>>,
    k8_16: Constant<Bits<16>>,
}

impl Default for Modulate {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            texel: Default::default(),
            colour: Default::default(),
            valid_out: Default::default(),
            rgb_out: Default::default(),
            mm: Default::default(),
            m_p: Default::default(),
            m_hi: Default::default(),
            m_sum: Default::default(),
            out: Default::default(),
            valid: Default::default(),
            packed: Default::default(),
            k128_16: Constant::new(128u64.into()),
            k8_16: Constant::new(8u64.into()),
        }
    }
}

impl Logic for Modulate {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, valid);
        for c in 0..3 {
            self.out[c].clock.next = self.clock.val();
        }
        // p = t c + 128, (p + (p >> 8)) >> 8.
        self.mm[0].a.next = self.texel.val().get_bits::<8>(16);
        self.mm[1].a.next = self.texel.val().get_bits::<8>(8);
        self.mm[2].a.next = self.texel.val().get_bits::<8>(0);
        self.mm[0].b.next = self.colour.val().get_bits::<8>(16);
        self.mm[1].b.next = self.colour.val().get_bits::<8>(8);
        self.mm[2].b.next = self.colour.val().get_bits::<8>(0);
        for c in 0..3 {
            self.m_p[c].next = self.mm[c].p.val() + self.k128_16.val();
            self.m_hi[c].next = self.m_p[c].val() >> self.k8_16.val();
            self.m_sum[c].next = self.m_p[c].val() + self.m_hi[c].val();
            self.out[c].d.next = 0.into();
            if self.valid_in.val() {
                self.out[c].d.next = self.m_sum[c].val().get_bits::<8>(8);
            }
        }
        self.valid.d.next = self.valid_in.val();
        self.packed[0].next = bit_cast::<24, 8>(self.out[0].q.val()) << 16;
        self.packed[1].next = bit_cast::<24, 8>(self.out[1].q.val()) << 8;
        self.packed[2].next = bit_cast::<24, 8>(self.out[2].q.val());
        self.rgb_out.next = self.packed[0].val() | self.packed[1].val() | self.packed[2].val();
        self.valid_out.next = self.valid.q.val();
    }
}
