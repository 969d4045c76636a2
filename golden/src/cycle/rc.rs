//! Cycle-accurate model of the Rasterizer Controller (seed 001 §2.3.1, §3.1): what every output port of
//! the RTL top `rc` shows in every clock cycle, given the inputs of that cycle.
//!
//! Written from the timing specification below (also in `docs/rc.md`) and the algorithmic model
//! [`crate::raster`]: the arithmetic of a triangle (culling, edge functions, bounding box, depth plane)
//! is *taken from* [`crate::raster::setup`], only *when* things happen is modelled here. The RTL
//! computes the same numbers with its own datapath; the testbench compares the two every cycle.
//!
//! # Ports (all synchronous to one clock; outputs depend on registers and, for the write ports, on
//! `z_rd_data` of the same cycle; an output whose valid/enable is low is driven 0)
//!
//! | port | dir | meaning |
//! |---|---|---|
//! | `cmd` valid/ready/data | in | commands: frame start (`clear`), triangle, end of frame |
//! | `result` valid/ready/data | out | per triangle {index, culled, zero_area, visible}; `eof` marker |
//! | `z_re`, `z_rd_addr` | out | Z-buffer read: data on `z_rd_data` in the next cycle |
//! | `z_rd_data` | in | 24-bit depth read one cycle after `z_re` (contents before that edge's write) |
//! | `i_rd_data` | in | the I-buffer word at the same address, read with the same `z_re`/`z_rd_addr` |
//! | `z_we`, `z_wr_addr`, `z_wr_data` | out | Z-buffer write, performed at the rising edge |
//! | `i_we`, `i_wr_addr`, `i_wr_data` | out | I-buffer write, performed at the rising edge |
//!
//! Addresses are `y * width + x` (20 bits). `z_rd_data` is only used in the cycle after `z_re`.
//!
//! # Timing
//!
//! *Setup unit*, two stages, each holding one command (`cmd.ready` is high exactly when the first
//! stage is `Idle`):
//! * First stage. Frame start and end of frame: accepted in cycle t, ready to hand over (`Hand`) in
//!   t+1. Triangle accepted in cycle t: t+1 determinant, t+2 culling / canonical order / bounding box
//!   and divider start; a culled triangle or one with an empty clamped bounding box is ready in t+3.
//!   Otherwise t+3..t+8 edge start values and the depth numerators, the 25-step reciprocal runs
//!   t+3..t+11 (three steps per clock) and is taken in t+12; ready in t+13 ([`HAND_DRAWN`]).
//! * Hand-over: in a `Hand` cycle the record moves to the second stage if that is empty in this cycle
//!   (otherwise the first stage waits); the first stage is `Idle` (accepting) the cycle after.
//! * Second stage: a drawn triangle's depth plane in the 7 cycles after the hand-over
//!   ([`PLANE_CYCLES`]), then the record is offered to the traversal; any other record is offered the
//!   cycle after the hand-over. Offered until taken; empty the cycle after.
//! * So a record is offered [`SETUP_CYCLES_DRAWN`] = 21 cycles after its command was accepted (4 for a
//!   culled or empty-box triangle, 2 for frame start and end of frame), and while the second stage
//!   works on one triangle's plane the first stage takes the next: drawn triangles back to back take
//!   14 cycles each (the first stage's `Idle` .. `Hand`), culled ones 4.
//!
//! *Traversal* (takes a record only in its `Idle` state):
//! * Frame start: with `clear`, W*H cycles of clear writes (Z = 2^24-1, I = 0, one pixel per clock,
//!   both buffers at once) starting the cycle after; without `clear`, nothing (the buffers were
//!   cleared elsewhere, e.g. behind the Color Shader's scan-out).
//! * A triangle to walk: loaded in the cycle it is taken, then its clamped bounding box in raster
//!   order, at most one fragment per clock, uncovered candidates skipped up to 4 or 16 at a time
//!   ([`walk_step`] is the rule); the cycle that ends the walk also takes the next record if it is a
//!   triangle or a frame start, so consecutive walks follow each other with no idle cycle.
//! * Results (a walk's last token, a culled/empty triangle, end of frame) go through the z-test stage
//!   into a one-word result register. Such a token is issued only when the result register is empty
//!   and the z-test stage holds no other result: otherwise the traversal waits (in the clock that would
//!   end the walk, or in `Idle` before taking the record). A walk's last token is its last fragment
//!   when the clock that issues it also ends the walk, else an uncovered end token.
//!
//! *Z-test stage* (the cycle after a candidate was issued): `z_rd_data` and `i_rd_data` arrive; the old
//! depth is 2^24-1 where the I-buffer holds the background index (a pixel no triangle of this frame has
//! written: its Z word is stale, not cleared), else `z_rd_data`; if the previous cycle wrote the same
//! address, that written depth is used instead (forwarding, no stall); pass = inside and z < old.
//! So the Z-buffer never needs a clear of its own: clearing the I-buffer (the RC's `clear`, or the
//! Color Shader's clear-behind) is enough. On a pass Z and I are written in this cycle. The triangle's visible flag is the OR of its
//! passes; its result enters the result register at the end of the cycle of its last candidate's
//! z-test. The end-of-frame result is pushed after every earlier write has been performed.

