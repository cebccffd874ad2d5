// The loop census's rewrite (shader/loop_census.h): every for, while and do-while body begins
// with its own count — a braced body after its `{`, any other statement wrapped in braces — a
// do-while's `while` is not a loop of its own, each loop's file and line, lines kept, and the
// result a valid shader for every target.
#include <catch2/catch.hpp>

#include <algorithm>

#include "module_source.h"
#include "shader/glslang_compiler.h"
#include "shader/loop_census.h"

namespace {

std::string between(const std::string& s, const std::string& from, const std::string& to) {
  const std::size_t a = s.find(from);
  return s.substr(a, s.find(to, a) - a);
}

}  // namespace

TEST_CASE("the loop census counts every loop body, braced or not, and records where each loop is") {
  const std::string body =
      "uint f(uint n) {\n"                                        // line 1
      "  uint s = 0u;\n"                                          // 2
      "  for (uint i = 0u; i < n; ++i) s += i;\n"                 // 3
      "  while (s > 7u) { s -= 3u; }\n"                           // 4
      "  do { s += 1u; } while ((s & 1u) == 0u);\n"               // 5
      "  for (uint k = 0u; k < 4u; k++)\n"                        // 6
      "    if (k > s) for (uint j = 0u; j < k; ++j) { s += j; } else s += 1u;\n"  // 7
      "  return s;\n"
      "}\n";
  pn::ShaderSource source = pn::test::module_source(body);
  const std::vector<pn::CensusLoop> loops = pn::census_preprocessed_loops(source, 5);
  CHECK(between(source.text, "#line 1 0\n", "\nvoid pnLoopCensus(uint loop) {") ==
        "#line 1 0\n"
        "uint f(uint n) {\n"
        "  uint s = 0u;\n"
        "  for (uint i = 0u; i < n; ++i) { pnLoopCensus(0u); s += i;}\n"
        "  while (s > 7u) { pnLoopCensus(1u);  s -= 3u; }\n"
        "  do { pnLoopCensus(2u);  s += 1u; } while ((s & 1u) == 0u);\n"
        "  for (uint k = 0u; k < 4u; k++)\n"
        "    { pnLoopCensus(3u); if (k > s) for (uint j = 0u; j < k; ++j) { pnLoopCensus(4u);  s += j; } else s += 1u;}\n"
        "  return s;\n"
        "}\n");
  CHECK(pn::test::loop_lines(loops) == std::vector<int>{3, 4, 5, 6, 7});
  CHECK(source.text.find("binding = 5") != std::string::npos);
  CHECK(source.text.find("slot * 6u + loop + 1u") != std::string::npos);  // 5 loops, entry 0 unused
}

TEST_CASE("a census'd compute shader compiles for gl450, vulkan and es310") {
  const std::string body =
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(std430, binding = 0) buffer Out { uint result; };\n"
      "void main() {\n"
      "  uint s = 0u;\n"
      "  for (uint i = 0u; i < gl_GlobalInvocationID.x; ++i) s += i;\n"
      "  do { s += 1u; } while (s < 4u);\n"
      "  result = s;\n"
      "}\n";
  const pn::GlslangProcess glslang;
  for (pn::Target target : {pn::Target::gl450, pn::Target::vulkan, pn::Target::es310}) {
    pn::ShaderSource source = pn::test::module_source(body, target);
    const std::vector<pn::CensusLoop> loops = pn::census_loops(glslang, source, target, 3);
    CHECK(loops.size() == 2);
    const pn::CompileResult r = pn::compile_with_glslang(glslang, source, target);
    INFO(pn::first_error(r, "no error") << "\n" << source.text);
    CHECK(r.ok);
  }
}
