// Verilator harness of the generated `chipset` top (hdl/src/chipset.rs), driven from Rust by
// tb/src/verilator/mod.rs (`VerilatorChipset`) over a pipe.
//
//   usage: Vchipset <width> <height> [vcd-file]
//
// The harness owns the memories behind the top's ports and drives the top exactly as the RustHDL
// backend tb/src/chipset.rs (`RtlChipset`) does: the same phase loops, the same handshakes, the same
// memory model, the same cycle accounting, so that both backends give the same cycle counts.
//
// Memories (as `RtlChipset`): synchronous, latency 1, read-before-write. In each cycle the inputs are
// applied with the clock low and the top is evaluated (VCD time 10*cycle); the harness samples the
// handshakes, then the memories take their reads (old contents) and writes at the edge, then the clock
// rises (VCD time 10*cycle + 5). The read data reach the `*_rd_data` ports with the next low phase.
// Contents after reset: Z word i = (i * 2654435761) & 0xffffff, I word i = (i * 40503) & 0xffff
// (garbage with a fixed pattern, as in `RtlChipset`; the first frame's clear puts them in order),
// TdbS all zero. TdbS records are 424 bits = 14 32-bit words (Verilator's VlWide<14>, word 0 holding
// bits 31:0).
//
// Protocol. Rust -> harness on stdin: a text line, then for some commands a binary payload (32-bit
// little-endian words):
//   raster <n> <budget>\n   + n RC command words of 6 x u32 (190 bits): run the geometry phase
//   setup <n> <budget>\n    + n colour-setup words of 10 x u32 (297 bits): run colour setup
//   scan <tdata> <budget> <phong> <n>\n + n Phong-constant writes of 6 x u32 (kind 0 = light, 1 =
//                           material; address; slot; 96 data bits): write them one per cycle, then run
//                           the scan-out (background as video_tdata, clear behind on, Phong if set)
//   vcd_close\n             flush and close the VCD
//   quit\n                  exit
// Harness -> Rust on the protocol channel (the original stdout; the process's stdout is redirected to
// stderr so that nothing the model prints can corrupt the protocol):
//   P <done> <total> <phase>\n                        progress
//   E <message>\n                                     the command failed (message as RtlChipset's)
//   R <cycle> <clear_writes> <first_tri_taken|-1> <last_cmd_taken> <z_reads> <n>\n
//       + n result words (u32, RcResult bits) + W*H I-buffer words + W*H Z-buffer words (u32 each)
//   S <cycle>\n                                       colour setup done
//   O <cycle> <n>\n + n video_tdata words (u32)       scan-out done
//   V\n                                               VCD closed
// `budget` is the number of cycles after which the phase is an error (a hang, not an endless loop).

#include "Vchipset.h"
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
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr int RC_WORDS = 6;      // 190-bit RC command
constexpr int SETUP_WORDS = 10;  // 297-bit colour-setup command
constexpr int TDBS_WORDS = 14;   // 424-bit TdbS record
constexpr size_t CONFIG_WORDS = 6;  // one Phong-constant write
constexpr uint64_t PROGRESS_EVERY = 1 << 16;
using Record = std::array<uint32_t, TDBS_WORDS>;

FILE* proto_out = nullptr;

struct Failure {
    std::string message;
};