use crate::format::{Screen, WinVertex, DEPTH_MAX, INDEX_BACKGROUND};
use crate::raster::{setup, Culled, CullMode, FrontFace, Setup};

/// Cycles from accepting a triangle to its record being ready, when it is drawn (see module doc).
pub const SETUP_CYCLES_DRAWN: u64 = 21;
/// Cycles from accepting a triangle to its record being ready, when it is culled or has an empty box.
pub const SETUP_CYCLES_SHORT: u64 = 4;
/// Cycles from a command's acceptance to its hand-over from the setup's first stage to its second
/// (`Hand`), by kind: drawn triangle, culled triangle or empty box, frame start or end of frame.
pub const HAND_DRAWN: u64 = 13;
pub const HAND_SHORT: u64 = 3;
pub const HAND_MARKER: u64 = 1;
/// Cycles of the second stage (the depth plane) between the hand-over and the record's offer, for a
/// drawn triangle (0 for the others: offered the cycle after the hand-over).
pub const PLANE_CYCLES: u64 = 7;
/// Steps of the restoring divider (RECIP_BITS + 1).
pub const RECIP_STEPS: u32 = 25;
/// Width of a triangle index on the ports.
pub const INDEX_BITS: u32 = 16;

/// What a command does.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum CmdKind {
    /// Start a frame; `clear` asks the RC to clear both buffers itself.
    Frame,
    /// Draw a triangle.
    Triangle,
    /// End of frame: answered with an end-of-frame result after every earlier triangle's result.
    EndOfFrame,
}

/// One word on the command port.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct RcCmd {
    pub kind: CmdKind,
    pub clear: bool,
    pub index: u32,
    pub cull: CullMode,
    pub front: FrontFace,
    pub v: [WinVertex; 3],
}

