// The loop guard's rewrite (shader/loop_guard.h): every for/while condition
// prefixed, nothing else touched, each loop's file and line, and the result
// still a valid shader for every target glslang knows; the guard reads glslang's
// preprocessed text, so no spelling of a loop hides from it (issue 39), in GLSL
// and in an HLSL copy.
#include <catch2/catch.hpp>

#include <algorithm>

#include "core/error.h"
#include "module_source.h"
#include "shader/glslang_compiler.h"
#include "shader/loop_guard.h"

namespace {


// The text after the guard's prelude (the part the rewrite edits loop by loop).
std::string after_prelude(const pn::ShaderSource& s) { return s.text.substr(s.text.find("\n#line 1 0\n") + 1); }

}  // namespace

TEST_CASE("the loop guard prefixes every loop condition and records where each loop is") {
  const std::string body =
      "uint f(uint n) {\n"                                        // line 1
      "  uint s = 0u;\n"                                          // 2
      "  for (uint i = 0u; i < n; ++i) s += i;\n"                 // 3
      "  while (s > 7u) { s -= 3u; }\n"                           // 4
      "  do { s += 1u; } while ((s & 1u) == 0u);\n"               // 5
      "  for (;;) { if (s > 0u) break; }\n"                       // 6
      "  // while (comment) for (;;)\n"                           // 7
      "  /* for (uint j = 0u; j < 4u; ++j) */ uint whiley = 0u;\n"  // 8
      "  for (uint k = 0u; k < min(n, 4u); k++)\n"                // 9
      "    while (whiley < k) whiley++;\n"                        // 10
      "  return s + whiley;\n"
      "}\n";
  pn::ShaderSource source = pn::test::module_source(body);
  const std::vector<pn::GuardedLoop> loops = pn::guard_preprocessed_loops(source, {7, 1000}, pn::GuardSyntax::glsl);
  CHECK(after_prelude(source) ==
        "#line 1 0\n"
        "uint f(uint n) {\n"
        "  uint s = 0u;\n"
        "  for (uint i = 0u; pnLoopGuard(0u) && ( i < n); ++i) s += i;\n"
        "  while (pnLoopGuard(1u) && (s > 7u)) { s -= 3u; }\n"
        "  do { s += 1u; } while (pnLoopGuard(2u) && ((s & 1u) == 0u));\n"
        "  for (; pnLoopGuard(3u);) { if (s > 0u) break; }\n"
        "  // while (comment) for (;;)\n"
        "  /* for (uint j = 0u; j < 4u; ++j) */ uint whiley = 0u;\n"
        "  for (uint k = 0u; pnLoopGuard(4u) && ( k < min(n, 4u)); k++)\n"
        "    while (pnLoopGuard(5u) && (whiley < k)) whiley++;\n"
        "  return s + whiley;\n"
        "}\n");
  CHECK(pn::test::loop_lines(loops) == std::vector<int>{3, 4, 5, 6, 9, 10});
  CHECK(source.text.find("binding = 7") != std::string::npos);
  CHECK(source.text.find("1000u") != std::string::npos);
  // The rewrite adds no line: every line of the module keeps its number.
  const std::string guarded = after_prelude(source), plain = after_prelude(pn::test::module_source(body));
  CHECK(std::count(guarded.begin(), guarded.end(), '\n') == std::count(plain.begin(), plain.end(), '\n'));
  const auto at = static_cast<std::ptrdiff_t>(source.text.find("while (pnLoopGuard(1u)"));
  const int physical = static_cast<int>(std::count(source.text.begin(), source.text.begin() + at, '\n')) + 1;
  CHECK(source.origin_of_line(physical) == std::pair<std::string, int>{"m.glsl", 4});
}

TEST_CASE("a guarded shader compiles for gl450, vulkan and es310") {
  const std::string body =
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = 0) buffer Out { uint result; };\n"
      "void main() {\n"
      "  uint s = 0u;\n"
      "  for (uint i = 0u; i < 10u; ++i) { uint j = 0u; while (j < i) { s += j; j++; } }\n"
      "  do { s >>= 1u; } while (s > 100u);\n"
      "  result = s;\n"
      "}\n";
  const pn::GlslangProcess process;
  for (pn::Target target : pn::all_targets()) {
    pn::FlatSource flat;
    flat.text = "#line 1 0\n" + body;
    flat.files = {"m.comp"};
    flat.has_main = true;
    pn::ShaderSource source = pn::standalone_source(flat, target);
    CHECK(pn::guard_loops(process, source, target, {5, 1u << 22}).size() == 2);  // the while and the do; the for has a constant bound
    const pn::CompileResult compiled = pn::compile_with_glslang(process, source, target);
    INFO(pn::target_name(target) << ":\n" << source.text);
    for (const auto& d : compiled.diagnostics) INFO(d.str());
    CHECK(compiled.ok);
  }
}