class Bench {
  public:
    Bench(uint32_t w, uint32_t h, const char* vcd) : width(w), height(h), n(size_t(w) * h) {
        ctx.reset(new VerilatedContext);
#if VM_TRACE
        if (vcd) ctx->traceEverOn(true);
#endif
        top.reset(new Vchipset{ctx.get(), "uut"});
        zbuf.resize(n);
        ibuf.resize(n);
        for (size_t i = 0; i < n; i++) {
            zbuf[i] = (uint32_t(i) * 2654435761u) & 0xffffffu;
            ibuf[i] = (uint32_t(i) * 40503u) & 0xffffu;
        }
        tdbs.assign(1 << 16, Record{});
        t_rd.fill(0);
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

    void close_vcd() {
#if VM_TRACE
        if (tfp) {
            tfp->close();
            tfp.reset();
        }
#endif
    }

    // One phase loop per command; each mirrors the same function of RtlChipset line by line.
    void rasterize(const std::vector<uint32_t>& words, uint64_t budget);
    void colour_setup(const std::vector<uint32_t>& words, uint64_t budget);
    void scanout(uint32_t background, uint64_t budget, bool phong, const std::vector<uint32_t>& config);

  private:
    const uint32_t width, height;
    const size_t n;
    std::unique_ptr<VerilatedContext> ctx;
    std::unique_ptr<Vchipset> top;
#if VM_TRACE
    std::unique_ptr<VerilatedVcdC> tfp;
#endif
    std::vector<uint32_t> zbuf, ibuf;
    std::vector<Record> tdbs;
    uint32_t z_rd = 0, i_rd = 0;
    Record t_rd;
    uint64_t cycle = 0;
    uint64_t clear_writes = 0;

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
    }

    void low() {
        top->z_rd_data = z_rd;
        top->i_rd_data = i_rd;
        for (int k = 0; k < TDBS_WORDS; k++) top->t_rd_data[k] = t_rd[k];
        top->clock = 0;
        top->eval();
        dump(cycle * 10);
    }

    [[noreturn]] void bad(const char* what, size_t a) {
        char m[200];
        snprintf(m, sizeof m, "chipset: %s address %zu outside the %zu-word buffer in cycle %llu", what, a, n,
                 (unsigned long long)cycle);
        throw Failure{m};
    }