impl RcCmd {
    pub fn frame(clear: bool) -> RcCmd {
        RcCmd { kind: CmdKind::Frame, clear, ..RcCmd::idle() }
    }
    pub fn end_of_frame() -> RcCmd {
        RcCmd { kind: CmdKind::EndOfFrame, ..RcCmd::idle() }
    }
    /// A triangle command; the vertices must fit the port formats (see [`RcCmd::check`]).
    pub fn triangle(index: u32, v: [WinVertex; 3], cull: CullMode, front: FrontFace) -> Result<RcCmd, String> {
        let c = RcCmd { kind: CmdKind::Triangle, clear: false, index, cull, front, v };
        c.check()?;
        Ok(c)
    }
    /// The value the bench drives while `valid` is low.
    pub fn idle() -> RcCmd {
        RcCmd {
            kind: CmdKind::Frame,
            clear: false,
            index: 0,
            cull: CullMode::Back,
            front: FrontFace::Ccw,
            v: [WinVertex::default(); 3],
        }
    }
    /// Whether the command fits the port: x, y in S11.4 16 bits, z in 24 bits, index in 16 bits.
    pub fn check(&self) -> Result<(), String> {
        if self.index >= 1 << INDEX_BITS {
            return Err(format!("triangle index {} does not fit the RC's {INDEX_BITS}-bit index", self.index));
        }
        for (k, p) in self.v.iter().enumerate() {
            if p.x < i16::MIN as i32 || p.x > i16::MAX as i32 || p.y < i16::MIN as i32 || p.y > i16::MAX as i32 {
                return Err(format!(
                    "triangle {}: vertex {k} ({}, {}) subpixels is outside the 16-bit S11.4 window format",
                    self.index, p.x, p.y
                ));
            }
            if p.z > DEPTH_MAX {
                return Err(format!("triangle {}: vertex {k} depth {} exceeds 24 bits", self.index, p.z));
            }
        }
        Ok(())
    }
}

/// One word on the result port.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct RcResult {
    pub eof: bool,
    pub index: u32,
    pub culled: bool,
    pub zero_area: bool,
    pub visible: bool,
}

/// The inputs of one cycle.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RcInputs {
    pub cmd_valid: bool,
    pub cmd: RcCmd,
    pub res_ready: bool,
    pub z_rd_data: u32,
    /// The I-buffer word read with `z_re`/`z_rd_addr` (background: the Z word is stale).
    pub i_rd_data: u32,
}

/// The outputs of one cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct RcOutputs {
    pub cmd_ready: bool,
    pub res_valid: bool,
    pub res: RcResult,
    pub z_re: bool,
    pub z_rd_addr: u32,
    pub z_we: bool,
    pub z_wr_addr: u32,
    pub z_wr_data: u32,
    pub i_we: bool,
    pub i_wr_addr: u32,
    pub i_wr_data: u32,
}

impl RcOutputs {
    /// The ports as (name, value) pairs, in a fixed order: what benches compare and print.
    pub fn ports(&self) -> [(&'static str, u64); 15] {
        [
            ("cmd_ready", self.cmd_ready as u64),
            ("res_valid", self.res_valid as u64),
            ("res.eof", self.res.eof as u64),
            ("res.index", self.res.index as u64),
            ("res.culled", self.res.culled as u64),
            ("res.zero_area", self.res.zero_area as u64),
            ("res.visible", self.res.visible as u64),
            ("z_re", self.z_re as u64),
            ("z_rd_addr", self.z_rd_addr as u64),
            ("z_we", self.z_we as u64),
            ("z_wr_addr", self.z_wr_addr as u64),
            ("z_wr_data", self.z_wr_data as u64),
            ("i_we", self.i_we as u64),
            ("i_wr_addr", self.i_wr_addr as u64),
            ("i_wr_data", self.i_wr_data as u64),
        ]
    }
}

/// What the setup unit hands to the traversal.
#[derive(Copy, Clone, Debug)]
enum Record {
    Frame { clear: bool },
    EndOfFrame,
    /// Culled, zero area or empty bounding box: a result without traversal.
    Skip { index: u32, culled: Option<Culled> },
    Walk { index: u32, setup: Setup },
}

/// One stage of the setup: empty, or holding a record that is ready (to hand over, or to offer) after
/// `n` more cycles (n = 0: ready now).
#[derive(Copy, Clone, Debug, PartialEq)]
enum SetupState {
    Idle,
    Busy(u64),
}

/// A token entering the z-test stage.
#[derive(Copy, Clone, Debug, PartialEq)]
enum Token {
    None,
    Clear { addr: u32 },
    Frag { inside: bool, last: bool, addr: u32, z: u32, index: u32 },
    Result(RcResult),
}

impl Token {
    fn pushes_result(&self) -> bool {
        matches!(self, Token::Result(_) | Token::Frag { last: true, .. })
    }
}

#[derive(Copy, Clone, Debug, PartialEq)]
enum TravState {
    Idle,
    Clear { addr: u32 },
    Walk { x: i32, y: i32 },
}

/// Candidates the traversal looks at per clock: it issues the first covered one (at most one
/// fragment per clock) and skips the rest of the window when none is covered.
pub const WALK_WINDOW: i32 = 4;
/// Candidates skipped in one clock when an edge function rules them all out.
pub const WALK_LONG_SKIP: i32 = 16;

/// One clock of the walk at candidate (x, y): the fragment issued (its x), whether the walk ends in
/// this clock, and the next candidate otherwise.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct WalkStep {
    pub frag: Option<i32>,
    pub end: bool,
    pub next_x: i32,
    pub next_y: i32,
}

