// Verilator harness of the generated `chipset` top (hdl/src/chipset.rs), or with TYPE_III defined of
// the `chipset3` top (hdl/src/chipset/chipset3.rs: TdbV instead of the Z-buffer), or with TEXTURED
// defined of the `chipset_tex` top (hdl/src/chipset/chipset_tex.rs: TdbT and four texture banks
// besides `chipset`'s ports), driven from Rust by tb/src/verilator/mod.rs (`VerilatorChipset`) over a
// pipe.
//
//   usage: Vchipset <width> <height> [vcd-file]      (Vchipset3 for Type III, Vchipset_tex textured)
//
// The harness owns the memories behind the top's ports and drives the top exactly as the RustHDL
// backend tb/src/chipset.rs (`RtlChipset`) does: the same phase loops, the same handshakes, the same
// memory model, the same cycle accounting, so that both backends give the same cycle counts.
//
// Memories (as `RtlChipset`): synchronous, latency 1, read-before-write. In each cycle the inputs are
// applied with the clock low and the top is evaluated (VCD time 10*cycle); the harness samples the
// handshakes, then the memories take their reads (old contents) and writes at the edge, then the clock
// rises (VCD time 10*cycle + 5). The read data reach the `*_rd_data` ports with the next low phase.
// Z-buffer: W*H words. I-buffer: two banks of W*H words (address bit 20 = bank). TdbS: two banks of
// 2^16 records (address bit 16 = bank). Contents after reset: Z word i = (i * 2654435761) & 0xffffff,
// I word j of both banks together = (j * 40503) & 0xffff (garbage with a fixed pattern, as in
// `RtlChipset`; the first frame in each bank clears it), TdbS all zero. TdbS records are 424 bits =
// 14 32-bit words (Verilator's VlWide<14>, word 0 holding bits 31:0). Type III's TdbV: 2^16 depth
// planes (A, B 40 bits, C 56 bits, signed), all C = -2^40 after reset (as `RtlChipset3`'s).
//
// Protocol. Rust -> harness on stdin: a text line, then for some commands a binary payload (32-bit
// little-endian words):
//   frame <n> <tdata> <phong> <c>\n + n RC command words of RC_WORDS x u32, then c Phong-constant
//                           writes of 6 x u32 (kind 0 = light, 1 = material; address; slot; 96 data
//                           bits): queue a frame (background tdata, Phong scan-out if set)
//   texture <w0_log2> <h0_log2> <levels> <filter> <clamp>\n + 1 word (bank words b), `levels` level
//                           bases, 4*b texel words (RGB888 as video_tdata, bank 0 first): the last
//                           queued frame is textured (TEXTURED only; `RtlChipsetTex`'s FrameTexture)
//   run <budget> <visible_bit> <seed> <gap> <stall>\n
//                           run the queued frames back to back (the host loop of `RtlChipset::run`,
//                           with its random gaps and stalls: `HostDrive`, xorshift64* from `seed`)
//   vcd_close\n             flush and close the VCD
//   quit\n                  exit
// During `run`, the harness asks for the host's lower pipeline: it writes `Q <frame> <position>\n` and
// reads back 1 + SETUP_WORDS words: a flag (1 = a command follows; 0 = the host failed, stop the run) and a
// colour-setup word of SETUP_WORDS words (TEXTURED: then the TEX_WORDS words of the texture values).
// Harness -> Rust on the protocol channel (the original stdout; the process's stdout is redirected to
// stderr so that nothing the model prints can corrupt the protocol):
//   P <done> <total> <phase>\n                        progress
//   Q <frame> <position>\n                            a visible triangle (see above)
//   E <message>\n                                     the run failed (message as RtlChipset's)
//   R <frame> <n> <bank>\n + n result words (u32, RcResult bits) + W*H I words of the drawn bank + W*H
//                                                     Z words (Type III: 2^16 TdbV planes of 6 words,
//                                                     A, B, C each as 64 bits, low word first): the
//                                                     frame's end-of-frame result
//   O <frame> <n>\n + n video_tdata words (u32)       the frame's scan-out ended
//   F <frame> <11 cycle stamps, -1 for none>           start first_tri_taken last_cmd_taken eof
//     <10 port counts>\n                              clear_writes z_reads setup_first drawn
//                                                     scan_begin scan_taken scan_done, then the words
//                                                     on each memory port (tb::chipset::PortTraffic's
//                                                     order: Z r/w, I r/w, TdbV r/w, TdbS w, scan I
//                                                     r/w, TdbS r; TEXTURED adds `tb::chipset::
//                                                     TexTraffic`'s 5: TdbT r/w, bank words,
//                                                     footprints, covered scan reads)
//   D <cycle>\n                                       the run is done
//   V\n                                               VCD closed
// `budget` is the number of cycles after which the run is an error (a hang, not an endless loop).

