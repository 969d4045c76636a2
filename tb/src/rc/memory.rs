//! The memory models behind the RC's Z-buffer and I-buffer ports: synchronous SRAM, one read and one
//! write port, read data one cycle after the read enable, a read of the address being written returns
//! the old contents (what FPGA block RAM in "read first" mode and the RTL's forwarding assume).

/// A `len`-word synchronous SRAM of `bits`-bit words.
#[derive(Clone, Debug)]
pub struct Sram {
    pub words: Vec<u32>,
    bits: u32,
    rd: u32,
}

impl Sram {
    /// Every word set to `fill`.
    pub fn new(len: usize, bits: u32, fill: u32) -> Sram {
        Sram { words: vec![fill & Self::mask(bits); len], bits, rd: 0 }
    }
    /// Words from a seeded source: what a buffer holds before anything cleared it.
    pub fn garbage(len: usize, bits: u32, rng: &mut crate::common::Rng) -> Sram {
        Sram { words: (0..len).map(|_| rng.next_u64() as u32 & Self::mask(bits)).collect(), bits, rd: 0 }
    }
    fn mask(bits: u32) -> u32 {
        ((1u64 << bits) - 1) as u32
    }
    /// The read port's data output in this cycle.
    pub fn read_data(&self) -> u32 {
        self.rd
    }
    /// The rising edge: read (old contents), then write. An address outside the memory is an error.
    pub fn edge(&mut self, read: Option<u32>, write: Option<(u32, u32)>) -> Result<(), String> {
        if let Some(a) = read {
            self.rd = *self.words.get(a as usize).ok_or_else(|| format!("read of address {a} outside a {}-word memory", self.words.len()))?;
        }
        if let Some((a, d)) = write {
            if d > Self::mask(self.bits) {
                return Err(format!("write of {d:#x} to address {a} does not fit {} bits", self.bits));
            }
            let len = self.words.len();
            *self.words.get_mut(a as usize).ok_or_else(|| format!("write to address {a} outside a {len}-word memory"))? = d;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_read_during_a_write_to_the_same_address_returns_the_old_word() {
        let mut m = Sram::new(4, 24, 7);
        m.edge(Some(2), Some((2, 9))).unwrap();
        assert_eq!(m.read_data(), 7);
        m.edge(Some(2), None).unwrap();
        assert_eq!(m.read_data(), 9);
        assert!(m.edge(Some(4), None).unwrap_err().contains("outside"));
    }
}