/// The traversal's rule (docs/rc.md, "Traversal"): the window is the candidates x..=x+3 of the row,
/// not past the box. Issue the first covered one and go on at the next covered one in the window.
/// With none left, the clock skips ahead: past the window, or past [`WALK_LONG_SKIP`] candidates when
/// none is covered and an edge function is negative both at x and at x+15 (it is linear, so it is
/// negative in between). It ends the row instead when the skip reaches the box's edge or when, at the
/// skip's last candidate, an edge function is negative and does not grow to the right (step_x <= 0:
/// nothing further right in this row is inside). The walk ends with the last row.
pub fn walk_step(s: &Setup, x: i32, y: i32) -> WalkStep {
    let b = s.bbox;
    let mut covered = (x..=(x + WALK_WINDOW - 1).min(b.x1)).filter(|&cx| s.covers(cx, y));
    let frag = covered.next();
    let next_covered = covered.next();
    let (xi, yi) = (x as i64, y as i64);
    let long = frag.is_none() && s.edges.iter().any(|e| e.at(xi, yi) < 0 && e.at(xi + WALK_LONG_SKIP as i64 - 1, yi) < 0);
    let far = x + if long { WALK_LONG_SKIP } else { WALK_WINDOW } - 1;
    let dead = s.edges.iter().any(|e| e.at(far as i64, yi) < 0 && e.step_x <= 0);
    let row_done = next_covered.is_none() && (far >= b.x1 || dead);
    let end = row_done && y == b.y1;
    let (next_x, next_y) = match (row_done, next_covered) {
        (true, _) => (b.x0, y + 1),
        (false, Some(nx)) => (nx, y),
        (false, None) => (far + 1, y),
    };
    WalkStep { frag, end, next_x, next_y }
}

/// The cycle-accurate RC.
#[derive(Clone, Debug)]
pub struct RcModel {
    screen: Screen,
    // setup unit
    /// The setup's first stage (det, cull, box, edges, numerators, reciprocal) and its record.
    sstate: SetupState,
    pending: Option<Record>,
    /// The second stage (the depth plane, then the offer to the traversal) and its record.
    bstate: SetupState,
    bpending: Option<Record>,
    // traversal
    tstate: TravState,
    walking: Option<(u32, Setup)>,
    // z-test stage
    f1: Token,
    fwd: Option<(u32, u32)>,
    vis: bool,
    // result register
    res: Option<RcResult>,
    /// Cycles stepped so far.
    pub cycle: u64,
    /// Cycles the traversal spent walking triangles, and those of them that issued a fragment.
    pub walk_clocks: u64,
    pub walk_fragment_clocks: u64,
}

impl RcModel {
    pub fn new(screen: Screen) -> RcModel {
        RcModel {
            screen,
            sstate: SetupState::Idle,
            pending: None,
            bstate: SetupState::Idle,
            bpending: None,
            tstate: TravState::Idle,
            walking: None,
            f1: Token::None,
            fwd: None,
            vis: false,
            res: None,
            cycle: 0,
            walk_clocks: 0,
            walk_fragment_clocks: 0,
        }
    }

    pub fn screen(&self) -> Screen {
        self.screen
    }