#if defined(TYPE_III)
#include "Vchipset3.h"
using Top = Vchipset3;
#elif defined(TEXTURED)
#include "Vchipset_tex.h"
using Top = Vchipset_tex;
#else
#include "Vchipset.h"
using Top = Vchipset;
#endif
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace {

// RC_WORDS (the RC command), SETUP_WORDS (the colour-setup command) and TEX_WORDS (the texture
// values): 32-bit words of the packed ports, from the structs' widths (`tb::verilator` defines them).
#if !defined(RC_WORDS) || !defined(SETUP_WORDS) || !defined(TEX_WORDS)
#error "RC_WORDS, SETUP_WORDS and TEX_WORDS are defined by tb::verilator's build flags"
#endif
constexpr int TDBS_WORDS = 14;   // 424-bit TdbS record
constexpr size_t CONFIG_WORDS = 6;  // one Phong-constant write
constexpr uint64_t PROGRESS_EVERY = 1 << 16;
using Record = std::array<uint32_t, TDBS_WORDS>;
constexpr int TDBT_WORDS = 13;   // 408-bit TdbT record
using TexRecord = std::array<uint32_t, TDBT_WORDS>;
// tb::chipset::TexTraffic's fields.
enum TexCount { TT_RD, TT_WR, BANK_WORDS, FOOTPRINTS, COVERED, TEX_COUNTS };
// A frame's texture as the host loads it (tb::chipset::FrameTexture).
struct Texture {
    uint32_t w0_log2 = 0, h0_log2 = 0, last_level = 0, filter = 0, clamp = 0;
    std::vector<uint32_t> bases;
    std::array<std::vector<uint32_t>, 4> banks;
};
// tb::chipset::PortTraffic's fields.
enum Port { Z_RD, Z_WR, I_RD, I_WR, TDBV_RD, TDBV_WR, TDBS_WR, SCAN_I_RD, SCAN_I_WR, TDBS_RD, PORTS };
// A TdbV record: the depth plane.
struct Plane {
    int64_t a = 0, b = 0, c = 0;
};
uint64_t mask(int64_t v, int bits) { return uint64_t(v) & ((uint64_t(1) << bits) - 1); }
int64_t sign_extend(uint64_t v, int bits) { return int64_t(v << (64 - bits)) >> (64 - bits); }

FILE* proto_out = nullptr;

struct Failure {
    std::string message;
};

class Bench {
  public:
    Bench(uint32_t w, uint32_t h, const char* vcd) : width(w), height(h), n(size_t(w) * h), vcd_name(vcd ? vcd : "") {
        ctx.reset(new VerilatedContext);
#if VM_TRACE
        if (vcd) ctx->traceEverOn(true);
#endif
        top.reset(new Top{ctx.get(), "uut"});
#ifdef TYPE_III
        tdbv.assign(1 << 16, Plane{0, 0, -(int64_t(1) << 40)});
#endif
        zbuf.resize(n);
        ibuf.resize(2 * n);
        for (size_t i = 0; i < n; i++) zbuf[i] = (uint32_t(i) * 2654435761u) & 0xffffffu;
        for (size_t i = 0; i < 2 * n; i++) ibuf[i] = (uint32_t(i) * 40503u) & 0xffffu;
        tdbs.assign(2 << 16, Record{});
        t_rd.fill(0);
#ifdef TEXTURED
        tdbt.assign(2 << 16, TexRecord{});
        tt_rd.fill(0);
#endif
#if VM_TRACE
        if (vcd) {
            tfp.reset(new VerilatedVcdC);
            top->trace(tfp.get(), 1);
            tfp->open(vcd);
            if (!tfp->isOpen()) {
                fprintf(stderr, "cannot open VCD %s\n", vcd);
                exit(2);
            }
        }
#else
        if (vcd) {
            fprintf(stderr, "this harness was built without --trace\n");
            exit(2);
        }
#endif
    }

    ~Bench() { close_vcd(); top->final(); }

    // Per frame of a run: the result words so far.
    std::vector<std::vector<uint32_t>> results_of;
    uint32_t visible_bit = 0;

    void close_vcd() {
#if VM_TRACE
        if (tfp) {
            tfp->close();
            tfp.reset();
        }
#endif
    }

    struct Frame {
        std::vector<uint32_t> words;   // RC commands, RC_WORDS each
        std::vector<uint32_t> config;  // Phong-constant writes, CONFIG_WORDS each
        uint32_t background = 0;
        bool phong = false;
        size_t results = 0;
        long long start = -1, first_tri_taken = -1, last_cmd_taken = 0, eof = -1, clear_writes = 0, z_reads = 0,
                  setup_first = -1, drawn = -1, scan_begin = -1, scan_taken = -1, scan_done = -1;
        long long traffic[PORTS] = {};
        std::shared_ptr<Texture> tex;
        long long tex_traffic[TEX_COUNTS] = {};
        size_t config_writes() const { return config.size() / CONFIG_WORDS + (tex ? tex->bases.size() : 0); }
    };
    std::vector<Frame> frames;

    // The host loop of RtlChipset::run (tb/src/chipset.rs), line by line.
    void run(uint64_t budget);
    // HostDrive: random gaps before commands and stalls on what the host takes (percent), and the
    // xorshift64* state of tb::common::Rng.
    uint64_t rng = 1, gap = 0, stall = 0;
    uint64_t next_random() {
        uint64_t x = rng;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        rng = x;
        return x * 0x2545F4914F6CDD1Dull;
    }
    bool chance(uint64_t percent) { return next_random() % 100 < percent; }

  private:
    const uint32_t width, height;
    const size_t n;
    const std::string vcd_name;
    std::unique_ptr<VerilatedContext> ctx;
    std::unique_ptr<Top> top;
#if VM_TRACE
    std::unique_ptr<VerilatedVcdC> tfp;
#endif
    std::vector<uint32_t> zbuf, ibuf;
    std::vector<Plane> tdbv;
    Plane tdbv_rd;
    // Words on each port in this cycle (high() counts them, run() gives them to their frames).
    long long counts[PORTS] = {};
    std::vector<Record> tdbs;
    uint32_t z_rd = 0, id_rd = 0, is_rd = 0;
    Record t_rd;
    std::vector<TexRecord> tdbt;
    TexRecord tt_rd{};
    // The texture in the four banks (loaded when a textured frame's scan-out begins) and what they
    // return (latency 1); the texture ports' words in this cycle.
    std::shared_ptr<Texture> banks;
    uint32_t tex_rd[4] = {};
    long long tcounts[TEX_COUNTS] = {};
    uint64_t cycle = 0;

    void dump(uint64_t t) {
#if VM_TRACE
        if (tfp) tfp->dump(t);
#else
        (void)t;
#endif
    }

    void idle_inputs() {
        top->rc_cmd__024valid = 0;
        top->rc_result__024ready = 1;
        top->setup_cmd__024valid = 0;
        top->scan_start = 0;
        top->video_tready = 1;
        // Phong-constant writes: none, and payloads 0 (as RtlChipset drives them).
        top->light_write_enable = 0;
        top->light_write_address = 0;
        top->material_write_enable = 0;
        top->material_write_address = 0;
        top->material_write_slot = 0;
        for (int k = 0; k < 3; k++) top->light_write_data[k] = top->material_write_data[k] = 0;
#ifdef TEXTURED
        top->tex_base_we = 0;
#endif
    }

    void drive_config(const uint32_t* c) {
        if (c[0] == 0) {
            top->light_write_enable = 1;
            top->light_write_address = c[1];
            for (int k = 0; k < 3; k++) top->light_write_data[k] = c[3 + k];
        } else {
            top->material_write_enable = 1;
            top->material_write_address = c[1];
            top->material_write_slot = c[2];
            for (int k = 0; k < 3; k++) top->material_write_data[k] = c[3 + k];
        }
    }

    // The RC's own memory: Type IV's Z-buffer, or Type III's TdbV.
    bool rc_memory_active() const {
#ifdef TYPE_III
        return top->tdbv_re || top->tdbv_we;
#else
        return top->z_re || top->z_we;
#endif
    }

    void low() {
#ifdef TYPE_III
        top->tdbv_rd_a = mask(tdbv_rd.a, 40);
        top->tdbv_rd_b = mask(tdbv_rd.b, 40);
        top->tdbv_rd_c = mask(tdbv_rd.c, 56);
#else
        top->z_rd_data = z_rd;
#endif
        top->id_rd_data = id_rd;
        top->is_rd_data = is_rd;
        for (int k = 0; k < TDBS_WORDS; k++) top->t_rd_data[k] = t_rd[k];
#ifdef TEXTURED
        for (int k = 0; k < TDBT_WORDS; k++) top->tt_rd_data[k] = tt_rd[k];
        top->tex_data0 = tex_rd[0];
        top->tex_data1 = tex_rd[1];
        top->tex_data2 = tex_rd[2];
        top->tex_data3 = tex_rd[3];
#endif
        top->clock = 0;
        top->eval();
        dump(cycle * 10);
    }

    [[noreturn]] void bad(const char* what, size_t a) {
        char m[240];
        snprintf(m, sizeof m, "chipset: %s address %#zx outside the buffer (W*H = %zu words per bank) in cycle %llu", what, a,
                 n, (unsigned long long)cycle);
        throw Failure{m};
    }

    // I-buffer address: bit 20 the bank, bits 19:0 the pixel.
    size_t ia(const char* what, size_t a) {
        if ((a & 0xfffff) >= n) bad(what, a);
        return (a >> 20) * n + (a & 0xfffff);
    }

    void high() {
        // Reads see the contents before this edge's writes.
        for (long long& c : counts) c = 0;
#ifdef TYPE_III
        if (top->tdbv_re) {
            tdbv_rd = tdbv[top->tdbv_rd_addr & 0xffff];
            counts[TDBV_RD]++;
        }
        if (top->tdbv_we) {
            tdbv[top->tdbv_wr_addr & 0xffff] =
                Plane{sign_extend(top->tdbv_wr_a, 40), sign_extend(top->tdbv_wr_b, 40), sign_extend(top->tdbv_wr_c, 56)};
            counts[TDBV_WR]++;
        }
#else
        if (top->z_re) {
            size_t a = top->z_rd_addr;
            if (a >= n) bad("Z read", a);
            z_rd = zbuf[a];
            counts[Z_RD]++;
        }
#endif
        if (top->id_re) {
            id_rd = ibuf[ia("I read (draw side)", top->id_rd_addr)];
            counts[I_RD]++;
        }
        if (top->is_re) {
            is_rd = ibuf[ia("I read (scan side)", top->is_rd_addr)];
            counts[SCAN_I_RD]++;
        }
        if (top->t_re) {
            t_rd = tdbs[top->t_rd_addr & 0x1ffff];
            counts[TDBS_RD]++;
        }
#ifndef TYPE_III
        if (top->z_we) {
            size_t a = top->z_wr_addr;
            if (a >= n) bad("Z write", a);
            zbuf[a] = top->z_wr_data;
            counts[Z_WR]++;
        }
#endif
        const bool dw = top->id_we, sw = top->is_we;
        const size_t da = top->id_wr_addr, sa = top->is_wr_addr;
        if (dw && sw && da == sa) {
            throw Failure{"chipset: both I-buffer write ports write address " + std::to_string(da) + " in cycle " +
                          std::to_string(cycle)};
        }
        if (dw) {
            ibuf[ia("I write (draw side)", da)] = top->id_wr_data;
            counts[I_WR]++;
        }
        if (sw) {
            ibuf[ia("I write (scan side)", sa)] = top->is_wr_data;
            counts[SCAN_I_WR]++;
        }
        if (top->t_we) {
            Record& r = tdbs[top->t_wr_addr & 0x1ffff];
            for (int k = 0; k < TDBS_WORDS; k++) r[k] = top->t_wr_data[k];
            counts[TDBS_WR]++;
        }
#ifdef TEXTURED
        for (long long& c : tcounts) c = 0;
        tcounts[COVERED] = (top->is_re && is_rd != 0) ? 1 : 0;  // INDEX_BACKGROUND is 0
        if (top->tt_re) {
            tt_rd = tdbt[top->tt_rd_addr & 0x1ffff];
            tcounts[TT_RD]++;
        }
        if (top->tt_we) {
            TexRecord& r = tdbt[top->tt_wr_addr & 0x1ffff];
            for (int k = 0; k < TDBT_WORDS; k++) r[k] = top->tt_wr_data[k];
            tcounts[TT_WR]++;
        }
        const uint32_t rd = top->tex_rd;
        if (rd) {
            if (!banks) throw Failure{"chipset: a texture read in cycle " + std::to_string(cycle) + " with no texture loaded"};
            const uint32_t addr[4] = {top->tex_addr0, top->tex_addr1, top->tex_addr2, top->tex_addr3};
            for (int k = 0; k < 4; k++) {
                if (!(rd >> k & 1)) continue;
                const std::vector<uint32_t>& b = banks->banks[k];
                if (addr[k] >= b.size()) {
                    throw Failure{"chipset: texture bank " + std::to_string(k) + " read at " + std::to_string(addr[k]) +
                                  ", outside its " + std::to_string(b.size()) + " words, in cycle " + std::to_string(cycle)};
                }
                tex_rd[k] = b[addr[k]];
                tcounts[BANK_WORDS]++;
            }
            tcounts[FOOTPRINTS]++;
        }
#endif
        top->clock = 1;
        top->eval();
        dump(cycle * 10 + 5);
        cycle++;
    }
};

void progress(const char* phase, uint64_t done, uint64_t total) {
    fprintf(proto_out, "P %llu %llu %s\n", (unsigned long long)done, (unsigned long long)total, phase);
    fflush(proto_out);
}

void put_words(const uint32_t* w, size_t count) {
    // The protocol is little-endian; so is every host Verilator targets here (checked in main).
    if (count && fwrite(w, 4, count, proto_out) != count) exit(3);
}

bool read_words(std::vector<uint32_t>& v, size_t count);

enum class Scan { Wait, Config, Start, Running };

void Bench::run(uint64_t budget) {
    const size_t nf = frames.size(), w = width, h = height;
    size_t rc_f = 0, rc_next = 0, res_f = 0, draw_f = 0, scan_f = 0, config_k = 0, pixels = 0;
    struct Queued {
        size_t frame;
        std::array<uint32_t, SETUP_WORDS> word;
        std::array<uint32_t, TEX_WORDS> tex;
    };
    std::deque<Queued> queue;
    std::vector<uint32_t> tdata, answer;
    tdata.reserve(w * h);
    Scan scan = Scan::Wait;
    const uint64_t start = cycle, limit = cycle + budget;
    bool rc_presenting = false, setup_presenting = false;
    // The watchdog of RtlChipset::run: no activity at the ports for longer than any triangle needs.
    const uint64_t watchdog = uint64_t(n) + 1024;
    uint64_t last_activity = cycle;
    while (scan_f < nf) {
        idle_inputs();
        // Random gaps and stalls, drawn in RtlChipset::run's order.
        const bool rc_can = rc_f < nf && rc_next < frames[rc_f].words.size() / RC_WORDS &&
                            (rc_f == 0 || frames[rc_f - 1].scan_taken >= 0);
        if (rc_can && !rc_presenting) rc_presenting = !(gap > 0 && chance(gap));
        if (!queue.empty() && !setup_presenting) setup_presenting = !(gap > 0 && chance(gap));
        const bool res_ready = !(stall > 0 && chance(stall));
        const bool video_ready = !(stall > 0 && chance(stall));
        top->rc_result__024ready = res_ready;
        top->video_tready = video_ready;
        // Upper pipeline: frame rc_f's commands, once the previous frame's scan-out has started.
        const bool rc_offer = rc_can && rc_presenting;
        if (rc_offer) {
            top->rc_cmd__024valid = 1;
            for (int k = 0; k < RC_WORDS; k++) top->rc_cmd__024data[k] = frames[rc_f].words[rc_next * RC_WORDS + k];
            if (frames[rc_f].start < 0) frames[rc_f].start = (long long)cycle;
        }
        // Lower pipeline: the queued colour-setup commands.
        const bool setup_offer = !queue.empty() && setup_presenting;
        if (setup_offer) {
            top->setup_cmd__024valid = 1;
            for (int k = 0; k < SETUP_WORDS; k++) top->setup_cmd__024data[k] = queue.front().word[k];
#ifdef TEXTURED
            for (int k = 0; k < TEX_WORDS; k++) top->setup_tex[k] = queue.front().tex[k];
#endif
            if (frames[queue.front().frame].setup_first < 0) frames[queue.front().frame].setup_first = (long long)cycle;
        }
        // Scan-out of frame scan_f.
        if (scan == Scan::Wait && frames[scan_f].drawn >= 0 && (scan_f == 0 || frames[scan_f - 1].scan_done >= 0)) {
            frames[scan_f].scan_begin = (long long)cycle;
            config_k = 0;
            scan = frames[scan_f].config_writes() == 0 ? Scan::Start : Scan::Config;
            // No scan runs: the host loads the frame's texture into the banks.
            if (frames[scan_f].tex) banks = frames[scan_f].tex;
        }
        Frame& sf = frames[scan_f];
        top->scan_background = sf.background;
        top->scan_clear_behind = 1;
        top->scan_phong = sf.phong;
        const size_t phong_writes = sf.config.size() / CONFIG_WORDS;
        if (scan == Scan::Config && config_k < phong_writes) drive_config(&sf.config[config_k * CONFIG_WORDS]);
#ifdef TEXTURED
        top->scan_texture = sf.tex ? 1 : 0;
        if (sf.tex) {
            top->tex_w0_log2 = sf.tex->w0_log2;
            top->tex_h0_log2 = sf.tex->h0_log2;
            top->tex_last_level = sf.tex->last_level;
            top->tex_filter = sf.tex->filter;
            top->tex_clamp = sf.tex->clamp;
            if (scan == Scan::Config && config_k >= phong_writes) {
                top->tex_base_we = 1;
                top->tex_base_sel = uint32_t(config_k - phong_writes);
                top->tex_base_data = sf.tex->bases[config_k - phong_writes];
            }
        }
#endif
        if (scan == Scan::Start) top->scan_start = 1;
        low();
        const bool rc_taken = rc_offer && top->rc_cmd__024ready;
        const bool setup_taken = setup_offer && top->setup_cmd__024ready;
        const bool setup_busy = top->setup_busy || top->t_we;
        const bool start_taken = scan == Scan::Start && !top->scan_busy;
        const bool scan_busy = top->scan_busy;
        if (res_f < nf) {
            frames[res_f].z_reads += top->id_re ? 1 : 0;
            frames[res_f].clear_writes += (top->id_we && top->id_wr_data == 0) ? 1 : 0;
        }
        const bool result = top->rc_result__024valid && res_ready;
        const uint32_t r = top->rc_result__024data;
        bool beat = false;
        uint32_t word = 0;
        if (top->video_tvalid && video_ready) {
            const size_t x = pixels % w, y = pixels / w;
            if (bool(top->video_tuser) != (pixels == 0)) {
                throw Failure{std::string("chipset: tuser is ") + (top->video_tuser ? "true" : "false") + " on pixel (" +
                              std::to_string(x) + "," + std::to_string(y) + ")"};
            }
            if (bool(top->video_tlast) != (x == w - 1)) {
                throw Failure{std::string("chipset: tlast is ") + (top->video_tlast ? "true" : "false") + " on pixel (" +
                              std::to_string(x) + "," + std::to_string(y) + ")"};
            }
            beat = true;
            word = top->video_tdata;
        }
        const size_t draw_bank = top->draw_bank;
        const bool active = rc_taken || setup_taken || start_taken || (top->rc_result__024valid && res_ready) ||
                            (top->video_tvalid && video_ready) || rc_memory_active() || top->id_re || top->id_we || top->is_we ||
                            top->t_we || scan == Scan::Config;
        // The host answers a visible result at once (its command is offered from the next cycle).
        bool eof = false;
        if (result) {
            if (res_f >= nf) throw Failure{"chipset: a result after the last frame's end of frame in cycle " + std::to_string(cycle)};
            if (r & 1) {  // RcResult.eof is bit 0 (hdl/src/rc/mod.rs)
                eof = true;
            } else {
                Frame& fr = frames[res_f];
                results_of[res_f].push_back(r);
                fr.results++;
                if (r & visible_bit) {
                    fprintf(proto_out, "Q %zu %zu\n", res_f, fr.results - 1);
                    fflush(proto_out);
#ifdef TEXTURED
                    const size_t answer_words = 1 + SETUP_WORDS + TEX_WORDS;
#else
                    const size_t answer_words = 1 + SETUP_WORDS;
#endif
                    if (!read_words(answer, answer_words)) exit(4);
                    if (answer[0] != 1) throw Failure{"host: the lower pipeline failed"};
                    Queued q{res_f, {}, {}};
                    for (int k = 0; k < SETUP_WORDS; k++) q.word[k] = answer[1 + k];
                    for (size_t k = 0; k + 1 + SETUP_WORDS < answer_words; k++) q.tex[k] = answer[1 + SETUP_WORDS + k];
                    queue.push_back(q);
                }
            }
        }
        high();
        // The draw side's words go to the frame being drawn (the RC's to res_f, colour setup's to
        // draw_f), the scan side's to scan_f (as RtlChipset::run).
        if (res_f < nf) {
            for (Port p : {Z_RD, Z_WR, I_RD, I_WR, TDBV_RD, TDBV_WR}) frames[res_f].traffic[p] += counts[p];
        }
        if (draw_f < nf) frames[draw_f].traffic[TDBS_WR] += counts[TDBS_WR];
        for (Port p : {SCAN_I_RD, SCAN_I_WR, TDBS_RD}) frames[scan_f].traffic[p] += counts[p];
        if (draw_f < nf) frames[draw_f].tex_traffic[TT_WR] += tcounts[TT_WR];
        for (TexCount c : {TT_RD, BANK_WORDS, FOOTPRINTS, COVERED}) frames[scan_f].tex_traffic[c] += tcounts[c];
        const long long now = (long long)cycle;
        if (rc_taken) {
            rc_presenting = false;
            Frame& fr = frames[rc_f];
            if (rc_next == 1) fr.first_tri_taken = now - 1;
            fr.last_cmd_taken = now;
            rc_next++;
            if (rc_next == fr.words.size() / RC_WORDS) {
                rc_f++;
                rc_next = 0;
            }
        }
        if (setup_taken) {
            queue.pop_front();
            setup_presenting = false;
        }
        if (eof) {
            Frame& fr = frames[res_f];
            fr.eof = now;
            std::vector<uint32_t>& res = results_of[res_f];
            fprintf(proto_out, "R %zu %zu %zu\n", res_f, res.size(), draw_bank);
            put_words(res.data(), res.size());
            put_words(ibuf.data() + draw_bank * n, n);
#ifdef TYPE_III
            std::vector<uint32_t> planes;
            planes.reserve(6 * tdbv.size());
            for (const Plane& p : tdbv) {
                for (int64_t v : {p.a, p.b, p.c}) {
                    planes.push_back(uint32_t(uint64_t(v)));
                    planes.push_back(uint32_t(uint64_t(v) >> 32));
                }
            }
            put_words(planes.data(), planes.size());
#else
            put_words(zbuf.data(), n);
#endif
            fflush(proto_out);
            res_f++;
        }
        if (draw_f < nf && frames[draw_f].eof >= 0 && queue.empty() && !setup_taken && !setup_busy) {
            frames[draw_f].drawn = now;
            draw_f++;
        }
        if (scan == Scan::Config) {
            config_k++;
            if (config_k == frames[scan_f].config_writes()) scan = Scan::Start;
        } else if (scan == Scan::Start && start_taken) {
            frames[scan_f].scan_taken = now - 1;
            scan = Scan::Running;
        }
        if (beat) {
            if (scan != Scan::Running || pixels == w * h) {
                throw Failure{"chipset: a pixel no scan-out asked for in cycle " + std::to_string(now - 1)};
            }
            tdata.push_back(word);
            pixels++;
            if (pixels % PROGRESS_EVERY == 0) progress("scan-out", pixels, w * h);
        }
        if (scan == Scan::Running && pixels == w * h && !scan_busy) {
            frames[scan_f].scan_done = now;
            fprintf(proto_out, "O %zu %zu\n", scan_f, tdata.size());
            put_words(tdata.data(), tdata.size());
            fflush(proto_out);
            tdata.clear();
            scan = Scan::Wait;
            pixels = 0;
            scan_f++;
        }
        if (cycle % PROGRESS_EVERY == 0 && res_f < nf) {
            const Frame& fr = frames[res_f];
            progress(fr.first_tri_taken < 0 ? "clear" : "rasterization", fr.results, fr.words.size() / RC_WORDS - 2);
        }
        if (active) last_activity = cycle;
        if (cycle - last_activity > watchdog) {
            const std::string phase = res_f < nf ? "frame " + std::to_string(res_f + 1) + "'s rasterization"
                                                 : "frame " + std::to_string(scan_f + 1) + "'s scan-out";
            const std::string wave = vcd_name.empty() ? "run again with a VCD (render --vcd) to see why"
                                                      : "the waveform is " + vcd_name;
            throw Failure{"chipset: no progress for " + std::to_string(watchdog) + " cycles in " + phase + ", at cycle " +
                          std::to_string(cycle) + ": no command or result taken, no memory access, no pixel; " + wave};
        }
        if (cycle > limit) {
            throw Failure{"chipset: " + std::to_string(nf) + " frames not done after " + std::to_string(cycle - start) +
                          " cycles (" + std::to_string(res_f) + " drawn by the RC, " + std::to_string(scan_f) +
                          " scanned out)"};
        }
    }
    for (size_t f = 0; f < nf; f++) {
        const Frame& fr = frames[f];
        fprintf(proto_out, "F %zu %lld %lld %lld %lld %lld %lld %lld %lld %lld %lld %lld", f, fr.start, fr.first_tri_taken,
                fr.last_cmd_taken, fr.eof, fr.clear_writes, fr.z_reads, fr.setup_first, fr.drawn, fr.scan_begin,
                fr.scan_taken, fr.scan_done);
        for (long long t : fr.traffic) fprintf(proto_out, " %lld", t);
#ifdef TEXTURED
        for (long long t : fr.tex_traffic) fprintf(proto_out, " %lld", t);
#endif
        fprintf(proto_out, "\n");
    }
    fprintf(proto_out, "D %llu\n", (unsigned long long)cycle);
    fflush(proto_out);
}

bool read_words(std::vector<uint32_t>& v, size_t count) {
    v.resize(count);
    return count == 0 || fread(v.data(), 4, count, stdin) == count;
}

}  // namespace

