//! Conversions between the golden model's types and the RTL's port words (`hdl::cs` LogicStructs),
//! and bit vectors for the Verilog replay. One place, so that a packing error shows up in every bench.

use golden::cycle::colour_setup::SetupCmd;
use golden::cycle::tex_setup::TexSetupCmd;
use golden::format::Plane;
use golden::shade::TdbsEntry;
use hdl::common::{from_i64, to_i64};
use golden::texcoord::TexPlanes;
use hdl::cs::{SetupCommand, TdbsRecord, TdbtRecord, TexSetupCommand, TexValues};
use rust_hdl::prelude::*;

fn bits_of<const N: usize>(v: i64) -> Bits<N> {
    unsigned_cast(from_i64::<N>(v))
}

fn signed_of<const N: usize>(b: Bits<N>) -> i64 {
    to_i64(signed_cast(b))
}

/// A golden TdbS entry as the RTL's record.
pub fn record_of(e: &TdbsEntry) -> TdbsRecord {
    let p = &e.planes;
    TdbsRecord {
        r_a: bits_of(p[0].a),
        r_b: bits_of(p[0].b),
        r_c: bits_of(p[0].c),
        g_a: bits_of(p[1].a),
        g_b: bits_of(p[1].b),
        g_c: bits_of(p[1].c),
        b_a: bits_of(p[2].a),
        b_b: bits_of(p[2].b),
        b_c: bits_of(p[2].c),
        material: (e.material as u64).into(),
    }
}

/// The RTL's record as a golden TdbS entry.
pub fn entry_of(r: &TdbsRecord) -> TdbsEntry {
    TdbsEntry {
        planes: [
            Plane { a: signed_of(r.r_a), b: signed_of(r.r_b), c: signed_of(r.r_c) },
            Plane { a: signed_of(r.g_a), b: signed_of(r.g_b), c: signed_of(r.g_c) },
            Plane { a: signed_of(r.b_a), b: signed_of(r.b_b), c: signed_of(r.b_c) },
        ],
        material: r.material.to_u64() as u16,
    }
}

/// A colour-setup command as the RTL's stream word.
pub fn command_of(c: &SetupCmd) -> SetupCommand {
    let s = |v: i16| -> Bits<16> { (v as u16 as u64).into() };
    let w = crate::common::window_bits;
    SetupCommand {
        index: (c.index as u64).into(),
        x0: w(c.x[0]),
        y0: w(c.y[0]),
        x1: w(c.x[1]),
        y1: w(c.y[1]),
        x2: w(c.x[2]),
        y2: w(c.y[2]),
        v0r: s(c.values[0][0]),
        v0g: s(c.values[0][1]),
        v0b: s(c.values[0][2]),
        v1r: s(c.values[1][0]),
        v1g: s(c.values[1][1]),
        v1b: s(c.values[1][2]),
        v2r: s(c.values[2][0]),
        v2g: s(c.values[2][1]),
        v2b: s(c.values[2][2]),
        material: (c.material as u64).into(),
        flat: c.flat,
        flat_r: (c.flat_rgb[0] as u64).into(),
        flat_g: (c.flat_rgb[1] as u64).into(),
        flat_b: (c.flat_rgb[2] as u64).into(),
    }
}

/// Golden texture planes as the RTL's TdbT record.
pub fn tdbt_record_of(t: &TexPlanes) -> TdbtRecord {
    TdbtRecord {
        s_a: bits_of(t.sw.a),
        s_b: bits_of(t.sw.b),
        s_c: bits_of(t.sw.c),
        t_a: bits_of(t.tw.a),
        t_b: bits_of(t.tw.b),
        t_c: bits_of(t.tw.c),
        q_a: bits_of(t.q.a),
        q_b: bits_of(t.q.b),
        q_c: bits_of(t.q.c),
    }
}

/// The RTL's TdbT record as golden texture planes.
pub fn tex_planes_of(r: &TdbtRecord) -> TexPlanes {
    TexPlanes {
        sw: Plane { a: signed_of(r.s_a), b: signed_of(r.s_b), c: signed_of(r.s_c) },
        tw: Plane { a: signed_of(r.t_a), b: signed_of(r.t_b), c: signed_of(r.t_c) },
        q: Plane { a: signed_of(r.q_a), b: signed_of(r.q_b), c: signed_of(r.q_c) },
    }
}