    /// Whether nothing is in flight: no command in setup, the traversal idle, no result waiting.
    pub fn is_idle(&self) -> bool {
        self.sstate == SetupState::Idle && self.bstate == SetupState::Idle && self.tstate == TravState::Idle && self.f1 == Token::None && self.res.is_none()
    }

    fn addr(&self, x: i32, y: i32) -> u32 {
        y as u32 * self.screen.width + x as u32
    }

    /// The record the setup unit offers this cycle, if ready.
    fn offered(&self) -> Option<Record> {
        match self.bstate {
            SetupState::Busy(0) => self.bpending,
            _ => None,
        }
    }

    /// This cycle's walk step, when walking (found once per cycle, used by the token and the edge).
    fn walk(&self) -> Option<WalkStep> {
        match (self.tstate, self.walking) {
            (TravState::Walk { x, y }, Some((_, s))) => Some(walk_step(&s, x, y)),
            _ => None,
        }
    }

    /// The token the traversal issues this cycle and whether it takes the offered record, given this
    /// cycle's walk step.
    fn traversal(&self, walk: Option<WalkStep>) -> (Token, bool) {
        let result_free = self.res.is_none() && !self.f1.pushes_result();
        match self.tstate {
            TravState::Clear { addr } => (Token::Clear { addr }, false),
            TravState::Walk { x, y } => {
                let (index, s) = self.walking.expect("walking without a triangle");
                let w = walk.expect("a walk step while walking");
                if w.end && !result_free {
                    return (Token::None, false);
                }
                // The cycle that ends a walk also takes the next record when it needs no token of its
                // own (a triangle to walk, a frame start): no idle cycle between triangles.
                let take = w.end && matches!(self.offered(), Some(Record::Walk { .. }) | Some(Record::Frame { .. }));
                match (w.frag, w.end) {
                    (Some(fx), last) => (Token::Frag { inside: true, last, addr: self.addr(fx, y), z: s.depth_at(fx, y), index }, take),
                    (None, true) => (Token::Frag { inside: false, last: true, addr: self.addr(x, y), z: 0, index }, take),
                    (None, false) => (Token::None, false),
                }
            }
            TravState::Idle => match self.offered() {
                None => (Token::None, false),
                Some(Record::Frame { .. }) | Some(Record::Walk { .. }) => (Token::None, true),
                Some(Record::EndOfFrame) if result_free => (Token::Result(RcResult { eof: true, ..RcResult::default() }), true),
                Some(Record::Skip { index, culled }) if result_free => (
                    Token::Result(RcResult {
                        eof: false,
                        index,
                        culled: culled.is_some(),
                        zero_area: culled == Some(Culled::ZeroArea),
                        visible: false,
                    }),
                    true,
                ),
                Some(_) => (Token::None, false),
            },
        }
    }

    /// The traversal's state after taking `rec` (from `Idle`, or in the cycle that ends a walk).
    fn start_record(&mut self, rec: Record) {
        match rec {
            Record::Frame { clear: true } => self.tstate = TravState::Clear { addr: 0 },
            Record::Walk { index, setup } => {
                self.tstate = TravState::Walk { x: setup.bbox.x0, y: setup.bbox.y0 };
                self.walking = Some((index, setup));
            }
            _ => {}
        }
    }

    /// The z-test stage's decision this cycle: (write, pass).
    fn z_test(&self, z_rd_data: u32, i_rd_data: u32) -> (Option<(u32, u32, u32)>, bool) {
        match self.f1 {
            Token::Clear { addr } => (Some((addr, DEPTH_MAX, INDEX_BACKGROUND)), false),
            Token::Frag { inside: true, addr, z, index, .. } => {
                let old = match self.fwd {
                    Some((a, d)) if a == addr => d,
                    _ if i_rd_data == INDEX_BACKGROUND => DEPTH_MAX,
                    _ => z_rd_data,
                };
                if z < old {
                    (Some((addr, z, index)), true)
                } else {
                    (None, false)
                }
            }
            _ => (None, false),
        }
    }