int main(int argc, char** argv) {
    // The protocol goes to the original stdout; anything the model prints goes to stderr.
    int proto_fd = dup(1);
    if (proto_fd < 0 || dup2(2, 1) < 0) return 2;
    proto_out = fdopen(proto_fd, "wb");
    if (!proto_out) return 2;
    const uint32_t one = 1;
    if (*reinterpret_cast<const uint8_t*>(&one) != 1) {
        fprintf(stderr, "big-endian host: the pipe protocol is little-endian\n");
        return 2;
    }
    if (argc < 3) {
        fprintf(stderr, "usage: %s <width> <height> [vcd-file]\n", argv[0]);
        return 2;
    }
    const long w = atol(argv[1]), h = atol(argv[2]);
    if (w < 1 || w > 1024 || h < 1 || h > 1024) {
        fprintf(stderr, "screen %ldx%ld outside 1..=1024\n", w, h);
        return 2;
    }
    Bench bench(uint32_t(w), uint32_t(h), argc > 3 ? argv[3] : nullptr);
    fprintf(proto_out, "READY\n");
    fflush(proto_out);
    char line[256];
    std::vector<uint32_t> words;
    while (fgets(line, sizeof line, stdin)) {
        char cmd[32] = {0};
        unsigned long long a = 0, b = 0, c = 0, d = 0, e = 0;
        const int got = sscanf(line, "%31s %llu %llu %llu %llu %llu", cmd, &a, &b, &c, &d, &e);
        try {
            if (got == 5 && !strcmp(cmd, "frame")) {
                Bench::Frame f;
                if (!read_words(f.words, size_t(a) * RC_WORDS)) return 4;
                if (!read_words(f.config, size_t(d) * CONFIG_WORDS)) return 4;
                f.background = uint32_t(b);
                f.phong = c != 0;
                bench.frames.push_back(std::move(f));
            } else if (got == 6 && !strcmp(cmd, "texture")) {
                if (bench.frames.empty()) throw Failure{"harness: a texture before any frame"};
                std::vector<uint32_t> size;
                if (!read_words(size, 1)) return 4;
                auto t = std::make_shared<Texture>();
                t->w0_log2 = uint32_t(a);
                t->h0_log2 = uint32_t(b);
                t->last_level = uint32_t(c) - 1;
                t->filter = uint32_t(d);
                t->clamp = uint32_t(e);
                if (!read_words(t->bases, size_t(c))) return 4;
                for (auto& bank : t->banks) {
                    if (!read_words(bank, size[0])) return 4;
                }
                bench.frames.back().tex = t;
            } else if (got == 6 && !strcmp(cmd, "run")) {
                bench.visible_bit = uint32_t(b);
                bench.rng = c ? c : 1;
                bench.gap = d;
                bench.stall = e;
                bench.results_of.assign(bench.frames.size(), {});
                try {
                    bench.run(a);
                } catch (...) {
                    bench.frames.clear();
                    throw;
                }
                bench.frames.clear();
            } else if (got == 1 && !strcmp(cmd, "vcd_close")) {
                bench.close_vcd();
                fprintf(proto_out, "V\n");
                fflush(proto_out);
            } else if (got == 1 && !strcmp(cmd, "quit")) {
                break;
            } else {
                fprintf(proto_out, "E harness: unknown command line '%s'\n", strtok(line, "\n"));
                fflush(proto_out);
            }
        } catch (const Failure& f) {
            fprintf(proto_out, "E %s\n", f.message.c_str());
            fflush(proto_out);
        }
    }
    return 0;
}
