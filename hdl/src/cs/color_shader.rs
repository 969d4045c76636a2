//! `color_shader` (top `cs`): the Color Shader's scan-out engine (seed 001 §3.1, Fig. 5: "the CS
//! utilizes the data in I-buffer and TdbS to generate the final result ... frame buffer can be optional
//! if the CS can generate pixels in screen scan-out rate"). Reads the I-buffer in raster order, fetches
//! the TdbS record of each pixel's index, evaluates the record's three planes `c + a*X + b*Y` and
//! streams RGB888 out, one pixel per clock:
//! * flat and Gouraud (`shading_phong` low): the planes are R, G, B, rounded and clamped to 0..255;
//! * Phong (`shading_phong` high; seed 001 §3.3, seed 000 §III: per-pixel lighting at scan-out rate,
//!   once per visible pixel): the planes are the interpolated normal, which the [`Normalizer`] makes
//!   unit and [`CS_LIGHTS`] [`LightUnit`]s light with the pixel's material (seed 001 eq. 4: ambient,
//!   per light diffuse and specular with the gloss), rounded and clamped.
//!
//! Background (index 0) pixels get `background`.
//!
//! The pipeline is [`ScanPipe`] (shared with the textured CS, [`crate::cs::color_shader_tex`]); this
//! block adds the credit and the 32-deep output FIFO.
//!
//! ```text
//!                      +--------------------------------------------------------+
//!  start ------------->| frame control: W, H, background, clear_behind, phong    |--> busy
//!  width, height ----->| (latched at start; 1..=1024 else size_error)           |--> size_error
//!  background -------->|                                                        |
//!  clear_behind ------>|  issue (credit < 32)                                   |
//!  shading_phong ----->|   |                                                    |--> ibuf_read_enable/_address (20 b)
//!  ibuf_read_data ---->|   t+1 index arrives; clear-behind writes --------------|--> ibuf_write_*, zbuf_write_*
//!                      |   t+2 TdbS read                                        |--> tdbs_read_enable/_address (16 b)
//!  tdbs_read_data ---->|   t+3 record arrives: 6 products 40x11                 |
//!                      |   t+4 c + aX + bY + 1/2                                |
//!                      |   t+5 >>16: clamp 0..255 (Gouraud) | sat16 (normal) ---+-> normalizer (12)
//!                      |   t+17 light units (8 each, chained) <- material memory|
//!  light_write_* ----->|        L, H per light                                  |
//!  material_write_* -->|        ambient, gloss, Kd Il, Ks Il per material       |
//!                      |   t+25 ambient + lights;  t+26 round, clamp, mux       |
//!                      |   video_fifo (32 deep) --------------------------------|--> video_tdata {R,B,G}, _tvalid,
//!  video_tready ------>|                                                        |    _tuser (SOF), _tlast (EOL)
//!                      +--------------------------------------------------------+
//! ```
//!
//! Timing (`golden::cycle::color_shader` is the reference): a pixel issued in cycle t has its I-buffer
//! address on the port in t, its index in t+1 (when the clear-behind writes of its address happen), its
//! TdbS address in t+2, its record in t+3, and its beat in the FIFO at t+26's edge, on the video port
//! from t+27, whatever the shading (flat and Gouraud colours wait for the Phong path, so that one
//! latency and one credit serve both). A pixel is issued only while fewer than 32 are pending (issued
//! and not yet taken by the consumer): the FIFO can always hold every pixel in flight, so back-pressure
//! loses or repeats nothing, and with `video_tready` high 27 are pending, so a pixel is issued every
//! clock. Both memory read ports have latency 1 (data of the address of cycle t in t+1). All payload
//! outputs are 0 while their enable / valid is low.
//!
//! The light and material writes are for an idle CS (between frames): a frame reads whatever the
//! registers and the material memory hold while its pixels pass. The material memory is read at the
//! low [`CS_MATERIAL_BITS`] bits of the record's `material`.
//!
//! `video_tdata` follows the AXI4-Stream video convention for RGB (Xilinx UG934): R in 23:16, B in
//! 15:8, G in 7:0; `background` uses the same packing.