    /// One clock cycle: the outputs during the cycle (before the rising edge), then the edge.
    pub fn step(&mut self, inp: &RcInputs) -> RcOutputs {
        let walk = self.walk();
        let (tok, take) = self.traversal(walk);
        if let TravState::Walk { .. } = self.tstate {
            self.walk_clocks += 1;
            self.walk_fragment_clocks += matches!(tok, Token::Frag { inside: true, .. }) as u64;
        }
        let (write, pass) = self.z_test(inp.z_rd_data, inp.i_rd_data);
        let mut out = RcOutputs { cmd_ready: self.sstate == SetupState::Idle, ..RcOutputs::default() };
        if let Some(r) = self.res {
            out.res_valid = true;
            out.res = r;
        }
        if let Token::Frag { inside: true, addr, .. } = tok {
            out.z_re = true;
            out.z_rd_addr = addr;
        }
        if let Some((addr, z, i)) = write {
            (out.z_we, out.z_wr_addr, out.z_wr_data) = (true, addr, z);
            (out.i_we, out.i_wr_addr, out.i_wr_data) = (true, addr, i);
        }

        // ---- rising edge ----
        // Result register: pop, then push from the z-test stage.
        if out.res_valid && inp.res_ready {
            self.res = None;
        }
        match self.f1 {
            Token::Result(r) => self.res = Some(r),
            Token::Frag { last: true, index, .. } => {
                self.res = Some(RcResult { index, visible: self.vis || pass, ..RcResult::default() });
                self.vis = false;
            }
            Token::Frag { .. } => self.vis |= pass,
            _ => {}
        }
        self.fwd = write.map(|(a, z, _)| (a, z));
        self.f1 = tok;

        // Traversal.
        let offered = self.offered();
        match self.tstate {
            TravState::Clear { addr } => {
                self.tstate = if addr + 1 == self.screen.width * self.screen.height { TravState::Idle } else { TravState::Clear { addr: addr + 1 } };
            }
            TravState::Walk { .. } => {
                let w = walk.expect("a walk step while walking");
                if w.end {
                    if tok != Token::None {
                        self.tstate = TravState::Idle;
                        self.walking = None;
                        if take {
                            self.start_record(offered.unwrap());
                        }
                    }
                } else {
                    self.tstate = TravState::Walk { x: w.next_x, y: w.next_y };
                }
            }
            TravState::Idle => {
                if take {
                    self.start_record(offered.unwrap());
                }
            }
        }

        // Setup, second stage: the offered record leaves when taken.
        let b_was_idle = self.bstate == SetupState::Idle;
        match self.bstate {
            SetupState::Idle => {}
            SetupState::Busy(0) => {
                if take {
                    self.bpending = None;
                    self.bstate = SetupState::Idle;
                }
            }
            SetupState::Busy(n) => self.bstate = SetupState::Busy(n - 1),
        }
        // Setup, first stage: a finished record goes to the second stage when that was empty in this
        // cycle; a command is taken when the first stage was empty.
        match self.sstate {
            SetupState::Idle => {
                if inp.cmd_valid {
                    let c = inp.cmd;
                    let (rec, cycles) = match c.kind {
                        CmdKind::Frame => (Record::Frame { clear: c.clear }, HAND_MARKER),
                        CmdKind::EndOfFrame => (Record::EndOfFrame, HAND_MARKER),
                        CmdKind::Triangle => match setup(&c.v, c.cull, c.front, self.screen) {
                            Err(culled) => (Record::Skip { index: c.index, culled: Some(culled) }, HAND_SHORT),
                            Ok(s) if s.bbox.is_empty() => (Record::Skip { index: c.index, culled: None }, HAND_SHORT),
                            Ok(s) => (Record::Walk { index: c.index, setup: s }, HAND_DRAWN),
                        },
                    };
                    self.pending = Some(rec);
                    self.sstate = SetupState::Busy(cycles - 1);
                }
            }
            SetupState::Busy(0) => {
                if b_was_idle {
                    let rec = self.pending.take().expect("a finished record");
                    let plane = if let Record::Walk { .. } = rec { PLANE_CYCLES } else { 0 };
                    self.bpending = Some(rec);
                    self.bstate = SetupState::Busy(plane);
                    self.sstate = SetupState::Idle;
                }
            }
            SetupState::Busy(n) => self.sstate = SetupState::Busy(n - 1),
        }
        self.cycle += 1;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: i32, y: i32, z: u32) -> WinVertex {
        WinVertex { x, y, z }
    }

