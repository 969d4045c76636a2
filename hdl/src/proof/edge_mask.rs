//! One edge's 8x8 subpixel mask in the filter stage (seed 002 §6.1): the distance of every subpixel
//! centre to the edge from the distance d at the pixel centre, by the paper's *tree of multiples* of
//! sin a and cos a, then the sign of each. Three registers, all loading when `adv` is high (the filter
//! stage's global stall). Cycle behaviour: `golden::proof::cycle_filter` (F1, F2, F3 of one edge).
//!
//! ```text
//!         +----------------------------------------------------------------------+
//!  d   ──▶| F1: base = 16 d - 7 cos - 7 sin   F2: rows j = base + j sy       F3:  |
//!  cs  ──▶|     sx = 2 cos, sy = 2 sin            (tree: +4sy, +2sy, +sy)    mask |──▶ mask
//!  sn  ──▶|                                   F3: leaf i of row j = row + i sx      |   (bit 8j+i)
//!  adv ──▶|                                       (tree: +4sx, +2sx, +sx), >= 0     |
//!         +----------------------------------------------------------------------+
//! ```
//! Units: 2^-14 px / 16, so every subpixel distance is an exact integer (subpixel centres at
//! (2i - 7)/16 px from the pixel centre). All values are 22-bit two's complement; for any 16-bit
//! inputs they stay below 2^21 in magnitude, so nothing wraps.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct EdgeMask {
    pub clock: Signal<In, Clock>,
    // From the filter stage's control
    /// Move every register one stage on at this edge.
    pub adv: Signal<In, Bit>,
    // From F0 and the direction table
    /// Distance of the pixel centre to the edge, S1.14.
    pub d: Signal<In, Bits<16>>,
    /// cos a and sin a of the edge's inward normal, Q1.14.
    pub cs: Signal<In, Bits<16>>,
    pub sn: Signal<In, Bits<16>>,
    // To F4
    /// Subpixels inside the edge (bit 8 j + i: column i, row j), F3's register.
    pub mask: Signal<Out, Bits<64>>,

    // Registers (pub: the bench compares them with the model).
    pub base: DFF<Bits<22>>,
    pub sx: DFF<Bits<22>>,
    pub sy: DFF<Bits<22>>,
    pub rows: Vec<DFF<Bits<22>>>,
    pub sx2: DFF<Bits<22>>,
    pub m: DFF<Bits<64>>,

    // F1 arithmetic.
    d22: Signal<Local, Bits<22>>,
    c22: Signal<Local, Bits<22>>,
    s22: Signal<Local, Bits<22>>,
    d16: Signal<Local, Bits<22>>,
    c8: Signal<Local, Bits<22>>,
    s8: Signal<Local, Bits<22>>,
    u1: Signal<Local, Bits<22>>,
    u2: Signal<Local, Bits<22>>,
    u3: Signal<Local, Bits<22>>,
    u4: Signal<Local, Bits<22>>,
    // The tree in y: level 2 (2 nodes), level 1 (4), leaves (8 rows).
    sy2: Signal<Local, Bits<22>>,
    sy4: Signal<Local, Bits<22>>,
    yl2: Vec<Signal<Local, Bits<22>>>,
    yl1: Vec<Signal<Local, Bits<22>>>,
    yl0: Vec<Signal<Local, Bits<22>>>,
    // The tree in x, eight copies (one per row): level 2, level 1, leaves.
    sxa: Signal<Local, Bits<22>>,
    sxb: Signal<Local, Bits<22>>,
    xl2: Vec<Signal<Local, Bits<22>>>,
    xl1: Vec<Signal<Local, Bits<22>>>,
    xl0: Vec<Signal<Local, Bits<22>>>,
    ob: Vec<Signal<Local, Bits<8>>>,
    outside: Signal<Local, Bits<64>>,
    ext16: Constant<Bits<22>>,
}

impl Default for EdgeMask {
    fn default() -> Self {
        let locals = |n: usize| (0..n).map(|_| Signal::default()).collect::<Vec<_>>();
        let bytes = |n: usize| (0..n).map(|_| Signal::default()).collect::<Vec<_>>();
        EdgeMask {
            clock: Default::default(),
            adv: Default::default(),
            d: Default::default(),
            cs: Default::default(),
            sn: Default::default(),
            mask: Default::default(),
            base: Default::default(),
            sx: Default::default(),
            sy: Default::default(),
            rows: (0..8).map(|_| DFF::default()).collect(),
            sx2: Default::default(),
            m: Default::default(),
            d22: Default::default(),
            c22: Default::default(),
            s22: Default::default(),
            d16: Default::default(),
            c8: Default::default(),
            s8: Default::default(),
            u1: Default::default(),
            u2: Default::default(),
            u3: Default::default(),
            u4: Default::default(),
            sy2: Default::default(),
            sy4: Default::default(),
            yl2: locals(2),
            yl1: locals(4),
            yl0: locals(8),
            sxa: Default::default(),
            sxb: Default::default(),
            xl2: locals(16),
            xl1: locals(32),
            xl0: locals(64),
            ob: bytes(8),
            outside: Default::default(),
            ext16: Constant::new(0x3f_0000u64.into()),
        }
    }
}