/// Texture values as the RTL's port word.
pub fn tex_values_of(v: &[[i64; 3]; 3]) -> TexValues {
    let b = |k: usize, ch: usize| -> Bits<33> { bits_of(v[k][ch]) };
    TexValues { v0s: b(0, 0), v0t: b(0, 1), v0q: b(0, 2), v1s: b(1, 0), v1t: b(1, 1), v1q: b(1, 2), v2s: b(2, 0), v2t: b(2, 1), v2q: b(2, 2) }
}

/// A texture-setup command as the RTL's stream word.
pub fn tex_command_of(c: &TexSetupCmd) -> TexSetupCommand {
    let w = crate::common::window_bits;
    TexSetupCommand {
        index: (c.index as u64).into(),
        x0: w(c.x[0]),
        y0: w(c.y[0]),
        x1: w(c.x[1]),
        y1: w(c.y[1]),
        x2: w(c.x[2]),
        y2: w(c.y[2]),
        values: tex_values_of(&c.values),
    }
}

/// RGB888 as the texture path's ports take it (texels, colours: R 23:16, G 15:8, B 7:0).
pub fn rgb888(c: [u8; 3]) -> u64 {
    (c[0] as u64) << 16 | (c[1] as u64) << 8 | c[2] as u64
}

/// RGB888 as `video_tdata` / `background` (AXI4-Stream video, UG934: R 23:16, B 15:8, G 7:0).
pub fn tdata_of(rgb: [u8; 3]) -> u32 {
    (rgb[0] as u32) << 16 | (rgb[2] as u32) << 8 | rgb[1] as u32
}

/// `video_tdata` as RGB888.
pub fn rgb_of(tdata: u32) -> [u8; 3] {
    [(tdata >> 16) as u8, tdata as u8, (tdata >> 8) as u8]
}

/// A bit vector, least significant bit first, built field by field (the first field in the LSBs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BitVector(pub Vec<bool>);