    /// Drive one command and idle inputs until the model is idle, with an ideal 1-cycle memory.
    fn run(m: &mut RcModel, cmds: &[RcCmd], z: &mut [u32], i: &mut [u32]) -> (Vec<(u64, RcResult)>, u64) {
        let mut results = Vec::new();
        let mut next = 0;
        let (mut rd, mut ird) = (0u32, 0u32);
        for _ in 0..1_000_000u64 {
            let valid = next < cmds.len();
            let inp = RcInputs { cmd_valid: valid, cmd: if valid { cmds[next] } else { RcCmd::idle() }, res_ready: true, z_rd_data: rd, i_rd_data: ird };
            let o = m.step(&inp);
            if valid && o.cmd_ready {
                next += 1;
            }
            if o.res_valid {
                results.push((m.cycle - 1, o.res));
            }
            if o.z_re {
                rd = z[o.z_rd_addr as usize];
                ird = i[o.z_rd_addr as usize];
            }
            if o.z_we {
                z[o.z_wr_addr as usize] = o.z_wr_data;
            }
            if o.i_we {
                i[o.i_wr_addr as usize] = o.i_wr_data;
            }
            if next == cmds.len() && m.is_idle() {
                return (results, m.cycle);
            }
        }
        panic!("model did not go idle");
    }

    #[test]
    fn a_drawn_triangle_takes_the_documented_setup_latency_then_one_fragment_per_clock() {
        let screen = Screen::new(16, 16).unwrap();
        let mut m = RcModel::new(screen);
        // A 4x4-pixel box, clockwise (det > 0), drawn with CullMode::None. Pixels whose centres are
        // inside: X + Y < 4 with the diagonal excluded (not top-left) -> rows of 3, 2, 1 and 0.
        let t = RcCmd::triangle(7, [v(0, 0, 10), v(64, 0, 10), v(0, 64, 10)], CullMode::None, FrontFace::Ccw).unwrap();
        let (mut z, mut i) = (vec![DEPTH_MAX; 256], vec![0; 256]);
        let (res, _) = run(&mut m, &[t], &mut z, &mut i);
        // Accepted in cycle 0, record ready in cycle SETUP_CYCLES_DRAWN (21) and taken there. The walk:
        // one clock per fragment (3 + 2 + 1), the last of a row ending the row because the window
        // reaches the box's edge, and one clock for the empty last row: 7 clocks. The last token's
        // z-test one cycle later, the result in the register the cycle after that.
        assert_eq!(res[0], (SETUP_CYCLES_DRAWN + 7 + 2, RcResult { index: 7, visible: true, ..Default::default() }));
        assert_eq!(i.iter().filter(|&&x| x == 7).count(), 6);
    }

