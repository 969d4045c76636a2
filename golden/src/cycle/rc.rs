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
//! *Setup unit*: a pipeline of [`SETUP_STAGES`] stages, each holding one command on its way to
//! becoming a traversal record, a pipelined reciprocal beside it and a queue of [`RECORD_QUEUE`]
//! records behind it (docs/rc.md, "Setup", has the stages' arithmetic):
//! * Stages S0 `Det`, S1 `Order`, S2 `Edges`, S3, S4 and S5 `Hold`, S6 `Grad`, S7 `Plane`. A drawn
//!   triangle spends [`STAGE_CYCLES_DRAWN`] cycles in them when nothing waits; any other command (frame
//!   start, end of frame, a culled or empty-box triangle) one cycle in each.
//! * Handshake, from the registers at the start of a cycle, last stage first: a stage hands its record
//!   on when it has spent its cycles and the next stage is empty or hands its own on in the same cycle;
//!   S7 when the queue holds fewer than [`RECORD_QUEUE`] records at the cycle's start. S1 hands a drawn
//!   triangle on only when the reciprocal advances, which is its request's acceptance. `cmd.ready` is
//!   high when S0 is empty or hands its command on.
//! * The reciprocal: [`RECIP_LATENCY`] stations; it advances (every request one station on, S1's
//!   request into the first) unless its last station holds a result that S6 does not take in this
//!   cycle. S6 takes it in its first cycle with a drawn triangle, and waits there until it comes.
//! * So a drawn triangle is offered to the traversal [`SETUP_CYCLES_DRAWN`] cycles after its command
//!   was accepted, anything else [`SETUP_CYCLES_SHORT`] cycles after; back to back, drawn triangles
//!   are accepted every 4 cycles (S2's, S6's and S7's four) and other commands every cycle.
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
//!   into a result queue of [`RESULT_QUEUE`] words. Such a token is issued only when the queue's length
//!   plus the results in the z-test stages (F0, F1) is below [`RESULT_QUEUE`]: otherwise the traversal waits (in the clock that would
//!   end the walk, or in `Idle` before taking the record). A walk's last token is its last fragment
//!   when the clock that issues it also ends the walk, else an uncovered end token.
//!
//! *Z-test stages*: F0 (the cycle after a candidate was issued; the traversal's token is registered
//! there, off the walk's decision) issues the Z and I read of a covered fragment (`z_re`,
//! `z_rd_addr`). F1 (the cycle after that): `z_rd_data` and `i_rd_data` arrive; the old
//! depth is 2^24-1 where the I-buffer holds the background index (a pixel no triangle of this frame has
//! written: its Z word is stale, not cleared), else `z_rd_data`; if the previous cycle wrote the same
//! address, that written depth is used instead (forwarding, no stall); pass = inside and z < old.
//! So the Z-buffer never needs a clear of its own: clearing the I-buffer (the RC's `clear`, or the
//! Color Shader's clear-behind) is enough. On a pass Z and I are written in this cycle. The triangle's visible flag is the OR of its
//! passes; its result enters the result queue at the end of the cycle of its last candidate's
//! z-test. The end-of-frame result is pushed after every earlier write has been performed.

use crate::format::{Plane, Screen, WinVertex, DEPTH_MAX, INDEX_BACKGROUND, WINDOW_BITS, WINDOW_MAX, WINDOW_MIN};
use crate::raster::{setup, Culled, CullMode, FrontFace, RcType, Setup};