impl BitVector {
    /// Append the low `width` bits of `v` (width <= 128).
    pub fn push(&mut self, v: u128, width: usize) {
        for i in 0..width {
            self.0.push(i < 128 && (v >> i) & 1 == 1);
        }
    }
    /// Append a signed value's low `width` bits.
    pub fn push_signed(&mut self, v: i64, width: usize) {
        self.push(v as i128 as u128, width);
    }
    /// Append a TdbS entry in the record's packed layout (424 bits).
    pub fn push_record(&mut self, e: &TdbsEntry) {
        for p in &e.planes {
            self.push_signed(p.a, 40);
            self.push_signed(p.b, 40);
            self.push_signed(p.c, 56);
        }
        self.push(e.material as u128, 16);
    }
    /// Append a colour-setup command in its packed layout (297 bits).
    pub fn push_command(&mut self, c: &SetupCmd) {
        self.push(c.index as u128, 16);
        for k in 0..3 {
            self.push(c.x[k] as u32 as u128 & 0xf_ffff, 20);
            self.push(c.y[k] as u32 as u128 & 0xf_ffff, 20);
        }
        for k in 0..3 {
            for ch in 0..3 {
                self.push(c.values[k][ch] as u16 as u128, 16);
            }
        }
        self.push(c.material as u128, 16);
        self.push(c.flat as u128, 1);
        for ch in 0..3 {
            self.push(c.flat_rgb[ch] as u128, 8);
        }
    }
    /// Append texture planes in the TdbT record's packed layout (408 bits).
    pub fn push_tex_planes(&mut self, t: &TexPlanes) {
        for p in [&t.sw, &t.tw, &t.q] {
            self.push_signed(p.a, 40);
            self.push_signed(p.b, 40);
            self.push_signed(p.c, 56);
        }
    }
    /// Append a texture-setup command in its packed layout (409 bits).
    pub fn push_tex_command(&mut self, c: &TexSetupCmd) {
        self.push(c.index as u128, 16);
        for k in 0..3 {
            self.push(c.x[k] as u32 as u128 & 0xf_ffff, 20);
            self.push(c.y[k] as u32 as u128 & 0xf_ffff, 20);
        }
        for vk in &c.values {
            for &v in vk {
                self.push_signed(v, 33);
            }
        }
    }
    pub fn len(&self) -> usize {
        self.0.len()
    }
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// Hexadecimal, most significant digit first, `ceil(len/4)` digits ($readmemh format).
    pub fn hex(&self) -> String {
        let digits = self.0.len().div_ceil(4);
        let mut s = String::with_capacity(digits);
        for d in (0..digits).rev() {
            let mut v = 0u8;
            for b in 0..4 {
                if self.0.get(4 * d + b).copied().unwrap_or(false) {
                    v |= 1 << b;
                }
            }
            s.push(char::from_digit(v as u32, 16).unwrap());
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_round_trip_through_the_rtl_struct_and_match_its_packed_bits() {
        let e = TdbsEntry {
            planes: [
                Plane { a: -(1 << 39), b: (1 << 39) - 1, c: -(1 << 55) },
                Plane { a: 12345, b: -6789, c: (1 << 55) - 1 },
                Plane { a: -1, b: 0, c: 255 << 16 },
            ],
            material: 0xbeef,
        };
        let r = record_of(&e);
        assert_eq!(entry_of(&r), e);
        let packed: Bits<424> = r.into();
        let mut v = BitVector::default();
        v.push_record(&e);
        assert_eq!(v.len(), 424);
        for i in 0..424 {
            assert_eq!(packed.get_bit(i), v.0[i], "bit {i}");
        }
    }

    #[test]
    fn commands_pack_as_the_rtl_struct_does() {
        let c = SetupCmd {
            index: 0x1234,
            x: [-262144, 524287, 5],
            y: [-1, 0, -524288],
            values: [[255, 0, -16384], [16384, 7, 8], [9, -10, 11]],
            material: 3,
            flat: true,
            flat_rgb: [1, 2, 250],
        };
        let packed: Bits<321> = command_of(&c).into();
        let mut v = BitVector::default();
        v.push_command(&c);
        assert_eq!(v.len(), 321);
        for i in 0..321 {
            assert_eq!(packed.get_bit(i), v.0[i], "bit {i}");
        }
    }

    #[test]
    fn texture_commands_and_records_pack_as_the_rtl_structs_do() {
        let c = TexSetupCmd { index: 0xfedc, x: [-262144, 524287, 5], y: [-1, 0, -524288], values: [[-(1 << 32), (1 << 32) - 1, 1], [7, -8, 1 << 24], [123456789, -987654321, 3]] };
        let packed: Bits<433> = tex_command_of(&c).into();
        let mut v = BitVector::default();
        v.push_tex_command(&c);
        assert_eq!(v.len(), 433);
        for i in 0..433 {
            assert_eq!(packed.get_bit(i), v.0[i], "command bit {i}");
        }
        let t = TexPlanes {
            sw: Plane { a: -(1 << 39), b: (1 << 39) - 1, c: -(1 << 55) },
            tw: Plane { a: 12345, b: -6789, c: (1 << 55) - 1 },
            q: Plane { a: -1, b: 0, c: 255 << 16 },
        };
        let r = tdbt_record_of(&t);
        assert_eq!(tex_planes_of(&r), t);
        let packed: Bits<408> = r.into();
        let mut v = BitVector::default();
        v.push_tex_planes(&t);
        for i in 0..408 {
            assert_eq!(packed.get_bit(i), v.0[i], "record bit {i}");
        }
    }

    #[test]
    fn tdata_uses_the_ug934_component_order() {
        assert_eq!(tdata_of([0x11, 0x22, 0x33]), 0x113322);
        assert_eq!(rgb_of(0x113322), [0x11, 0x22, 0x33]);
        let mut v = BitVector::default();
        v.push(0xabc, 12);
        v.push(1, 1);
        assert_eq!(v.hex(), "1abc");
    }
}