    /// The walk issues every covered pixel of the box exactly once, in raster order, and nothing
    /// else, on random triangles of every size and orientation (the rule that skips candidates must
    /// never skip a covered one).
    #[test]
    fn the_walk_issues_every_covered_pixel_once_in_raster_order_and_nothing_else() {
        let screen = Screen::new(64, 48).unwrap();
        let mut seed = 0x9e3779b97f4a7c15u64;
        let mut rnd = |n: i64| -> i64 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % n as u64) as i64
        };
        let mut walked = 0;
        for t in 0..3000 {
            let span = [8, 40, 200, 1100][t % 4];
            let (cx, cy) = (rnd(64 * 16), rnd(48 * 16));
            let p = |r: &mut dyn FnMut(i64) -> i64| v((cx + r(2 * span) - span) as i32, (cy + r(2 * span) - span) as i32, 5);
            let tri = [p(&mut rnd), p(&mut rnd), p(&mut rnd)];
            let Ok(s) = setup(&tri, CullMode::None, FrontFace::Ccw, screen) else { continue };
            if s.bbox.is_empty() {
                continue;
            }
            let want: Vec<(i32, i32)> = (s.bbox.y0..=s.bbox.y1).flat_map(|y| (s.bbox.x0..=s.bbox.x1).map(move |x| (x, y))).filter(|&(x, y)| s.covers(x, y)).collect();
            let (mut x, mut y, mut got, mut clocks) = (s.bbox.x0, s.bbox.y0, Vec::new(), 0u64);
            loop {
                let w = walk_step(&s, x, y);
                clocks += 1;
                got.extend(w.frag.map(|fx| (fx, y)));
                if w.end {
                    break;
                }
                assert!(w.next_y == y && w.next_x > x || w.next_y == y + 1 && w.next_x == s.bbox.x0, "the walk went backwards");
                (x, y) = (w.next_x, w.next_y);
            }
            assert_eq!(got, want, "triangle {tri:?}");
            assert!(clocks <= s.bbox.pixels(), "more clocks than candidates");
            walked += 1;
        }
        assert!(walked > 1500, "only {walked} triangles walked");
    }

    #[test]
    fn a_stale_depth_under_a_background_index_counts_as_far_so_z_needs_no_clear() {
        let screen = Screen::new(16, 16).unwrap();
        let t = RcCmd::triangle(7, [v(0, 0, 10), v(64, 0, 10), v(0, 64, 10)], CullMode::None, FrontFace::Ccw).unwrap();
        // Z words nearer than the triangle everywhere (left by an earlier frame), I-buffer cleared.
        let (mut z, mut i) = (vec![0; 256], vec![INDEX_BACKGROUND; 256]);
        let (res, _) = run(&mut RcModel::new(screen), &[RcCmd::frame(false), t, RcCmd::end_of_frame()], &mut z, &mut i);
        assert!(res[0].1.visible, "the stale depths hid the triangle");
        assert_eq!(i.iter().filter(|&&x| x == 7).count(), 6);
        // Where the I-buffer holds an index, its depth is valid and hides the triangle.
        let (mut z, mut i) = (vec![0; 256], vec![3; 256]);
        let (res, _) = run(&mut RcModel::new(screen), &[RcCmd::frame(false), t, RcCmd::end_of_frame()], &mut z, &mut i);
        assert!(!res[0].1.visible && i.iter().all(|&x| x == 3));
    }

    #[test]
    fn clear_takes_one_cycle_per_pixel_for_both_buffers() {
        let screen = Screen::new(8, 4).unwrap();
        let mut m = RcModel::new(screen);
        let (mut z, mut i) = (vec![5; 32], vec![9; 32]);
        let (res, cycles) = run(&mut m, &[RcCmd::frame(true), RcCmd::end_of_frame()], &mut z, &mut i);
        assert!(z.iter().all(|&d| d == DEPTH_MAX) && i.iter().all(|&x| x == 0));
        assert_eq!(res.len(), 1);
        assert!(res[0].1.eof);
        // Frame accepted in 0, taken by the traversal in 1, clear tokens 2..=33 (32 pixels).
        assert!(cycles >= 32 + 2 && cycles <= 32 + 8, "cycles {cycles}");
    }

    #[test]
    fn commands_outside_the_port_formats_are_rejected_with_the_reason() {
        let e = RcCmd::triangle(1, [v(40000, 0, 0), v(0, 0, 0), v(0, 1, 0)], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("S11.4"), "{e}");
        let e = RcCmd::triangle(1, [v(0, 0, 1 << 24), v(0, 0, 0), v(0, 1, 0)], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("24 bits"), "{e}");
        let e = RcCmd::triangle(70000, [v(0, 0, 0); 3], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("16-bit index"), "{e}");
    }
}
