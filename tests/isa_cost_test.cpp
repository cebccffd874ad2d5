// The GPU cost estimate's reading of an ISA (isa/isa_cost.h): issue cycles from the family and
// wave size, loops from the branches back, each census count's loop from its marker (a buffer
// load and store at offset 4 · (id + 1) with the add between, left out of the cost).
#include <catch2/catch.hpp>

#include "isa/isa_cost.h"

TEST_CASE("issue cycles follow the family and the wave size (GCN: a device without wave32)") {
  const pn::IssueModel rdna64 = pn::issue_model("navi21", 64, 32), rdna32 = pn::issue_model("navi21", 32, 32);
  const pn::IssueModel gcn = pn::issue_model("polaris10", 64, 64), gfx11 = pn::issue_model("gfx1100", 64, 32);
  CHECK(pn::issue_cycles("v_add_f32_e32", rdna64) == 2.0);   // two passes of a SIMD32
  CHECK(pn::issue_cycles("v_add_f32_e32", rdna32) == 1.0);
  CHECK(pn::issue_cycles("v_add_f32_e32", gcn) == 4.0);      // SIMD16
  CHECK(pn::issue_cycles("v_add_f32_e32", gfx11) == 1.0);    // dual issue
  CHECK(pn::issue_cycles("v_add_nc_u32_e32", gfx11) == 2.0);
  CHECK(pn::issue_cycles("v_rcp_f32_e32", rdna64) == 8.0);   // the transcendental unit, a quarter
  CHECK(pn::issue_cycles("v_mul_lo_u32", rdna32) == 4.0);
  CHECK(pn::issue_cycles("s_add_u32", rdna64) == 1.0);
  CHECK(pn::issue_cycles("s_waitcnt", rdna64) == 0.0);
  CHECK(pn::issue_cycles("s_branch", gcn) == 8.0);
  CHECK(pn::issue_cycles("image_load", rdna64) == 2.0);
  CHECK(pn::vector_memory_load("image_load_mip"));
  CHECK(pn::vector_memory_load("buffer_load_dword"));
  CHECK_FALSE(pn::vector_memory_load("image_store"));
  CHECK_FALSE(pn::vector_memory_load("s_buffer_load_dword"));
}

TEST_CASE("a census count finds its loop; its marker is not counted; an unrolled one is straight code") {
  const std::string isa =
      "BB0:\n"
      "\ts_mov_b32 s0, 0                                   ; be800380\n"
      "\tbuffer_load_dword v5, v4, s[16:19], 0 offen offset:8 ; e0301008 80040504\n"  // loop 1, unrolled
      "\tv_add_nc_u32_e32 v5, 1, v5                        ; 4a0a0a81\n"
      "\tbuffer_store_dword v5, v4, s[16:19], 0 offen offset:8 ; e0701008 80040504\n"
      "BB1:\n"
      "\tbuffer_load_dword v6, v4, s[16:19], 0 offen offset:4 ; e0301004 80040604\n"  // loop 0
      "\timage_load v7, v[2:3], s[8:15] dmask:0x1 dim:SQ_RSRC_IMG_2D unorm ; f0001108\n"
      "\tv_mul_f32_e32 v1, v1, v7                          ; 10020f01\n"
      "\tv_add_nc_u32_e32 v6, 1, v6                        ; 4a0c0c81\n"
      "\tbuffer_store_dword v6, v4, s[16:19], 0 offen offset:4 ; e0701004 80040604\n"
      "\ts_add_u32 s0, s0, 1                               ; 80008100\n"
      "\ts_cmp_lt_u32 s0, 8                                ; bf0a8800\n"
      "\ts_cbranch_scc1 BB1                                ; bf85fff7\n"
      "BB2:\n"
      "\tv_add_f32_e32 v1, v1, v1                          ; 06020301\n"
      "\ts_endpgm                                          ; bf810000\n";
  const pn::IsaCostModel m = pn::isa_cost_model(isa, 2, pn::issue_model("navi21", 64, 32));
  REQUIRE(m.loop_bodies.size() == 2);
  CHECK(m.in_loop == std::vector<bool>{true, false});
  // The body: image_load 2 + v_mul 2 + s_add 1 + s_cmp 1 + s_cbranch 1.
  CHECK(m.loop_bodies[0].cycles == 7.0);
  CHECK(m.loop_bodies[0].loads == 1.0);
  // Straight: s_mov 1 + v_add_f32 2 + s_endpgm 0 (the unrolled loop's marker left out).
  CHECK(m.straight.cycles == 3.0);
  CHECK(m.straight.loads == 0.0);
  CHECK(m.unmarked_loops == 0);
}

