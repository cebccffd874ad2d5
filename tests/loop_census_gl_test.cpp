// The loop census on a real context (gl/compute_program.cpp under Context::set_loop_census):
// a pass whose loop runs a known number of times per invocation, counted, against that number —
// the mean per invocation, and each wave's most (a work group of 8×8 is one wave64, or two
// wave32 of four rows each).
#include <catch2/catch.hpp>

#include <algorithm>

#include "gl/compute_program.h"
#include "gl_test_context.h"

TEST_CASE("the loop census counts each invocation's loop runs, per wave64 and wave32") {
  const pn::Context& context = pn::test::gl_context();
  pn::FlatSource flat;
  flat.text =
      "#line 1 0\n"
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "void main() {\n"
      "  uvec2 p = gl_GlobalInvocationID.xy;\n"
      "  for (uint i = 0u; i < (p.x + 3u * p.y) % 7u; ++i) { }\n"
      "}\n";
  flat.files = {"census.comp"};
  flat.has_main = true;
  pn::LoopCensus census;
  context.set_loop_census(&census);
  {
    const pn::ComputeProgram program(context, "census.comp", pn::standalone_source(flat, pn::driver_target(context)));
    program.dispatch(24, 16);
  }
  context.set_loop_census(nullptr);
  REQUIRE(census.records.size() == 1);
  const pn::LoopCensusRecord& r = census.records.front();
  CHECK(r.pass == "census.comp");
  REQUIRE(r.loops.size() == 1);
  CHECK(r.loops[0].line == 4);
  CHECK(r.groups[0] == 3);
  CHECK(r.groups[1] == 2);
  const auto runs = [](int x, int y) { return static_cast<std::uint32_t>((x + 3 * y) % 7); };
  double sum = 0.0;
  std::vector<std::uint32_t> most64(6, 0), most32(12, 0);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x) {
      sum += runs(x, y);
      const int group = (y / 8) * 3 + x / 8;
      most64[static_cast<std::size_t>(group)] = std::max(most64[static_cast<std::size_t>(group)], runs(x, y));
      const std::size_t half = static_cast<std::size_t>(group * 2 + (y % 8) / 4);
      most32[half] = std::max(most32[half], runs(x, y));
    }
  CHECK(r.mean[0] == Approx(sum / (24.0 * 16.0)).epsilon(1e-12));
  CHECK(r.of_wave(64).most == most64);
  CHECK(r.of_wave(32).most == most32);
}
