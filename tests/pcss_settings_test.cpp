// Which PCSS settings an engine can run as one call (pcss_settings.h one_call),
// and which of them the runner runs that way by default.
#include <catch2/catch.hpp>

#include "pipeline/pcss_settings.h"

namespace {

pn::PcssSettings with(pn::PcssSettings s, const char* key, const char* value) {
  pn::set_pcss_setting(s, key, value);
  return s;
}

}  // namespace

TEST_CASE("one call: the shipped techniques have one, the ablations that need neighbours or the pyramid do not") {
  using pn::OneCall;
  CHECK(pn::one_call(pn::fast_pcss()) == OneCall::fast);
  CHECK(pn::one_call(pn::poisson_pcss()) == OneCall::poisson);
  CHECK(pn::one_call(pn::exact_pcss()) == OneCall::exact);
  CHECK(pn::one_call(pn::hqepcss()) == OneCall::hqepcss);
  CHECK(pn::one_call(pn::fast_pcss_all_off()) == OneCall::fast);
  for (const char* key : {"leaf", "refine"}) CHECK(pn::one_call(with(pn::fast_pcss(), key, "1")) == OneCall::fast);
  CHECK(pn::one_call(with(pn::fast_pcss(), "region", "window")) == OneCall::fast);
  CHECK(pn::one_call(with(pn::fast_pcss(), "depth-sums", "table")) == OneCall::fast);
  // Neighbours (reuse, blur), the pyramid under Fast PCSS, a refined Poisson search: staged only.
  CHECK_FALSE(pn::one_call(pn::fast_paper_pcss()));
  CHECK_FALSE(pn::one_call(with(pn::fast_pcss(), "reuse", "on")));
  CHECK_FALSE(pn::one_call(with(pn::fast_pcss(), "blur", "on")));
  CHECK_FALSE(pn::one_call(with(pn::fast_pcss(), "structure", "pyramid")));
  CHECK_FALSE(pn::one_call(with(pn::poisson_pcss(), "refine", "3")));
  CHECK_FALSE(pn::one_call(with(pn::hqepcss(), "leaf-mode", "sampled")));
}

TEST_CASE("one call: fast and poisson run it by default, exact and hqepcss run staged (llvmpipe's loop cap)") {
  CHECK_FALSE(pn::fast_pcss().staged);
  CHECK_FALSE(pn::poisson_pcss().staged);
  CHECK(pn::exact_pcss().staged);
  CHECK(pn::hqepcss().staged);
  CHECK(with(pn::fast_pcss(), "stages", "on").staged);
  CHECK_FALSE(with(pn::exact_pcss(), "stages", "off").staged);
  pn::PcssSettings bad = pn::fast_pcss();
  CHECK_THROWS_WITH(pn::set_pcss_setting(bad, "stages", "maybe"), Catch::Contains("stages=maybe") && Catch::Contains("on or off"));
}

TEST_CASE("one call: the Vogel disk runs only as its call, with up to 128 samples") {
  CHECK(pn::one_call(pn::vogel_pcss()) == pn::OneCall::vogel);
  CHECK_FALSE(pn::vogel_pcss().staged);
  pn::vogel_pcss().validate();
  with(with(pn::vogel_pcss(), "blocker-samples", "128"), "filter-samples", "128").validate();
  CHECK_THROWS_WITH(with(pn::vogel_pcss(), "filter-samples", "129").validate(),
                    Catch::Contains("filter samples 129: expected 1..128"));
  CHECK_THROWS_WITH(with(pn::poisson_pcss(), "filter-samples", "65").validate(),
                    Catch::Contains("filter samples 65: expected 1..64"));
  for (const auto& [key, value] : {std::pair{"stages", "on"}, {"refine", "2"}, {"occlusion", "poisson"}, {"blur", "on"}})
    CHECK_THROWS_WITH(with(pn::vogel_pcss(), key, value).validate(), Catch::Contains("only as its one call"));
}

TEST_CASE("receiver plane: on, off or a tangent for every one call; refused for the staged passes and when negative") {
  CHECK(with(pn::vogel_pcss(), "receiver-plane", "on").receiver_plane_tan == pn::kReceiverPlaneTan);
  CHECK(with(pn::vogel_pcss(), "receiver-plane", "2.5").receiver_plane_tan == 2.5f);
  CHECK(with(with(pn::vogel_pcss(), "receiver-plane", "on"), "receiver-plane", "off").receiver_plane_tan == 0.0f);
  with(pn::vogel_pcss(), "receiver-plane", "on").validate();
  CHECK_THROWS_WITH(with(pn::vogel_pcss(), "receiver-plane", "-1").validate(),
                    Catch::Contains("receiver-plane=-1: expected off, on or a finite tangent >= 0"));
  with(pn::fast_pcss(), "receiver-plane", "on").validate();
  with(with(pn::exact_pcss(), "stages", "off"), "receiver-plane", "on").validate();
  const char* refused = "which take no receiver plane: add receiver-plane=off";
  with(pn::poisson_pcss(), "receiver-plane", "on").validate();
  with(with(pn::hqepcss(), "stages", "off"), "receiver-plane", "on").validate();
  CHECK_THROWS_WITH(with(pn::hqepcss(), "receiver-plane", "on").validate(), Catch::Contains(refused));  // staged
  CHECK_THROWS_WITH(with(with(pn::fast_pcss(), "stages", "on"), "receiver-plane", "on").validate(),
                    Catch::Contains(refused));
  CHECK_THROWS_WITH(with(pn::fast_paper_pcss(), "receiver-plane", "on").validate(), Catch::Contains(refused));
  // `fast` carries the plane (tan 1); its staged passes need it off, and say so.
  CHECK(pn::shipped_fast_pcss().receiver_plane_tan == 1.0f);
  pn::shipped_fast_pcss().validate();
  CHECK_THROWS_WITH(with(pn::shipped_fast_pcss(), "stages", "on").validate(),
                    Catch::Contains("stages=on runs the staged passes, which take no receiver plane"));
  // Issue 54 X13: what asked for the staged passes is named, not the plane nobody gave.
  CHECK_THROWS_WITH(with(pn::shipped_fast_pcss(), "blur", "on").validate(),
                    Catch::Contains("'fast': blur=on needs the staged passes"));
  CHECK_THROWS_WITH(with(pn::shipped_fast_pcss(), "reuse", "on").validate(),
                    Catch::Contains("reuse needs the staged passes"));
  with(with(pn::shipped_fast_pcss(), "stages", "on"), "receiver-plane", "off").validate();
}

TEST_CASE("grid: 0 (off) or 1..PN_GRID_MAX_CELLS over the mip chain; refused elsewhere") {
  CHECK(with(pn::fast_pcss(), "grid", "4").grid == 4);
  with(pn::fast_pcss(), "grid", "4").validate();
  with(pn::fast_pcss(), "grid", std::to_string(PN_GRID_MAX_CELLS).c_str()).validate();
  CHECK_THROWS_WITH(with(pn::fast_pcss(), "grid", std::to_string(PN_GRID_MAX_CELLS + 1).c_str()).validate(),
                    Catch::Contains("grid 17: expected 0 (off) or 1..16"));
  CHECK_THROWS_WITH(with(pn::fast_pcss(), "grid", "-1").validate(), Catch::Contains("grid -1: expected"));
  CHECK_THROWS_WITH(with(pn::fast_paper_pcss(), "grid", "4").validate(), Catch::Contains("grid: expected structure=mip"));
}