TEST_CASE("a loop the compiler unrolled twice inside its ISA loop costs half that loop a run") {
  const std::string isa =
      "BB1:\n"
      "\tbuffer_load_dword v6, v4, s[16:19], 0 offen offset:4\n"
      "\tv_add_nc_u32_e32 v6, 1, v6\n"
      "\tbuffer_store_dword v6, v4, s[16:19], 0 offen offset:4\n"
      "\tv_mul_f32_e32 v1, v1, v1\n"
      "\tbuffer_load_dword v6, v4, s[16:19], 0 offen offset:4\n"
      "\tv_add_nc_u32_e32 v6, 1, v6\n"
      "\tbuffer_store_dword v6, v4, s[16:19], 0 offen offset:4\n"
      "\tv_mul_f32_e32 v1, v1, v1\n"
      "\ts_cbranch_scc1 BB1\n"
      "BB2:\n"
      "\ts_endpgm\n";
  const pn::IsaCostModel m = pn::isa_cost_model(isa, 1, pn::issue_model("navi21", 32, 32));
  CHECK(m.in_loop == std::vector<bool>{true});
  CHECK(m.loop_bodies[0].cycles == 1.5);  // (two v_mul + the branch) / 2
}

TEST_CASE("isa_loops costs each loop's own body in program order, an inner loop apart from its outer one") {
  const std::string isa =
      "BB0:\n"
      "\ts_mov_b32 s0, 0                                   ; be800380\n"
      "BB1:\n"                                                                   // outer loop
      "\tv_mul_f32_e32 v1, v1, v1                          ; 10020301\n"
      "BB2:\n"                                                                   // inner loop
      "\timage_load v7, v[2:3], s[8:15] dmask:0x1 dim:SQ_RSRC_IMG_2D unorm ; f0001108\n"
      "\tv_rcp_f32_e32 v1, v7                              ; 7e025507\n"
      "\ts_cbranch_scc1 BB2                                ; bf85fffd\n"
      "\ts_add_u32 s0, s0, 1                               ; 80008100\n"
      "\ts_cbranch_scc0 BB1                                ; bf84fffa\n"
      "BB3:\n"
      "\tv_add_f32_e32 v1, v1, v1                          ; 06020301\n"
      "\ts_endpgm                                          ; bf810000\n";
  const std::vector<pn::IsaLoop> loops = pn::isa_loops(isa, pn::issue_model("navi21", 64, 32));
  REQUIRE(loops.size() == 2);
  // The outer body: v_mul 2 + s_add 1 + s_cbranch 1; the inner: image_load 2 + v_rcp 8 + s_cbranch 1.
  CHECK(loops[0].depth == 0);
  CHECK(loops[0].instructions == 3.0);
  CHECK(loops[0].cycles == 4.0);
  CHECK(loops[0].loads == 0.0);
  CHECK(loops[1].depth == 1);
  CHECK(loops[1].instructions == 3.0);
  CHECK(loops[1].cycles == 11.0);
  CHECK(loops[1].loads == 1.0);
  CHECK(pn::isa_loops("\tv_add_f32_e32 v1, v1, v1 ; 06020301\n", pn::issue_model("navi21", 64, 32)).empty());
}
