// Formal harness of the `chipset_tex` top (the textured chipset: the RC, textured setup and cs_tex
// around the memory ports, RustHDL source hdl/src/chipset/chipset_tex.rs and back_tex.rs) built for
// a 4x3 screen (`idxrender verilog --size 4x3 --block chipset_tex`). Run by `bash scripts/formal.sh
// chipset_tex`; see docs/verification.md. The blocks' own properties are checked by rc.sv,
// rc_z_test.sv, colour_setup.sv, tex_setup's and cs_tex.sv; this harness checks what the chipset
// adds, as chipset.sv does (the host protocol, bank-swap assertions and reach points of
// chipset_bank_swap.vh), and the same of TdbT, whose banks swap with TdbS's.
//
// Assumed besides chipset.sv's: level-table writes only while the CS is idle; the texture's settings
// those the host can give (filter 0-2, sizes to 1024, the last level at most the larger size's log2);
// TdbT's and the texture banks' read data arbitrary. Asserted besides: every TdbT write (texture
// setup) is in bank `draw_bank`, every TdbT read (the CS) in the other bank. Reach point 4: texture
// setup writing TdbT bank 1. Reach point 5: the CS reading TdbT (frame 15). Reach point 6: the CS
// reading TdbT bank 1 (after a second swap, frame 55: beyond the bmc depth of 36, so the bmc checks
// the read assertion on bank-0 reads only).
module chipset_tex_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire [213:0] rc_cmd_data,
    input wire rc_cmd_valid,
    input wire rc_result_ready,
    input wire [320:0] setup_cmd_data,
    input wire setup_cmd_valid,
    input wire [296:0] setup_tex,
    input wire scan_start,
    input wire [23:0] scan_background,
    input wire scan_clear_behind,
    input wire scan_phong,
    input wire light_write_enable,
    input wire [1:0] light_write_address,
    input wire [95:0] light_write_data,
    input wire material_write_enable,
    input wire [3:0] material_write_address,
    input wire [2:0] material_write_slot,
    input wire [95:0] material_write_data,
    input wire video_tready,
    input wire [23:0] z_rd_data,
    input wire [15:0] id_rd_data,
    input wire [15:0] is_rd_data,
    input wire [423:0] t_rd_data,
    input wire [407:0] tt_rd_data,
    input wire scan_texture,
    input wire [3:0] tex_w0_log2,
    input wire [3:0] tex_h0_log2,
    input wire [3:0] tex_last_level,
    input wire [1:0] tex_filter,
    input wire tex_clamp,
    input wire tex_base_we,
    input wire [3:0] tex_base_sel,
    input wire [19:0] tex_base_data,
    input wire [23:0] tex_data0,
    input wire [23:0] tex_data1,
    input wire [23:0] tex_data2,
    input wire [23:0] tex_data3
);
    wire rc_cmd_ready, rc_result_valid, setup_cmd_ready, setup_busy, scan_busy;
    wire [19:0] rc_result_data;
    wire [23:0] video_tdata;
    wire video_tvalid, video_tuser, video_tlast;
    wire z_re, z_we, id_re, id_we, is_re, is_we, t_re, t_we, draw_bank;
    wire [19:0] z_rd_addr, z_wr_addr;
    wire [23:0] z_wr_data;
    wire [20:0] id_rd_addr, id_wr_addr, is_rd_addr, is_wr_addr;
    wire [15:0] id_wr_data, is_wr_data;
    wire [16:0] t_rd_addr, t_wr_addr;
    wire [423:0] t_wr_data;
    wire tt_re, tt_we;
    wire [16:0] tt_rd_addr, tt_wr_addr;
    wire [407:0] tt_wr_data;
    wire [3:0] tex_rd;
    wire [19:0] tex_addr0, tex_addr1, tex_addr2, tex_addr3;
    chipset_tex dut (
        .clock(clock),
        .rc_cmd$data(rc_cmd_data), .rc_cmd$valid(rc_cmd_valid), .rc_cmd$ready(rc_cmd_ready),
        .rc_result$data(rc_result_data), .rc_result$valid(rc_result_valid), .rc_result$ready(rc_result_ready),
        .setup_cmd$data(setup_cmd_data), .setup_cmd$valid(setup_cmd_valid), .setup_cmd$ready(setup_cmd_ready),
        .setup_tex(setup_tex), .setup_busy(setup_busy), .scan_start(scan_start), .scan_background(scan_background),
        .scan_clear_behind(scan_clear_behind), .scan_phong(scan_phong),
        .light_write_enable(light_write_enable), .light_write_address(light_write_address),
        .light_write_data(light_write_data), .material_write_enable(material_write_enable),
        .material_write_address(material_write_address), .material_write_slot(material_write_slot),
        .material_write_data(material_write_data), .scan_busy(scan_busy),
        .video_tdata(video_tdata), .video_tvalid(video_tvalid), .video_tready(video_tready),
        .video_tuser(video_tuser), .video_tlast(video_tlast),
        .z_re(z_re), .z_rd_addr(z_rd_addr), .z_rd_data(z_rd_data),
        .z_we(z_we), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data),
        .id_re(id_re), .id_rd_addr(id_rd_addr), .id_rd_data(id_rd_data),
        .id_we(id_we), .id_wr_addr(id_wr_addr), .id_wr_data(id_wr_data),
        .is_re(is_re), .is_rd_addr(is_rd_addr), .is_rd_data(is_rd_data),
        .is_we(is_we), .is_wr_addr(is_wr_addr), .is_wr_data(is_wr_data),
        .t_re(t_re), .t_rd_addr(t_rd_addr), .t_rd_data(t_rd_data),
        .t_we(t_we), .t_wr_addr(t_wr_addr), .t_wr_data(t_wr_data),
        .tt_re(tt_re), .tt_rd_addr(tt_rd_addr), .tt_rd_data(tt_rd_data),
        .tt_we(tt_we), .tt_wr_addr(tt_wr_addr), .tt_wr_data(tt_wr_data),
        .scan_texture(scan_texture), .tex_w0_log2(tex_w0_log2), .tex_h0_log2(tex_h0_log2),
        .tex_last_level(tex_last_level), .tex_filter(tex_filter), .tex_clamp(tex_clamp),
        .tex_base_we(tex_base_we), .tex_base_sel(tex_base_sel), .tex_base_data(tex_base_data),
        .tex_rd(tex_rd), .tex_addr0(tex_addr0), .tex_addr1(tex_addr1), .tex_addr2(tex_addr2),
        .tex_addr3(tex_addr3), .tex_data0(tex_data0), .tex_data1(tex_data1), .tex_data2(tex_data2),
        .tex_data3(tex_data3),
        .draw_bank(draw_bank)
    );

    `include "chipset_bank_swap.vh"

    // ---- The texture: the host's side, and TdbT's banks.
    always @(*) begin
        if (scan_busy || swap) assume (!tex_base_we);
        assume (tex_filter != 2'd3 && tex_w0_log2 <= 4'd10 && tex_h0_log2 <= 4'd10);
        assume (tex_last_level <= tex_w0_log2 || tex_last_level <= tex_h0_log2);
        if (tt_we) if (REACH < 0) assert (tt_wr_addr[16] == draw_bank);
        if (tt_re) if (REACH < 0) assert (tt_rd_addr[16] != draw_bank);
    end
    always @(posedge clock) if (past_valid) begin
        if ($past(setup_cmd_valid && !setup_cmd_ready)) assume (setup_tex == $past(setup_tex));
        cover (tt_we && draw_bank);
        if (REACH == 4 || REACH_SET[4]) reach_4: assert (!(tt_we && draw_bank));
        cover (tt_re);
        if (REACH == 5 || REACH_SET[5]) reach_5: assert (!tt_re);
        cover (tt_re && tt_rd_addr[16]);
        if (REACH == 6 || REACH_SET[6]) reach_6: assert (!(tt_re && tt_rd_addr[16]));
    end
endmodule