/// The setup pipeline's stages (docs/rc.md, "Setup"): `Det` determinant and bounding box; `Order`
/// culling, canonical order, the edges' operands and the reciprocal's request; `Edges` edge start
/// values and depth numerators; three `Hold` stages that keep records while their reciprocals run;
/// `Grad` the depth gradients (takes the reciprocal); `Plane` the depth plane's start value.
pub const SETUP_STAGES: usize = 8;
/// The stage that takes the reciprocal's result, in its first cycle.
pub const GRAD_STAGE: usize = 6;
/// Cycles a drawn triangle spends in each stage when nothing waits (`Grad`: from the reciprocal's
/// arrival). Any other command spends one cycle in each.
pub const STAGE_CYCLES_DRAWN: [u8; SETUP_STAGES] = [1, 1, 4, 1, 1, 1, 4, 4];
/// Cycles from a request's acceptance to the reciprocal's result (pipelined: one request per clock;
/// thirteen stations of at most two division steps, `hdl::rc::fast_reciprocal`; ten stations of three
/// until issue 15 item 5). The third Hold stage keeps the longer latency from holding up culled
/// triangles behind a drawn one (docs/rc.md, "Setup").
pub const RECIP_LATENCY: usize = 13;
/// Records the queue between setup and traversal holds.
pub const RECORD_QUEUE: usize = 4;
/// Results the result queue holds (four: with two tokens in flight, results leave at one per clock
/// with `res_ready` high).
pub const RESULT_QUEUE: usize = 4;
/// Type III: the stages of the visibility test (F1 I-buffer word, F2 TdbV record, F3 regenerated
/// depth, F4 compare and write), and its result queue, deep enough for a result per clock with four
/// in flight.
pub const TDBV_STAGES: usize = 4;
pub const RESULT_QUEUE_III: usize = 6;
/// Cycles from accepting a command to its record being offered to the traversal when nothing waits:
/// a drawn triangle (the reciprocal, requested in S1's cycle, arrives in S6 RECIP_LATENCY cycles later;
/// then S6's four cycles and S7's four), and any other command (one cycle in each stage).
pub const SETUP_CYCLES_DRAWN: u64 = 2 + RECIP_LATENCY as u64 + STAGE_CYCLES_DRAWN[GRAD_STAGE] as u64 + STAGE_CYCLES_DRAWN[GRAD_STAGE + 1] as u64;
const _: () = assert!(
    2 + STAGE_CYCLES_DRAWN[2] as u64 + STAGE_CYCLES_DRAWN[3] as u64 + STAGE_CYCLES_DRAWN[4] as u64 + STAGE_CYCLES_DRAWN[5] as u64
        <= 2 + RECIP_LATENCY as u64,
    "the reciprocal arrives after the record reaches Grad"
);
pub const SETUP_CYCLES_SHORT: u64 = SETUP_STAGES as u64 + 1;
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
    /// Whether the command fits the port: x, y in S11.8 20 bits, z in 24 bits, index in 16 bits.
    pub fn check(&self) -> Result<(), String> {
        if self.index >= 1 << INDEX_BITS {
            return Err(format!("triangle index {} does not fit the RC's {INDEX_BITS}-bit index", self.index));
        }
        for (k, p) in self.v.iter().enumerate() {
            if p.x < WINDOW_MIN || p.x > WINDOW_MAX || p.y < WINDOW_MIN || p.y > WINDOW_MAX {
                return Err(format!(
                    "triangle {}: vertex {k} ({}, {}) subpixels is outside the {WINDOW_BITS}-bit S11.8 window format",
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
    /// Type III: the TdbV record (a depth plane) read one cycle after `tdbv_re`.
    pub tdbv_rd_data: Plane,
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
    /// Type III: TdbV's read port (the index read from the I-buffer) and write port (a walked
    /// triangle's depth plane at its index).
    pub tdbv_re: bool,
    pub tdbv_rd_addr: u32,
    pub tdbv_we: bool,
    pub tdbv_wr_addr: u32,
    pub tdbv_wr_data: Plane,
}

impl RcOutputs {
    /// The ports of the top of type `ty` as (name, value) pairs, in a fixed order: what benches
    /// compare and print. Type III's I-buffer read is `z_re`/`z_rd_addr` here, named `i_re`/`i_rd_addr`.
    pub fn ports(&self, ty: RcType) -> Vec<(&'static str, u64)> {
        let bits = |v: i64, n: u32| (v as u64) & ((1u64 << n) - 1);
        let mut p = vec![
            ("cmd_ready", self.cmd_ready as u64),
            ("res_valid", self.res_valid as u64),
            ("res.eof", self.res.eof as u64),
            ("res.index", self.res.index as u64),
            ("res.culled", self.res.culled as u64),
            ("res.zero_area", self.res.zero_area as u64),
            ("res.visible", self.res.visible as u64),
        ];
        match ty {
            RcType::IV => p.extend([
                ("z_re", self.z_re as u64),
                ("z_rd_addr", self.z_rd_addr as u64),
                ("z_we", self.z_we as u64),
                ("z_wr_addr", self.z_wr_addr as u64),
                ("z_wr_data", self.z_wr_data as u64),
            ]),
            RcType::III => p.extend([
                ("i_re", self.z_re as u64),
                ("i_rd_addr", self.z_rd_addr as u64),
                ("tdbv_re", self.tdbv_re as u64),
                ("tdbv_rd_addr", self.tdbv_rd_addr as u64),
                ("tdbv_we", self.tdbv_we as u64),
                ("tdbv_wr_addr", self.tdbv_wr_addr as u64),
                ("tdbv_wr_a", bits(self.tdbv_wr_data.a, 40)),
                ("tdbv_wr_b", bits(self.tdbv_wr_data.b, 40)),
                ("tdbv_wr_c", bits(self.tdbv_wr_data.c, 56)),
            ]),
        }
        p.extend([("i_we", self.i_we as u64), ("i_wr_addr", self.i_wr_addr as u64), ("i_wr_data", self.i_wr_data as u64)]);
        p
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

impl Record {
    fn walks(&self) -> bool {
        matches!(self, Record::Walk { .. })
    }
    /// Cycles this record spends in setup stage `k` when nothing waits.
    fn stage_cycles(&self, k: usize) -> u8 {
        if self.walks() {
            STAGE_CYCLES_DRAWN[k]
        } else {
            1
        }
    }
}

/// A record in a setup stage and the cycles it has spent there.
#[derive(Copy, Clone, Debug)]
struct Staged {
    rec: Record,
    phase: u8,
}

/// The setup pipeline's handshake in one cycle, found from the registers at the cycle's start.
#[derive(Copy, Clone, Debug, Default)]
struct SetupMoves {
    /// Stage k hands its record on (to stage k + 1, or the last stage to the record queue).
    leave: [bool; SETUP_STAGES],
    /// S6 (`Grad`) takes the reciprocal's result.
    recip_take: bool,
    /// The reciprocal pipeline advances (and accepts S1's request, if any).
    recip_advance: bool,
    /// The first stage accepts a command.
    cmd_ready: bool,
}

/// A token entering the z-test stage (Type III: the first of its four stages).
#[derive(Copy, Clone, Debug, PartialEq)]
enum Token {
    None,
    Clear { addr: u32 },
    Frag { inside: bool, last: bool, addr: u32, x: i32, y: i32, z: u32, index: u32 },
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
    /// The setup pipeline's stages S0..S7.
    stages: [Option<Staged>; SETUP_STAGES],
    /// The reciprocal pipeline: which of its stations hold a request (the last one: a result).
    recip: [bool; RECIP_LATENCY],
    /// The queue of set-up records, head first.
    queue: std::collections::VecDeque<Record>,
    // traversal
    tstate: TravState,
    walking: Option<(u32, Setup)>,
    ty: RcType,
    // z-test stage: Type IV F1 only; Type III F1 to F4
    vis_pipe: [Token; TDBV_STAGES],
    /// Type III: F2's token found its pixel owned (the I-buffer word was not the background), and the
    /// old depth regenerated from the TdbV record that F2 received, in F3 and then in F4.
    f2_owned: bool,
    f3_old: u32,
    f4_old: u32,
    /// The writes of the last cycles, newest first (address, depth): Type IV forwards the first, Type III
    /// all four (the writes its I-buffer read cannot have seen).
    hist: [Option<(u32, u32)>; TDBV_STAGES],
    vis: bool,
    // result queue, head first
    res: std::collections::VecDeque<RcResult>,
    /// Cycles stepped so far.
    pub cycle: u64,
    /// Cycles the traversal spent walking triangles, and those of them that issued a fragment.
    pub walk_clocks: u64,
    pub walk_fragment_clocks: u64,
    /// Hazard coverage: cycles the record queue was full, the result queue was full, and the
    /// reciprocal's result waited for S6.
    pub record_queue_full_cycles: u64,
    pub result_queue_full_cycles: u64,
    pub recip_stall_cycles: u64,
}

impl RcModel {
    /// The Type IV RC (Z-buffer).
    pub fn new(screen: Screen) -> RcModel {
        RcModel::of_type(screen, RcType::IV)
    }

    pub fn of_type(screen: Screen, ty: RcType) -> RcModel {
        RcModel {
            ty,
            screen,
            stages: [None; SETUP_STAGES],
            recip: [false; RECIP_LATENCY],
            queue: std::collections::VecDeque::new(),
            tstate: TravState::Idle,
            walking: None,
            vis_pipe: [Token::None; TDBV_STAGES],
            f2_owned: false,
            f3_old: DEPTH_MAX,
            f4_old: DEPTH_MAX,
            hist: [None; TDBV_STAGES],
            vis: false,
            res: std::collections::VecDeque::new(),
            cycle: 0,
            walk_clocks: 0,
            walk_fragment_clocks: 0,
            record_queue_full_cycles: 0,
            result_queue_full_cycles: 0,
            recip_stall_cycles: 0,
        }
    }

    pub fn screen(&self) -> Screen {
        self.screen
    }

    /// Whether nothing is in flight: no command in setup, the traversal idle, no result waiting.
    pub fn is_idle(&self) -> bool {
        self.stages.iter().all(Option::is_none)
            && !self.recip.iter().any(|&b| b)
            && self.queue.is_empty()
            && self.tstate == TravState::Idle
            && self.in_flight().iter().all(|t| *t == Token::None)
            && self.res.is_empty()
    }

    fn addr(&self, x: i32, y: i32) -> u32 {
        y as u32 * self.screen.width + x as u32
    }

    /// The record the setup unit offers this cycle, if ready.
    fn offered(&self) -> Option<Record> {
        self.queue.front().copied()
    }

    /// The setup pipeline's handshake this cycle: a stage hands its record on when it is done with it
    /// and the next stage is empty or hands its own on in the same cycle (the last stage: when the
    /// queue has room at the cycle's start); S1 hands a drawn triangle on only when the reciprocal
    /// pipeline accepts its request; the reciprocal pipeline advances unless its result waits for S6.
    fn setup_moves(&self) -> SetupMoves {
        let mut m = SetupMoves::default();
        let done = |k: usize| self.stages[k].is_some_and(|s| s.phase + 1 >= s.rec.stage_cycles(k));
        let recip_out = self.recip[RECIP_LATENCY - 1];
        m.recip_take = recip_out && self.stages[GRAD_STAGE].is_some_and(|s| s.rec.walks() && s.phase == 0);
        m.recip_advance = !recip_out || m.recip_take;
        let mut free_next = self.queue.len() < RECORD_QUEUE;
        for k in (0..SETUP_STAGES).rev() {
            let waits_for_recip = k == 1 && self.stages[1].is_some_and(|s| s.rec.walks()) && !m.recip_advance;
            m.leave[k] = done(k) && free_next && !waits_for_recip;
            free_next = self.stages[k].is_none() || m.leave[k];
        }
        m.cmd_ready = free_next;
        m
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
        let result_free = self.res.len() + self.in_flight().iter().filter(|t| t.pushes_result()).count() < self.result_queue();
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
                    (Some(fx), last) => (Token::Frag { inside: true, last, addr: self.addr(fx, y), x: fx, y, z: s.depth_at(fx, y), index }, take),
                    (None, true) => (Token::Frag { inside: false, last: true, addr: self.addr(x, y), x, y, z: 0, index }, take),
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

    /// The visibility test's stages holding tokens: Type IV's two (F0 reads, F1 decides), Type III's four.
    fn in_flight(&self) -> &[Token] {
        match self.ty {
            RcType::IV => &self.vis_pipe[..2],
            RcType::III => &self.vis_pipe[..],
        }
    }

    fn result_queue(&self) -> usize {
        match self.ty {
            RcType::IV => RESULT_QUEUE,
            RcType::III => RESULT_QUEUE_III,
        }
    }

    /// The stage that decides and writes: Type IV's F1, Type III's F4.
    fn deciding(&self) -> Token {
        *self.in_flight().last().expect("at least one stage")
    }

    /// The decision this cycle: (write, pass). The old depth is, newest first, that of a write the
    /// token's read cannot have seen (forwarding), else the memory's: Type IV the Z word (far where
    /// the I-buffer word read with it is the background), Type III the depth regenerated in F3.
    fn z_test(&self, z_rd_data: u32, i_rd_data: u32) -> (Option<(u32, u32, u32)>, bool) {
        // The writes the deciding token's read cannot have seen: Type IV's read went out one cycle
        // before the decision, Type III's four.
        let missed = match self.ty {
            RcType::IV => &self.hist[..1],
            RcType::III => &self.hist[..],
        };
        match self.deciding() {
            Token::Clear { addr } => (Some((addr, DEPTH_MAX, INDEX_BACKGROUND)), false),
            Token::Frag { inside: true, addr, z, index, .. } => {
                let old = match (missed.iter().flatten().find(|(a, _)| *a == addr), self.ty) {
                    (Some(&(_, d)), _) => d,
                    (None, RcType::III) => self.f4_old,
                    (None, RcType::IV) if i_rd_data == INDEX_BACKGROUND => DEPTH_MAX,
                    (None, RcType::IV) => z_rd_data,
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
        let moves = self.setup_moves();
        self.record_queue_full_cycles += (self.queue.len() == RECORD_QUEUE) as u64;
        self.result_queue_full_cycles += (self.res.len() == self.result_queue()) as u64;
        self.recip_stall_cycles += !moves.recip_advance as u64;
        let mut out = RcOutputs { cmd_ready: moves.cmd_ready, ..RcOutputs::default() };
        // Type III: F1 reads TdbV at the index the I-buffer returned (where it is not the background);
        // a walked triangle's depth plane is written into TdbV in the cycle its record is taken.
        let tdbv_read = match (self.ty, self.vis_pipe[0]) {
            (RcType::III, Token::Frag { inside: true, .. }) if inp.i_rd_data != INDEX_BACKGROUND => Some(inp.i_rd_data),
            _ => None,
        };
        if let Some(i) = tdbv_read {
            (out.tdbv_re, out.tdbv_rd_addr) = (true, i);
        }
        if let (RcType::III, true, Some(Record::Walk { index, setup })) = (self.ty, take, self.offered()) {
            (out.tdbv_we, out.tdbv_wr_addr, out.tdbv_wr_data) = (true, index, setup.depth);
        }
        if let Some(&r) = self.res.front() {
            out.res_valid = true;
            out.res = r;
        }
        // The read: Type IV's from F0 (the token issued in the previous cycle), Type III's I-buffer read
        // with the token issued now.
        let reading = match self.ty {
            RcType::IV => self.vis_pipe[0],
            RcType::III => tok,
        };
        if let Token::Frag { inside: true, addr, .. } = reading {
            out.z_re = true;
            out.z_rd_addr = addr;
        }
        if let Some((addr, z, i)) = write {
            if self.ty == RcType::IV {
                (out.z_we, out.z_wr_addr, out.z_wr_data) = (true, addr, z);
            }
            (out.i_we, out.i_wr_addr, out.i_wr_data) = (true, addr, i);
        }

        // ---- rising edge ----
        // Result queue: pop, then push from the z-test stage.
        if out.res_valid && inp.res_ready {
            self.res.pop_front();
        }
        match self.deciding() {
            Token::Result(r) => self.res.push_back(r),
            Token::Frag { last: true, index, .. } => {
                self.res.push_back(RcResult { index, visible: self.vis || pass, ..RcResult::default() });
                self.vis = false;
            }
            Token::Frag { .. } => self.vis |= pass,
            _ => {}
        }
        self.hist.rotate_right(1);
        self.hist[0] = write.map(|(a, z, _)| (a, z));
        if self.ty == RcType::III {
            // F2 -> F3: the old depth from the TdbV record that arrived now (F2's pixel was owned);
            // F3 -> F4: carried on.
            self.f4_old = self.f3_old;
            self.f3_old = match self.vis_pipe[1] {
                Token::Frag { inside: true, x, y, .. } if self.f2_owned => inp.tdbv_rd_data.eval_clamped(x as u32, y as u32, DEPTH_MAX as i64) as u32,
                _ => DEPTH_MAX,
            };
            self.f2_owned = tdbv_read.is_some();
        }
        self.vis_pipe.rotate_right(1);
        self.vis_pipe[0] = tok;

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

        // The record queue: the traversal takes the head; the last setup stage appends.
        if take {
            self.queue.pop_front();
        }
        if moves.leave[SETUP_STAGES - 1] {
            self.queue.push_back(self.stages[SETUP_STAGES - 1].expect("a leaving record").rec);
        }
        // The reciprocal pipeline: S1's request enters when it advances.
        if moves.recip_advance {
            self.recip.rotate_right(1);
            self.recip[0] = moves.leave[1] && self.stages[1].is_some_and(|s| s.rec.walks());
        }
        // The setup stages, last first: a record moves on, or spends another cycle (S6 waits in its
        // first cycle for the reciprocal).
        for k in (0..SETUP_STAGES).rev() {
            let Some(st) = self.stages[k] else { continue };
            if moves.leave[k] {
                self.stages[k] = None;
                if k + 1 < SETUP_STAGES {
                    self.stages[k + 1] = Some(Staged { rec: st.rec, phase: 0 });
                }
            } else if st.phase + 1 < st.rec.stage_cycles(k) && !(k == GRAD_STAGE && st.phase == 0 && !moves.recip_take) {
                self.stages[k] = Some(Staged { phase: st.phase + 1, ..st });
            }
        }
        // S1 accepts a command; the triangle's arithmetic is the algorithmic model's.
        if inp.cmd_valid && moves.cmd_ready {
            let c = inp.cmd;
            let rec = match c.kind {
                CmdKind::Frame => Record::Frame { clear: c.clear },
                CmdKind::EndOfFrame => Record::EndOfFrame,
                CmdKind::Triangle => match setup(&c.v, c.cull, c.front, self.screen) {
                    Err(culled) => Record::Skip { index: c.index, culled: Some(culled) },
                    Ok(s) if s.bbox.is_empty() => Record::Skip { index: c.index, culled: None },
                    Ok(s) => Record::Walk { index: c.index, setup: s },
                },
            };
            self.stages[0] = Some(Staged { rec, phase: 0 });
        }
        self.cycle += 1;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ONE: i32 = crate::format::SUBPIXEL_ONE;

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
            let inp = RcInputs { cmd_valid: valid, cmd: if valid { cmds[next] } else { RcCmd::idle() }, res_ready: true, z_rd_data: rd, i_rd_data: ird, tdbv_rd_data: Plane::default() };
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
        let t = RcCmd::triangle(7, [v(0, 0, 10), v(4 * ONE, 0, 10), v(0, 4 * ONE, 10)], CullMode::None, FrontFace::Ccw).unwrap();
        let (mut z, mut i) = (vec![DEPTH_MAX; 256], vec![0; 256]);
        let (res, _) = run(&mut m, &[t], &mut z, &mut i);
        // Accepted in cycle 0, record ready in cycle SETUP_CYCLES_DRAWN and taken there. The walk:
        // one clock per fragment (3 + 2 + 1), the last of a row ending the row because the window
        // reaches the box's edge, and one clock for the empty last row: 7 clocks. The last token in F0
        // one cycle later, its z-test in F1 the cycle after, the result in the result queue the cycle
        // after that.
        assert_eq!(res[0], (SETUP_CYCLES_DRAWN + 7 + 3, RcResult { index: 7, visible: true, ..Default::default() }));
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
            let span = [8, 40, 200, 1100][t % 4] * (ONE as i64 / 16);
            let (cx, cy) = (rnd(64 * ONE as i64), rnd(48 * ONE as i64));
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
        let t = RcCmd::triangle(7, [v(0, 0, 10), v(4 * ONE, 0, 10), v(0, 4 * ONE, 10)], CullMode::None, FrontFace::Ccw).unwrap();
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
        // Frame accepted in 0, offered to the traversal SETUP_CYCLES_SHORT cycles later, then one clear
        // token per pixel (32), then the end of frame's result through F0, F1 and the result queue.
        assert!(cycles >= 32 + SETUP_CYCLES_SHORT && cycles <= 32 + SETUP_CYCLES_SHORT + 5, "cycles {cycles}");
    }

    #[test]
    fn commands_outside_the_port_formats_are_rejected_with_the_reason() {
        let e = RcCmd::triangle(1, [v(600_000, 0, 0), v(0, 0, 0), v(0, 1, 0)], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("S11.8"), "{e}");
        let e = RcCmd::triangle(1, [v(0, 0, 1 << 24), v(0, 0, 0), v(0, 1, 0)], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("24 bits"), "{e}");
        let e = RcCmd::triangle(70000, [v(0, 0, 0); 3], CullMode::None, FrontFace::Ccw).unwrap_err();
        assert!(e.contains("16-bit index"), "{e}");
    }
}