impl Logic for EdgeMask {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, base, sx, sy, sx2, m);
        for j in 0..8 {
            self.rows[j].clock.next = self.clock.val();
            self.rows[j].d.next = self.rows[j].q.val();
        }
        self.mask.next = self.m.q.val();

        // ---- F1: base = 16 d - 8 cos + cos - 8 sin + sin (inputs sign-extended to 22 bits).
        self.d22.next = bit_cast::<22, 16>(self.d.val());
        if self.d.val().get_bit(15) {
            self.d22.next = bit_cast::<22, 16>(self.d.val()) | self.ext16.val();
        }
        self.c22.next = bit_cast::<22, 16>(self.cs.val());
        if self.cs.val().get_bit(15) {
            self.c22.next = bit_cast::<22, 16>(self.cs.val()) | self.ext16.val();
        }
        self.s22.next = bit_cast::<22, 16>(self.sn.val());
        if self.sn.val().get_bit(15) {
            self.s22.next = bit_cast::<22, 16>(self.sn.val()) | self.ext16.val();
        }
        self.d16.next = self.d22.val() << 4;
        self.c8.next = self.c22.val() << 3;
        self.s8.next = self.s22.val() << 3;
        self.u1.next = self.d16.val() - self.c8.val();
        self.u2.next = self.u1.val() + self.c22.val();
        self.u3.next = self.u2.val() - self.s8.val();
        self.u4.next = self.u3.val() + self.s22.val();

        // ---- F2: the tree of multiples of sy. Each node passes its value to the left child and adds
        // the level's auxiliary input (4 sy, 2 sy, sy) for the right child.
        self.sy4.next = self.sy.q.val() << 2;
        self.sy2.next = self.sy.q.val() << 1;
        self.yl2[0].next = self.base.q.val();
        self.yl2[1].next = self.base.q.val() + self.sy4.val();
        for k in 0..2 {
            self.yl1[2 * k].next = self.yl2[k].val();
            self.yl1[2 * k + 1].next = self.yl2[k].val() + self.sy2.val();
        }
        for k in 0..4 {
            self.yl0[2 * k].next = self.yl1[k].val();
            self.yl0[2 * k + 1].next = self.yl1[k].val() + self.sy.q.val();
        }

        // ---- F3: per row, the tree of multiples of sx; a subpixel is inside if its leaf is >= 0.
        self.sxa.next = self.sx2.q.val() << 2;
        self.sxb.next = self.sx2.q.val() << 1;
        for j in 0..8 {
            self.xl2[2 * j].next = self.rows[j].q.val();
            self.xl2[2 * j + 1].next = self.rows[j].q.val() + self.sxa.val();
        }
        for k in 0..16 {
            self.xl1[2 * k].next = self.xl2[k].val();
            self.xl1[2 * k + 1].next = self.xl2[k].val() + self.sxb.val();
        }
        for k in 0..32 {
            self.xl0[2 * k].next = self.xl1[k].val();
            self.xl0[2 * k + 1].next = self.xl1[k].val() + self.sx2.q.val();
        }
        // The leaves' sign bits, one byte per row (bit 21 moved to bit 0 inside an 8-bit slice: ORs
        // and shifts at one width, no hazard), then the
        // mask is their complement.
        for j in 0..8 {
            self.ob[j].next = (self.xl0[8 * j].val().get_bits::<8>(14) >> 7)
                | ((self.xl0[8 * j + 1].val().get_bits::<8>(14) >> 7) << 1)
                | ((self.xl0[8 * j + 2].val().get_bits::<8>(14) >> 7) << 2)
                | ((self.xl0[8 * j + 3].val().get_bits::<8>(14) >> 7) << 3)
                | ((self.xl0[8 * j + 4].val().get_bits::<8>(14) >> 7) << 4)
                | ((self.xl0[8 * j + 5].val().get_bits::<8>(14) >> 7) << 5)
                | ((self.xl0[8 * j + 6].val().get_bits::<8>(14) >> 7) << 6)
                | ((self.xl0[8 * j + 7].val().get_bits::<8>(14) >> 7) << 7);
        }
        self.outside.next = bit_cast::<64, 8>(self.ob[0].val())
            | (bit_cast::<64, 8>(self.ob[1].val()) << 8)
            | (bit_cast::<64, 8>(self.ob[2].val()) << 16)
            | (bit_cast::<64, 8>(self.ob[3].val()) << 24)
            | (bit_cast::<64, 8>(self.ob[4].val()) << 32)
            | (bit_cast::<64, 8>(self.ob[5].val()) << 40)
            | (bit_cast::<64, 8>(self.ob[6].val()) << 48)
            | (bit_cast::<64, 8>(self.ob[7].val()) << 56);

        if self.adv.val() {
            self.base.d.next = self.u4.val();
            self.sx.d.next = self.c22.val() << 1;
            self.sy.d.next = self.s22.val() << 1;
            for j in 0..8 {
                self.rows[j].d.next = self.yl0[j].val();
            }
            self.sx2.d.next = self.sx.q.val();
            self.m.d.next = !self.outside.val();
        }
    }
}