use crate::cs::scan_pipe::ScanPipe;
use crate::cs::video_fifo::{VideoFifo32, VIDEO_FIFO_DEPTH};
use crate::cs::{LightVectors, MaterialWord, TdbsRecord, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ColorShader {
    pub clock: Signal<In, Clock>,
    // From the controller
    /// Start a frame (taken when not busy).
    pub start: Signal<In, Bit>,
    /// Screen width in pixels, 1..=1024 (latched at start).
    pub width: Signal<In, Bits<11>>,
    /// Screen height in pixels, 1..=1024 (latched at start).
    pub height: Signal<In, Bits<11>>,
    /// Background colour where the index is 0, packed as `video_tdata` (latched at start).
    pub background: Signal<In, Bits<24>>,
    /// Clear the I-buffer (to 0) and the Z-buffer (to far) behind the scan (latched at start).
    pub clear_behind: Signal<In, Bit>,
    /// Phong: the planes are the normal, lit per pixel (latched at start); else they are R, G, B.
    pub shading_phong: Signal<In, Bit>,
    // From the host (Phong constants; write while not busy)
    /// Load light `light_write_address`'s L and H (a light the scene lacks keeps zero coefficients).
    pub light_write_enable: Signal<In, Bit>,
    pub light_write_address: Signal<In, Bits<2>>,
    pub light_write_data: Signal<In, LightVectors>,
    /// Write word `material_write_slot` of material `material_write_address`: slot 0 = ambient and
    /// log2 of the gloss, slot 1 + l = light l's diffuse and specular coefficients ([`MaterialWord`]).
    pub material_write_enable: Signal<In, Bit>,
    pub material_write_address: Signal<In, Bits<CS_MATERIAL_BITS>>,
    pub material_write_slot: Signal<In, Bits<3>>,
    pub material_write_data: Signal<In, MaterialWord>,
    // To the controller
    /// A frame is being scanned (from the cycle after the start to the cycle its last beat is taken).
    pub busy: Signal<Out, Bit>,
    /// The last start had a size outside 1..=1024 and was refused.
    pub size_error: Signal<Out, Bit>,
    // To / from the I-buffer (synchronous read, latency 1)
    /// Read the I-buffer at `ibuf_read_address` this cycle.
    pub ibuf_read_enable: Signal<Out, Bit>,
    /// Pixel address `y*width + x`.
    pub ibuf_read_address: Signal<Out, Bits<20>>,
    /// The index at the address of the previous cycle.
    pub ibuf_read_data: Signal<In, Bits<16>>,
    // To / from TdbS (synchronous read, latency 1)
    /// Read TdbS at `tdbs_read_address` this cycle.
    pub tdbs_read_enable: Signal<Out, Bit>,
    /// The triangle index.
    pub tdbs_read_address: Signal<Out, Bits<16>>,
    /// The record at the address of the previous cycle.
    pub tdbs_read_data: Signal<In, TdbsRecord>,
    // To the I-buffer and the Z-buffer (clear-behind write ports)
    /// Write `ibuf_write_data` (0, background) at `ibuf_write_address`.
    pub ibuf_write_enable: Signal<Out, Bit>,
    pub ibuf_write_address: Signal<Out, Bits<20>>,
    pub ibuf_write_data: Signal<Out, Bits<16>>,
    /// Write `zbuf_write_data` (2^24-1, far) at `zbuf_write_address`.
    pub zbuf_write_enable: Signal<Out, Bit>,
    pub zbuf_write_address: Signal<Out, Bits<20>>,
    pub zbuf_write_data: Signal<Out, Bits<24>>,
    // To the display (AXI4-Stream video)
    /// RGB888: R 23:16, B 15:8, G 7:0.
    pub video_tdata: Signal<Out, Bits<24>>,
    pub video_tvalid: Signal<Out, Bit>,
    /// The consumer takes the beat at this edge if `video_tvalid`.
    pub video_tready: Signal<In, Bit>,
    /// Start of frame: the beat is pixel (0, 0).
    pub video_tuser: Signal<Out, Bit>,
    /// End of line: the beat is the last pixel of its row.
    pub video_tlast: Signal<Out, Bit>,

    pipe: ScanPipe,
    fifo: VideoFifo32,
    /// Pixels issued and not yet taken by the consumer.
    pending: DFF<Bits<6>>,
    issue: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    k0_6: Constant<Bits<6>>,
    k1_6: Constant<Bits<6>>,
    kdepth_6: Constant<Bits<6>>,
}

impl Default for ColorShader {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            start: Default::default(),
            width: Default::default(),
            height: Default::default(),
            background: Default::default(),
            clear_behind: Default::default(),
            shading_phong: Default::default(),
            light_write_enable: Default::default(),
            light_write_address: Default::default(),
            light_write_data: Default::default(),
            material_write_enable: Default::default(),
            material_write_address: Default::default(),
            material_write_slot: Default::default(),
            material_write_data: Default::default(),
            busy: Default::default(),
            size_error: Default::default(),
            ibuf_read_enable: Default::default(),
            ibuf_read_address: Default::default(),
            ibuf_read_data: Default::default(),
            tdbs_read_enable: Default::default(),
            tdbs_read_address: Default::default(),
            tdbs_read_data: Default::default(),
            ibuf_write_enable: Default::default(),
            ibuf_write_address: Default::default(),
            ibuf_write_data: Default::default(),
            zbuf_write_enable: Default::default(),
            zbuf_write_address: Default::default(),
            zbuf_write_data: Default::default(),
            video_tdata: Default::default(),
            video_tvalid: Default::default(),
            video_tready: Default::default(),
            video_tuser: Default::default(),
            video_tlast: Default::default(),
            pipe: Default::default(),
            fifo: Default::default(),
            pending: Default::default(),
            issue: Default::default(),
            pop: Default::default(),
            k0_6: Constant::new(0.into()),
            k1_6: Constant::new(1.into()),
            kdepth_6: Constant::new((VIDEO_FIFO_DEPTH as u64).into()),
        }
    }
}

