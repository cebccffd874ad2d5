// Mapping compiler logs back to files and lines.
#include <catch2/catch.hpp>

#include "shader/diagnostic.h"
#include "shader/target.h"

TEST_CASE("glslang, Mesa and NVIDIA log lines map through the location map") {
  const pn::LocationMap map = [](int number, int line) {
    return std::pair<std::string, int>{"file" + std::to_string(number), line + 100};
  };
  const std::string log =
      "ERROR: 2:14: 'x' : undeclared identifier \n"
      "0:7(3): error: `y' undeclared\n"
      "0(9) : error C1008: undefined variable \"z\"\n"
      "ERROR: Linking compute stage: Missing entry point\n"
      "ERROR: 3 compilation errors.  No code generated.\n";
  const auto d = pn::parse_info_log(log, map, "entry.glsl");
  REQUIRE(d.size() == 4);
  CHECK(d[0].str() == "file2:114: error: 'x' : undeclared identifier");
  CHECK(d[1].str() == "file0:107: error: `y' undeclared");
  CHECK(d[2].str() == "file0:109: error: undefined variable \"z\"");
  CHECK(d[3].str() == "entry.glsl: error: Linking compute stage: Missing entry point");
}

TEST_CASE("physical lines of a wrapped source map back through its #line markers") {
  pn::ShaderSource source;
  source.text = "#version 450\n#line 1 0\nalpha\n#line 5 1\nbeta\ngamma\n#line 3 0\ndelta\n";
  source.files = {"a.glsl", "b.glsl"};
  using Origin = std::pair<std::string, int>;
  CHECK(source.origin_of_line(1) == Origin{"<wrapper>", 1});
  CHECK(source.origin_of_line(3) == Origin{"a.glsl", 1});
  CHECK(source.origin_of_line(5) == Origin{"b.glsl", 5});
  CHECK(source.origin_of_line(6) == Origin{"b.glsl", 6});
  CHECK(source.origin_of_line(8) == Origin{"a.glsl", 3});
  CHECK(source.driver_text() == "#version 450\n\nalpha\n\nbeta\ngamma\n\ndelta\n");
}

TEST_CASE("line numbers beyond int in a log or a #line marker saturate instead of throwing (negative)") {
  const pn::LocationMap map = [](int number, int line) {
    return std::pair<std::string, int>{"file" + std::to_string(number), line};
  };
  const auto d = pn::parse_info_log("ERROR: 0:99999999999: 'x' : undeclared identifier\n", map, "entry.glsl");
  REQUIRE(d.size() == 1);
  CHECK(d[0].line == 2147483647);
  pn::ShaderSource source;
  source.text = "#version 450\n#line 99999999999 0\nalpha\n";
  source.files = {"a.glsl"};
  CHECK(source.origin_of_line(3) == std::pair<std::string, int>{"a.glsl", 2147483647});
}
