//! `LeadingOne36`: the most significant set bit of a 36-bit word, as a one-hot word and as its index
//! (combinational). A reciprocal normalises its divisor with it: `2^shift` is where the restoring
//! division's partial remainder starts (`golden::format::reciprocal`). For 0 both outputs are 0.
//!
//! ```text
//!  x (36 b) --> smear the top set bit down (x | x>>1 | x>>2 ...) --> isolate it --> onehot (36 b)
//!                                                                  --> OR-planes --> index (6 b)
//! ```

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct LeadingOne36 {
    pub x: Signal<In, Bits<36>>,
    /// The top set bit of `x` alone.
    pub onehot: Signal<Out, Bits<36>>,
    /// Its index: floor(log2 x).
    pub index: Signal<Out, Bits<6>>,
    smear1: Signal<Local, Bits<36>>,
    smear2: Signal<Local, Bits<36>>,
    smear4: Signal<Local, Bits<36>>,
    smear8: Signal<Local, Bits<36>>,
    smear16: Signal<Local, Bits<36>>,
    smear32: Signal<Local, Bits<36>>,
    hot: Signal<Local, Bits<36>>,
    enc0: Signal<Local, Bits<6>>,
    enc1: Signal<Local, Bits<6>>,
    enc2: Signal<Local, Bits<6>>,
    enc3: Signal<Local, Bits<6>>,
    enc4: Signal<Local, Bits<6>>,
    enc5: Signal<Local, Bits<6>>,
    mask0: Constant<Bits<36>>,
    mask1: Constant<Bits<36>>,
    mask2: Constant<Bits<36>>,
    mask3: Constant<Bits<36>>,
    mask4: Constant<Bits<36>>,
    mask5: Constant<Bits<36>>,
    k0_6: Constant<Bits<6>>,
    k1_6: Constant<Bits<6>>,
    k2_6: Constant<Bits<6>>,
    k4_6: Constant<Bits<6>>,
    k8_6: Constant<Bits<6>>,
    k16_6: Constant<Bits<6>>,
    k32_6: Constant<Bits<6>>,
}

/// Bit j of the mask is set where bit `bit` of j is set: the encoder's OR-planes.
fn encoder_mask(bit: u32) -> Bits<36> {
    let m: u64 = (0..36u64).filter(|j| j >> bit & 1 == 1).map(|j| 1u64 << j).sum();
    Bits::<36>::from(m)
}

impl Default for LeadingOne36 {
    fn default() -> Self {
        Self {
            x: Default::default(),
            onehot: Default::default(),
            index: Default::default(),
            smear1: Default::default(),
            smear2: Default::default(),
            smear4: Default::default(),
            smear8: Default::default(),
            smear16: Default::default(),
            smear32: Default::default(),
            hot: Default::default(),
            enc0: Default::default(),
            enc1: Default::default(),
            enc2: Default::default(),
            enc3: Default::default(),
            enc4: Default::default(),
            enc5: Default::default(),
            mask0: Constant::new(encoder_mask(0)),
            mask1: Constant::new(encoder_mask(1)),
            mask2: Constant::new(encoder_mask(2)),
            mask3: Constant::new(encoder_mask(3)),
            mask4: Constant::new(encoder_mask(4)),
            mask5: Constant::new(encoder_mask(5)),
            k0_6: Constant::new(0.into()),
            k1_6: Constant::new(1.into()),
            k2_6: Constant::new(2.into()),
            k4_6: Constant::new(4.into()),
            k8_6: Constant::new(8.into()),
            k16_6: Constant::new(16.into()),
            k32_6: Constant::new(32.into()),
        }
    }
}

impl Logic for LeadingOne36 {
    #[hdl_gen]
    fn update(&mut self) {
        self.smear1.next = self.x.val() | (self.x.val() >> self.k1_6.val());
        self.smear2.next = self.smear1.val() | (self.smear1.val() >> self.k2_6.val());
        self.smear4.next = self.smear2.val() | (self.smear2.val() >> self.k4_6.val());
        self.smear8.next = self.smear4.val() | (self.smear4.val() >> self.k8_6.val());
        self.smear16.next = self.smear8.val() | (self.smear8.val() >> self.k16_6.val());
        self.smear32.next = self.smear16.val() | (self.smear16.val() >> self.k32_6.val());
        self.hot.next = self.smear32.val() ^ (self.smear32.val() >> self.k1_6.val());
        self.enc0.next = self.k0_6.val();
        self.enc1.next = self.k0_6.val();
        self.enc2.next = self.k0_6.val();
        self.enc3.next = self.k0_6.val();
        self.enc4.next = self.k0_6.val();
        self.enc5.next = self.k0_6.val();
        if (self.hot.val() & self.mask0.val()).any() {
            self.enc0.next = self.k1_6.val();
        }
        if (self.hot.val() & self.mask1.val()).any() {
            self.enc1.next = self.k2_6.val();
        }
        if (self.hot.val() & self.mask2.val()).any() {
            self.enc2.next = self.k4_6.val();
        }
        if (self.hot.val() & self.mask3.val()).any() {
            self.enc3.next = self.k8_6.val();
        }
        if (self.hot.val() & self.mask4.val()).any() {
            self.enc4.next = self.k16_6.val();
        }
        if (self.hot.val() & self.mask5.val()).any() {
            self.enc5.next = self.k32_6.val();
        }
        self.onehot.next = self.hot.val();
        self.index.next = self.enc0.val() | self.enc1.val() | self.enc2.val() | self.enc3.val() | self.enc4.val() | self.enc5.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn leading_one_finds_the_top_set_bit_of_every_width() {
        let mut u = LeadingOne36::default();
        u.connect_all();
        for x in [0u64, 1, 2, 3, 5, 255, 256, (1 << 35) - 1, 1 << 35, 0x123456789] {
            u.x.next = x.into();
            assert!(simulate(&mut u, 100));
            let want = if x == 0 { 0 } else { 63 - x.leading_zeros() as u64 };
            assert_eq!(u.index.val().to_u64(), want, "x = {x:#x}");
            assert_eq!(u.onehot.val().to_u64(), if x == 0 { 0 } else { 1 << want }, "x = {x:#x}");
        }
    }
}