    void high() {
        // Reads see the contents before this edge's writes.
        if (top->z_re) {
            size_t a = top->z_rd_addr;
            if (a >= n) bad("Z read", a);
            z_rd = zbuf[a];
        }
        if (top->i_re) {
            size_t a = top->i_rd_addr;
            if (a >= n) bad("I read", a);
            i_rd = ibuf[a];
        }
        if (top->t_re) t_rd = tdbs[top->t_rd_addr & 0xffff];
        if (top->z_we) {
            size_t a = top->z_wr_addr;
            if (a >= n) bad("Z write", a);
            zbuf[a] = top->z_wr_data;
        }
        if (top->i_we) {
            size_t a = top->i_wr_addr;
            if (a >= n) bad("I write", a);
            uint32_t d = top->i_wr_data;
            ibuf[a] = d;
            if (d == 0) clear_writes++;
        }
        if (top->t_we) {
            Record& r = tdbs[top->t_wr_addr & 0xffff];
            for (int k = 0; k < TDBS_WORDS; k++) r[k] = top->t_wr_data[k];
        }
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

void Bench::rasterize(const std::vector<uint32_t>& words, uint64_t budget) {
    const size_t count = words.size() / RC_WORDS;
    std::vector<uint32_t> results;
    size_t next = 0;
    const uint64_t start = cycle;
    clear_writes = 0;
    long long first_tri_taken = -1;
    uint64_t last_cmd_taken = start;
    uint64_t z_reads = 0;  // cycles with a Z read: the fragments the RC Z-tested (as RtlChipset counts them)
    const uint64_t limit = cycle + budget;
    for (;;) {
        idle_inputs();
        if (next < count) {
            top->rc_cmd__024valid = 1;
            for (int k = 0; k < RC_WORDS; k++) top->rc_cmd__024data[k] = words[next * RC_WORDS + k];
        }
        low();
        const bool taken = next < count && top->rc_cmd__024ready;
        z_reads += top->z_re ? 1 : 0;
        bool eof = false;
        if (top->rc_result__024valid) {
            const uint32_t r = top->rc_result__024data;
            if (r & 1) {  // RcResult.eof is bit 0 (hdl/src/rc/mod.rs)
                eof = true;
            } else {
                results.push_back(r);
            }
        }
        high();
        if (taken) {
            if (next == 1) first_tri_taken = (long long)(cycle - 1);
            next++;
            last_cmd_taken = cycle;
        }
        if (cycle % PROGRESS_EVERY == 0) {
            progress(first_tri_taken < 0 ? "clear" : "rasterization", results.size(), count > 2 ? count - 2 : 0);
        }
        if (eof) break;
        if (cycle > limit) {
            throw Failure{"chipset: no end-of-frame result after " + std::to_string(cycle - start) + " cycles"};
        }
    }
    fprintf(proto_out, "R %llu %llu %lld %llu %llu %zu\n", (unsigned long long)cycle, (unsigned long long)clear_writes,
            first_tri_taken, (unsigned long long)last_cmd_taken, (unsigned long long)z_reads, results.size());
    put_words(results.data(), results.size());
    put_words(ibuf.data(), n);
    put_words(zbuf.data(), n);
    fflush(proto_out);
}

void Bench::colour_setup(const std::vector<uint32_t>& words, uint64_t budget) {
    const size_t count = words.size() / SETUP_WORDS;
    const uint64_t start = cycle, limit = cycle + budget;
    size_t next = 0;
    for (;;) {
        idle_inputs();
        if (next < count) {
            top->setup_cmd__024valid = 1;
            for (int k = 0; k < SETUP_WORDS; k++) top->setup_cmd__024data[k] = words[next * SETUP_WORDS + k];
        }
        low();
        const bool taken = next < count && top->setup_cmd__024ready;
        const bool busy = top->setup_busy || top->t_we;
        high();
        if (taken) {
            next++;
            if (next % 256 == 0) progress("colour setup", next, count);
        }
        if (next == count && !taken && !busy) break;
        if (cycle > limit) {
            throw Failure{"chipset: colour setup did not finish in " + std::to_string(cycle - start) + " cycles"};
        }
    }
    fprintf(proto_out, "S %llu\n", (unsigned long long)cycle);
    fflush(proto_out);
}

void Bench::scanout(uint32_t background, uint64_t budget, bool phong, const std::vector<uint32_t>& config) {
    const size_t w = width, h = height;
    std::vector<uint32_t> tdata;
    tdata.reserve(w * h);
    const uint64_t start = cycle, limit = cycle + budget;
    // Phong constants first, one write per cycle, while the CS is idle (as RtlChipset).
    for (size_t i = 0; i + CONFIG_WORDS <= config.size(); i += CONFIG_WORDS) {
        idle_inputs();
        const uint32_t* c = &config[i];
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
        low();
        high();
    }
    bool started = false;
    size_t pixels = 0;
    for (;;) {
        idle_inputs();
        top->scan_background = background;
        top->scan_clear_behind = 1;
        top->scan_phong = phong;
        top->scan_start = !started;
        low();
        const bool start_taken = !started && !top->scan_busy;
        bool beat = false;
        uint32_t word = 0;
        if (top->video_tvalid) {
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
        const bool busy = top->scan_busy;
        high();
        started |= start_taken;
        if (beat) {
            if (pixels == w * h) throw Failure{"chipset: more pixels than the screen has"};
            tdata.push_back(word);
            pixels++;
            if (pixels % PROGRESS_EVERY == 0) progress("scan-out", pixels, w * h);
        }
        if (started && pixels == w * h && !busy) break;
        if (cycle > limit) {
            throw Failure{"chipset: scan-out produced " + std::to_string(pixels) + " of " + std::to_string(w * h) +
                          " pixels in " + std::to_string(cycle - start) + " cycles"};
        }
    }
    fprintf(proto_out, "O %llu %zu\n", (unsigned long long)cycle, tdata.size());
    put_words(tdata.data(), tdata.size());
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
        unsigned long long a = 0, b = 0, c = 0, d = 0;
        const int got = sscanf(line, "%31s %llu %llu %llu %llu", cmd, &a, &b, &c, &d);
        try {
            if (got == 3 && !strcmp(cmd, "raster")) {
                if (!read_words(words, size_t(a) * RC_WORDS)) return 4;
                bench.rasterize(words, b);
            } else if (got == 3 && !strcmp(cmd, "setup")) {
                if (!read_words(words, size_t(a) * SETUP_WORDS)) return 4;
                bench.colour_setup(words, b);
            } else if (got == 5 && !strcmp(cmd, "scan")) {
                if (!read_words(words, size_t(d) * CONFIG_WORDS)) return 4;
                bench.scanout(uint32_t(a), b, c != 0, words);
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