TEST_CASE("only for loops bounded by construction stay unguarded") {
  const pn::GlslangProcess process;
  const auto guarded = [&](const std::string& loop) {
    pn::ShaderSource source = pn::test::module_source("#define PN_MAX_TAPS 16\n#define PN_TILE 8\nconst int PN_DISK[3] = int[](1, 2, 3);\n"
                                      "const int PN_FAR = 2000000000;\nint g;\nvoid bump(inout int x) { x = 0; }\n"
                                      "void add(inout int s, int x) { s += x; }\nvoid reset() { g = 0; }\n"
                                      "int f(int n) {\n  int s = 0;\n  " + loop + "\n  return s;\n}\n");
    return !pn::guard_loops(process, source, pn::Target::gl450, {0, 100}).empty();
  };
  // At most B - A iterations whatever the body computes:
  CHECK_FALSE(guarded("for (int i = 0; i < 8; ++i) s += i;"));
  CHECK_FALSE(guarded("for (int i = 0; i <= PN_MAX_TAPS; i++) { s += i * 2; }"));
  CHECK_FALSE(guarded("for (int i = 0; i < 2 * (PN_TILE - 1); i += 4) { s += min(i, 3); }"));
  CHECK_FALSE(guarded("for (int i = 0; i < PN_DISK.length(); ++i) s += i == 3 ? 1 : 0;"));
  CHECK_FALSE(guarded("for (int i = 0; i < 8; ++i) { add(s, i); }"));  // an in argument of a call with an inout one
  // Anything else may not end:
  CHECK(guarded("for (int i = 0; i < n; ++i) s += i;"));            // a bound known only at run time
  CHECK(guarded("for (int i = 0; i < 8; i += 0) s += i;"));         // a step that does not step
  CHECK(guarded("for (int i = 0; i < 8; i += PN_STEP) s += i;"));   // a step a copy may define as 0
  CHECK(guarded("for (int i = 0; i < 8; ++i) { i -= 1; }"));       // the body moves the counter back
  CHECK(guarded("for (int i = 0; i < 8; ++i) { --i; }"));
  CHECK(guarded("for (int i = 0; i < 8; ++i) { bump(i); }"));      // an inout argument
  CHECK(guarded("for (int i = 0; i < 8; ++i) { add(i, 1); }"));
  CHECK(guarded("for (int i = 0; i < 8; ++i) { float f = modf(1.5, i); }"));
  CHECK(guarded("for (int i = 0; i < 8; ++i) for (;;) s++;"));     // a nested loop as the body
  CHECK(guarded("for (int i = 0; i > -8; --i) s += i;"));
  CHECK(guarded("while (s < 8) s += 1;"));
  // Issue 26 B4: a bound past the guard's limit (here 100), literal or through macros, and a
  // counter written through a macro the body uses.
  CHECK_FALSE(guarded("for (int i = 0; i < 100; ++i) s += i;"));
  CHECK(guarded("for (int i = 0; i < 101; ++i) s += i;"));
  CHECK(guarded("for (int i = 0; i < 2000000000; ++i) s += i;"));
  CHECK_FALSE(guarded("for (int i = 50; i < 150; ++i) s += i;"));
  CHECK(guarded("\n#define PN_MANY (PN_HALF * 2)\n#define PN_HALF 60\n  for (int i = 0; i < PN_MANY; ++i) s += i;"));
  CHECK_FALSE(guarded("\n#define PN_FEW (PN_HALF / 2)\n#define PN_HALF 60\n  for (int i = 0; i < PN_FEW; ++i) s += i;"));
  CHECK(guarded("\n#define PN_RESET i = 0\n  for (int i = 0; i < 8; ++i) { PN_RESET; }"));
  CHECK(guarded("\n#define PN_SET(x) x = 0\n  for (int i = 0; i < 8; ++i) { PN_SET(i); }"));
  CHECK_FALSE(guarded("\n#define PN_TWO 2\n  for (int i = 0; i < 8; ++i) { s += PN_TWO; }"));
  // Issue 39: the bound is read after the preprocessor, so a named constant is no bound (it is not
  // folded there), nor is a counter the loop does not declare (a call may write it), nor a start
  // that is not a literal.
  CHECK(guarded("for (int i = 0; i < PN_FAR; ++i) s += i;"));
  CHECK(guarded("for (g = 0; g < 8; ++g) reset();"));
  CHECK(guarded("for (int i = n; i < 8; ++i) s += i;"));
  CHECK_FALSE(guarded("for (int i = -8; i < 8; ++i) s += i;"));
  CHECK(guarded("for (int i = -100; i < 8; ++i) s += i;"));  // 108 iterations: past the limit of 100
}

