//! Cycle model of the CS's texture unit (`hdl::cs::texture_sampler`, issue 17 item 4), on its ports:
//! a pixel stream (valid/ready) of (s, t, level of detail, colour) in, the four texture banks' read
//! enables and addresses out, the textured colour out.
//!
//! Timing, from the issue's requirement (nearest and bilinear one pixel per clock, trilinear at least
//! one every two) and the banked memory (`crate::texbank`):
//! * each cycle with a pixel offered issues one footprint: level L = min(lod >> 4, last level); a
//!   trilinear pixel whose level of detail has a fraction and whose L is below the last level
//!   issues L first, with `ready` low, and L + 1 in the next cycle, when it is accepted;
//! * a footprint issued in cycle c is on the bank ports in cycle c + 3 (its data is expected back in
//!   c + 4);
//! * a pixel accepted in cycle c has its colour on `rgb_out` with `valid_out` in cycle
//!   c + [`TEXTURE_SAMPLER_LATENCY`]: `modulate(Texture::sample(..), colour)`.
//!
//! Outputs are 0 where nothing is due.

use crate::texbank::{footprint, layout, Footprint, LevelGeom};
use crate::texture::{modulate, Filter, Texture, Wrap};
use std::collections::VecDeque;

/// Cycles from a pixel's acceptance to its colour.
pub const TEXTURE_SAMPLER_LATENCY: usize = 8;
/// Cycles from a footprint's issue to its addresses on the bank ports.
pub const ISSUE_TO_BANKS: usize = 3;

/// A pixel offered to the unit.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SamplerPixel {
    /// Q15.16 of the texture.
    pub s: i32,
    pub t: i32,
    /// Q4.4.
    pub lod: u8,
    pub colour: [u8; 3],
    /// False for a pixel that passes through untextured (the background in the Color Shader): no
    /// footprint, `colour` out after the same latency.
    pub textured: bool,
}

/// The unit's outputs in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct SamplerOut {
    pub ready: bool,
    /// The footprint on the bank ports (read enables and addresses; all 0 when none).
    pub banks: Footprint,
    /// The textured colour, when one is due.
    pub rgb: Option<[u8; 3]>,
}

/// The texture unit, for one texture and its settings.
#[derive(Clone, Debug)]
pub struct TextureSamplerModel {
    texture: Texture,
    geoms: Vec<LevelGeom>,
    filter: Filter,
    wrap: Wrap,
    pending: bool,
    cycle: usize,
    footprints: VecDeque<(usize, Footprint)>,
    colours: VecDeque<(usize, [u8; 3])>,
}

impl TextureSamplerModel {
    pub fn new(texture: Texture, filter: Filter, wrap: Wrap) -> TextureSamplerModel {
        let geoms = layout(&texture);
        TextureSamplerModel { texture, geoms, filter, wrap, pending: false, cycle: 0, footprints: VecDeque::new(), colours: VecDeque::new() }
    }

    /// Whether `p` takes two cycles (trilinear between two levels).
    pub fn takes_two_cycles(&self, p: &SamplerPixel) -> bool {
        p.textured && self.texture.levels_for(p.lod, self.filter).1.is_some()
    }

    /// Whether nothing is in flight.
    pub fn idle(&self) -> bool {
        self.footprints.is_empty() && self.colours.is_empty() && !self.pending
    }

    /// One clock: `offer` is the pixel on the input (valid), held by the caller until `ready`.
    pub fn step(&mut self, offer: Option<&SamplerPixel>) -> SamplerOut {
        let mut ready = true;
        if let Some(p) = offer.filter(|p| !p.textured) {
            self.pending = false;
            self.colours.push_back((self.cycle + TEXTURE_SAMPLER_LATENCY, p.colour));
        } else if let Some(p) = offer {
            let (level, second) = self.texture.levels_for(p.lod, self.filter);
            let issue = match second {
                Some((next, _)) if self.pending => next,
                _ => level,
            };
            let fp = footprint(self.geoms[issue], p.s, p.t, self.filter != Filter::Nearest, self.wrap);
            self.footprints.push_back((self.cycle + ISSUE_TO_BANKS, fp));
            if second.is_some() && !self.pending {
                ready = false;
                self.pending = true;
            } else {
                self.pending = false;
                let rgb = modulate(self.texture.sample(p.s, p.t, p.lod, self.filter, self.wrap), p.colour);
                self.colours.push_back((self.cycle + TEXTURE_SAMPLER_LATENCY, rgb));
            }
        } else {
            self.pending = false;
        }
        let banks = match self.footprints.front() {
            Some(&(c, fp)) if c == self.cycle => {
                self.footprints.pop_front();
                fp
            }
            _ => Footprint::default(),
        };
        let rgb = match self.colours.front() {
            Some(&(c, rgb)) if c == self.cycle => {
                self.colours.pop_front();
                Some(rgb)
            }
            _ => None,
        };
        self.cycle += 1;
        SamplerOut { ready, banks, rgb }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trilinear_pixel_between_two_levels_takes_two_cycles_and_others_one() {
        let tex = Texture::new(4, 4, vec![[50, 100, 150]; 16]).unwrap();
        let mut m = TextureSamplerModel::new(tex, Filter::Trilinear, Wrap::Repeat);
        let between = SamplerPixel { s: 1 << 14, t: 1 << 14, lod: 0x18, colour: [255; 3], textured: true };
        let whole = SamplerPixel { lod: 0x10, ..between };
        let beyond = SamplerPixel { lod: 0x28, ..between }; // level 2 is the last (1x1)
        assert!(!m.step(Some(&between)).ready);
        assert!(m.step(Some(&between)).ready);
        assert!(m.step(Some(&whole)).ready);
        assert!(m.step(Some(&beyond)).ready);
        // Results: 8 cycles after each acceptance (cycles 1, 2, 3), the uniform colour.
        let outs: Vec<SamplerOut> = (0..12).map(|_| m.step(None)).collect();
        let due: Vec<usize> = outs.iter().enumerate().filter(|(_, o)| o.rgb.is_some()).map(|(k, _)| k + 4).collect();
        assert_eq!(due, vec![9, 10, 11]);
        assert!(outs.iter().filter_map(|o| o.rgb).all(|c| c == [50, 100, 150]));
        assert!(m.idle());
    }
}