impl Logic for ColorShader {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, pending);
        clock!(self, clock, pipe, fifo);

        // Controller and host inputs; a start is passed only while not busy.
        self.busy.next = self.pipe.active.val() | (self.pending.q.val() != self.k0_6.val());
        self.pipe.start.next = self.start.val() & !self.busy.val();
        self.pipe.width.next = self.width.val();
        self.pipe.height.next = self.height.val();
        self.pipe.background.next = self.background.val();
        self.pipe.clear_behind.next = self.clear_behind.val();
        self.pipe.shading_phong.next = self.shading_phong.val();
        self.pipe.light_write_enable.next = self.light_write_enable.val();
        self.pipe.light_write_address.next = self.light_write_address.val();
        self.pipe.light_write_data.next = self.light_write_data.val();
        self.pipe.material_write_enable.next = self.material_write_enable.val();
        self.pipe.material_write_address.next = self.material_write_address.val();
        self.pipe.material_write_slot.next = self.material_write_slot.val();
        self.pipe.material_write_data.next = self.material_write_data.val();
        self.size_error.next = self.pipe.size_error.val();

        // Credit: issue while fewer than 32 pixels are pending; a pixel stops pending when taken.
        self.pipe.issue_ok.next = self.pending.q.val() != self.kdepth_6.val();
        self.issue.next = self.pipe.ibuf_read_enable.val();
        self.pop.next = self.fifo.read_valid.val() & self.video_tready.val();
        if self.issue.val() & !self.pop.val() {
            self.pending.d.next = self.pending.q.val() + self.k1_6.val();
        }
        if !self.issue.val() & self.pop.val() {
            self.pending.d.next = self.pending.q.val() - self.k1_6.val();
        }

        // Memory ports.
        self.ibuf_read_enable.next = self.pipe.ibuf_read_enable.val();
        self.ibuf_read_address.next = self.pipe.ibuf_read_address.val();
        self.pipe.ibuf_read_data.next = self.ibuf_read_data.val();
        self.tdbs_read_enable.next = self.pipe.tdbs_read_enable.val();
        self.tdbs_read_address.next = self.pipe.tdbs_read_address.val();
        self.pipe.tdbs_read_data.next = self.tdbs_read_data.val();
        self.ibuf_write_enable.next = self.pipe.ibuf_write_enable.val();
        self.ibuf_write_address.next = self.pipe.ibuf_write_address.val();
        self.ibuf_write_data.next = self.pipe.ibuf_write_data.val();
        self.zbuf_write_enable.next = self.pipe.zbuf_write_enable.val();
        self.zbuf_write_address.next = self.pipe.zbuf_write_address.val();
        self.zbuf_write_data.next = self.pipe.zbuf_write_data.val();

        // The pipeline's beats into the FIFO (t+26), out to the video port.
        self.fifo.write.next = self.pipe.beat_valid.val();
        self.fifo.write_data.next = self.pipe.beat_data.val();
        self.fifo.read.next = self.video_tready.val();
        self.video_tvalid.next = self.fifo.read_valid.val();
        self.video_tdata.next = self.fifo.read_data.val().get_bits::<24>(0);
        self.video_tuser.next = self.fifo.read_data.val().get_bit(24);
        self.video_tlast.next = self.fifo.read_data.val().get_bit(25);
    }
}