// The endless loop of issue 39 in each spelling the probe found passing `check blur`, as the
// flattener leaves it: every one is a plain loop in glslang's preprocessed text, guarded and
// named by the line of its keyword (or of the macro that spells it), and the result compiles.
TEST_CASE("every spelling of a loop is guarded: the guard reads the preprocessed text (issue 39)") {
  struct Spelling {
    const char* name;
    std::string body;  // from line 5 of m.glsl, after `float x = 0.0;`
    std::string loop;  // file:line of the loop's keyword, or of the macro that spells it
  };
  const std::vector<Spelling> spellings = {
      {"a line continuation", "  whi\\\nle (x > -1.0) { x += 1.0; }\n", "m.glsl:5"},
      {"a macro split by a continuation", "#define PN_REPEAT wh\\\nile\n  PN_REPEAT (x > -1.0) { x += 1.0; }\n", "m.glsl:7"},
      {"the keyword from an included header", "#line 1 1\n  while\n#line 5 0\n  (x > -1.0) { x += 1.0; }\n", "w.h:1"},
      {"a #line between keyword and condition", "  while\n#line 500\n  (x > -1.0) { x += 1.0; }\n", "m.glsl:5"},
      {"a comment inside the #define", "#/**/define PN_REPEAT while\n  PN_REPEAT (x > -1.0) { x += 1.0; }\n", "m.glsl:6"},
  };
  const pn::GlslangProcess process;
  for (const Spelling& spelling : spellings) {
    for (pn::Target target : pn::all_targets()) {
      pn::FlatSource flat;
      flat.text = "#line 1 0\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer Out { float result; };\n"
                  "void main() {\n  float x = 0.0;\n" + spelling.body + "  result = x;\n}\n";
      flat.files = {"m.glsl", "w.h"};
      flat.has_main = true;
      pn::ShaderSource source = pn::standalone_source(flat, target);
      const std::vector<pn::GuardedLoop> loops = pn::guard_loops(process, source, target, {5, 1000});
      INFO(spelling.name << ", " << pn::target_name(target) << ":\n" << source.text);
      REQUIRE(loops.size() == 1);
      CHECK(loops[0].file + ":" + std::to_string(loops[0].line) == spelling.loop);
      CHECK(source.text.find("pnLoopGuard(0u) && (") != std::string::npos);
      const pn::CompileResult compiled = pn::compile_with_glslang(process, source, target);
      for (const auto& d : compiled.diagnostics) INFO(d.str());
      CHECK(compiled.ok);
    }
  }
}

TEST_CASE("a source the preprocessor refuses is refused by the guard with its first error") {
  const pn::GlslangProcess process;
  pn::ShaderSource source = pn::test::module_source("float g = 1.0;\n#error not this copy\nfloat f() { return g; }\n");
  try {
    pn::guard_loops(process, source, pn::Target::gl450, {3, 100});
    FAIL("no error");
  } catch (const pn::Error& e) {
    CHECK(e.code() == pn::ExitCode::failed);
    CHECK_THAT(e.what(), Catch::StartsWith("m.glsl:2: error: ") && Catch::Contains("not this copy"));
  }
}

// Issue 39: an HLSL copy (check --hlsl-root) gets the same guard, in HLSL, after glslang's HLSL
// preprocessor: the probe's `for (uint k = 0u; k != 0xFFFFFFFFu; k += 2u)` and a macro-spelled loop.
TEST_CASE("an HLSL copy's loops are guarded in HLSL and still compile") {
  const std::string hlsl =
      "RWByteAddressBuffer result : register(u0);\n"            // 1
      "#define PN_REPEAT wh\\\nile\n"                            // 2-3
      "[numthreads(1, 1, 1)]\n"                                 // 4
      "void main() {\n"                                         // 5
      "  uint s = 0u;\n"                                        // 6
      "  [loop] for (uint k = 0u; k != 0xFFFFFFFFu; k += 2u)\n"  // 7
      "    s += k;\n"                                           // 8
      "  for (uint i = 0u; i < 4u; ++i) s += i;\n"              // 9: bounded, left alone
      "  PN_REPEAT (s > 3u) { s -= 2u; }\n"                     // 10
      "  result.Store(0, s);\n"
      "}\n";
  const pn::GlslangProcess process;
  std::string text = hlsl;
  const std::vector<pn::GuardedLoop> loops =
      pn::guard_hlsl_loops(process, text, "copy/pcf.hlsl", pn::Stage::compute, {7, 1000});
  INFO(text);
  std::vector<std::pair<std::string, int>> where;
  for (const pn::GuardedLoop& l : loops) where.push_back({l.file, l.line});
  CHECK(where == std::vector<std::pair<std::string, int>>{{"copy/pcf.hlsl", 7}, {"copy/pcf.hlsl", 10}});
  CHECK(text.find("register(u7)") != std::string::npos);
  const pn::CompileResult compiled = pn::compile_hlsl_with_glslang(process, text, "copy/pcf.hlsl", pn::Stage::compute);
  for (const auto& d : compiled.diagnostics) INFO(d.str());
  CHECK(compiled.ok);
}
