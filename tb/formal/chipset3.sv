// Formal harness of the `chipset3` top (the Type III chipset: rc3 + colour setup + Color Shader,
// RustHDL source hdl/src/chipset/chipset3.rs and chipset/back.rs) built for a 4x3 screen (`idxrender
// verilog --size 4x3 --block chipset3`). Run by `bash scripts/formal.sh chipset3`; see
// docs/verification.md. The same properties as chipset.sv (the bank swap of the I-buffer and TdbS),
// with the Type III RC's TdbV port (one bank) in place of the Z-buffer: TdbV read data arbitrary.
//
// Assumed, the host's side of the protocol (chipset.rs): streams held while stalled; RC commands of
// kinds 0-2, triangle indices not 0; the host draws a frame (RC commands; colour-setup commands at any
// time), and after the RC's end-of-frame result sends no RC command until it has started the scan; it
// starts the scan only once the end-of-frame result has come, no colour-setup command is waiting and
// colour setup is idle; light and material writes only while the CS is idle. Memory read data are
// arbitrary. Asserted: `draw_bank` changes exactly at the edges where a scan start is taken; every
// draw-side access (the RC's I-buffer reads and writes, colour setup's TdbS writes) is in bank
// `draw_bank`, every scan-side access (the CS's I-buffer reads and clear-behind writes, its TdbS
// reads) in the other bank; the RC's result and the video beat held, with tuser and tlast, while
// stalled. Reach points: a bank swap; the RC writing bank 1 (after a swap); colour setup writing TdbS
// bank 1; the CS reading bank 0 after a swap.
module chipset3_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire [213:0] rc_cmd_data,
    input wire rc_cmd_valid,
    input wire rc_result_ready,
    input wire [320:0] setup_cmd_data,
    input wire setup_cmd_valid,
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
    input wire signed [39:0] tdbv_rd_a,
    input wire signed [39:0] tdbv_rd_b,
    input wire signed [55:0] tdbv_rd_c,
    input wire [15:0] id_rd_data,
    input wire [15:0] is_rd_data,
    input wire [423:0] t_rd_data
);
    wire rc_cmd_ready, rc_result_valid, setup_cmd_ready, setup_busy, scan_busy;
    wire [19:0] rc_result_data;
    wire [23:0] video_tdata;
    wire video_tvalid, video_tuser, video_tlast;
    wire tdbv_re, tdbv_we, id_re, id_we, is_re, is_we, t_re, t_we, draw_bank;
    wire [15:0] tdbv_rd_addr, tdbv_wr_addr;
    wire signed [39:0] tdbv_wr_a, tdbv_wr_b;
    wire signed [55:0] tdbv_wr_c;
    wire [20:0] id_rd_addr, id_wr_addr, is_rd_addr, is_wr_addr;
    wire [15:0] id_wr_data, is_wr_data;
    wire [16:0] t_rd_addr, t_wr_addr;
    wire [423:0] t_wr_data;
    chipset3 dut (
        .clock(clock),
        .rc_cmd$data(rc_cmd_data), .rc_cmd$valid(rc_cmd_valid), .rc_cmd$ready(rc_cmd_ready),
        .rc_result$data(rc_result_data), .rc_result$valid(rc_result_valid), .rc_result$ready(rc_result_ready),
        .setup_cmd$data(setup_cmd_data), .setup_cmd$valid(setup_cmd_valid), .setup_cmd$ready(setup_cmd_ready),
        .setup_busy(setup_busy), .scan_start(scan_start), .scan_background(scan_background),
        .scan_clear_behind(scan_clear_behind), .scan_phong(scan_phong),
        .light_write_enable(light_write_enable), .light_write_address(light_write_address),
        .light_write_data(light_write_data), .material_write_enable(material_write_enable),
        .material_write_address(material_write_address), .material_write_slot(material_write_slot),
        .material_write_data(material_write_data), .scan_busy(scan_busy),
        .video_tdata(video_tdata), .video_tvalid(video_tvalid), .video_tready(video_tready),
        .video_tuser(video_tuser), .video_tlast(video_tlast),
        .tdbv_re(tdbv_re), .tdbv_rd_addr(tdbv_rd_addr),
        .tdbv_rd_a(tdbv_rd_a), .tdbv_rd_b(tdbv_rd_b), .tdbv_rd_c(tdbv_rd_c),
        .tdbv_we(tdbv_we), .tdbv_wr_addr(tdbv_wr_addr),
        .tdbv_wr_a(tdbv_wr_a), .tdbv_wr_b(tdbv_wr_b), .tdbv_wr_c(tdbv_wr_c),
        .id_re(id_re), .id_rd_addr(id_rd_addr), .id_rd_data(id_rd_data),
        .id_we(id_we), .id_wr_addr(id_wr_addr), .id_wr_data(id_wr_data),
        .is_re(is_re), .is_rd_addr(is_rd_addr), .is_rd_data(is_rd_data),
        .is_we(is_we), .is_wr_addr(is_wr_addr), .is_wr_data(is_wr_data),
        .t_re(t_re), .t_rd_addr(t_rd_addr), .t_rd_data(t_rd_data),
        .t_we(t_we), .t_wr_addr(t_wr_addr), .t_wr_data(t_wr_data),
        .draw_bank(draw_bank)
    );

    `include "chipset_bank_swap.vh"
endmodule
