// What the fuzz targets (fuzz/, scripts/fuzz.sh) found, each kept as a plain
// test: docs/reliability.md, "Fuzzing". The inputs that crashed a target are
// also replayed by scripts/fuzz.sh from fixtures/fuzz/regressions/.
#include <catch2/catch.hpp>

#include <climits>
#include <string>
#include <tuple>

#include "core/error.h"
#include "scene/model.h"
#include "shader/diagnostic.h"
#include "shader/flatten.h"
#include "shader/target.h"
#include "temp_tree.h"

using pn::test::TempTree;
namespace fs = std::filesystem;

namespace {

using Origin = std::pair<std::string, int>;

const pn::LocationMap kByNumber = [](int number, int line) { return Origin{"file" + std::to_string(number), line}; };

std::string model_error(const fs::path& file) {
  try {
    pn::load_model_triangles(file);
  } catch (const pn::Error& e) {
    CHECK(e.code() == pn::ExitCode::bad_input);
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("negative: 100,000-character log lines in each format map like short ones (std::regex overflowed the stack)") {
  const std::string x(100000, 'x');
  const std::string log = "ERROR: 2:14: '" + x + "' : undeclared identifier\n" +  // glslang
                          "0:7(3): error: `" + x + "' undeclared\n" +             // Mesa
                          "0(9) : error C1008: undefined variable \"" + x + "\"\n" +  // NVIDIA
                          "ERROR: " + x + "\n" +                                      // glslang, no location
                          "ERROR: 0:1: '' : compilation terminated " + x + "\n" +  // the rest is dropped
                          "ERROR: 0:2: '' : missing #endif\n";
  const auto d = pn::parse_info_log(log, kByNumber, "entry.glsl");
  REQUIRE(d.size() == 4);
  CHECK(d[0].str() == "file2:14: error: '" + x + "' : undeclared identifier");
  CHECK(d[1].str() == "file0:7: error: `" + x + "' undeclared");
  CHECK(d[2].str() == "file0:9: error: undefined variable \"" + x + "\"");
  CHECK(d[3].str() == "entry.glsl: error: " + x);
}

TEST_CASE("log lines with a carriage return keep the regexes' meaning: trailing is white space, inside is no match") {
  const auto d = pn::parse_info_log("ERROR: 0:3: 'x' : undeclared\r\n0:4(1): error: a\rb\n", kByNumber, "entry.glsl");
  REQUIRE(d.size() == 1);
  CHECK(d[0].str() == "file0:3: error: 'x' : undeclared");
}

TEST_CASE("negative: a 100,000-digit #line marker is blanked for the driver and saturates (std::regex overflowed the stack)") {
  pn::ShaderSource source;
  source.text = "#version 450\n#line " + std::string(100000, '9') + " 1\nalpha\n";
  source.files = {"a.glsl", "b.glsl"};
  CHECK(source.driver_text() == "#version 450\n\nalpha\n");
  CHECK(source.origin_of_line(3) == Origin{"b.glsl", INT_MAX});
}

TEST_CASE("negative: lines after `#line 2147483647` stay at 2147483647 instead of overflowing int") {
  // fixtures/fuzz/regressions/diagnostic/line_marker_int_max.txt: UBSan's signed-integer-overflow in origin_of_line.
  pn::ShaderSource source;
  source.text = "#version 450\n#line 2147483647 1\nalpha\nbeta\n#line 5 7\ngamma\n";
  source.files = {"a.glsl", "b.glsl"};
  CHECK(source.origin_of_line(3) == Origin{"b.glsl", INT_MAX});
  CHECK(source.origin_of_line(4) == Origin{"b.glsl", INT_MAX});
  CHECK(source.origin_of_line(6) == Origin{"<wrapper>", 5});  // file number 7 is not in the table
}

TEST_CASE("negative: an #include of a directory is refused at its line (it was included as an empty file)") {
  // fixtures/fuzz/regressions/flatten/include_directory.txt: fuzz_flatten's check that every
  // included file is a regular file failed on `#include "sub"` and `#include "."`.
  TempTree dir(TempTree::Files{{"m.glsl", "float m;\n#include \"sub\"\n"}, {"dot.glsl", "#include \".\"\n"}, {"sub/c.glsl", ""}});
  const pn::SourceTree tree(dir.root());
  for (const auto& [entry, line, name] : {std::tuple{"m.glsl", 2, "sub"}, std::tuple{"dot.glsl", 1, "."}}) {
    INFO(entry);
    try {
      pn::flatten(tree, dir.root() / entry);
      FAIL("flattened");
    } catch (const pn::Error& e) {
      CHECK_THAT(e.what(), Catch::EndsWith(std::string(entry) + ":" + std::to_string(line) + ": error: #include \"" + name +
                                           "\": expected a GLSL file, found a directory or special file"));
    }
  }
}

TEST_CASE("negative: an OFF file that crashes Assimp 5.2.5 is refused as bad input, one line naming it, the process alive") {
  // fixtures/fuzz/regressions/model/assimp_off_segv.txt without its "off" line: a SEGV inside
  // Assimp::Importer::ReadFile (`penumbra render --model` died with signal 11 before the import child).
  TempTree dir(TempTree::Files{{"crash.off", std::string("OFF1\n3 0   3 0 0\n \n0\n\x15\n0", 24)}});
  const fs::path file = dir.root() / "crash.off";
  const std::string message = model_error(file);
  CHECK_THAT(message, Catch::StartsWith("model '" + file.string() + "': not a mesh file Assimp can read: "));
  CHECK(message.find('\n') == std::string::npos);
}

TEST_CASE("negative: an OBJ that Assimp gives up on midway (a face index out of range in a second group) is bad input") {
  // fixtures/fuzz/regressions/model/assimp_obj_leak.txt: Assimp 5.2.5 leaks the first group's mesh
  // when it throws (assimp/assimp#4131), now inside the import child.
  TempTree dir(TempTree::Files{{"two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ng second\nf 1 2 99\n"}});
  const fs::path file = dir.root() / "two.obj";
  CHECK_THAT(model_error(file), Catch::StartsWith("model '" + file.string() + "': not a mesh file Assimp can read: "));
}

TEST_CASE("the import child returns every triangle of a good file, as many as the parent read before") {
  TempTree dir(TempTree::Files{{"one.obj", "v 1 2 3\nv 3 2 3\nv 1 6 5\nf 1 2 3\nv 0 0 0\nf 1 2 4\n"}});
  const std::vector<glm::vec3> t = pn::load_model_triangles(dir.root() / "one.obj");
  REQUIRE(t.size() == 6);
  CHECK(t[0] == glm::vec3(1, 2, 3));
  CHECK(t[2] == glm::vec3(1, 6, 5));
  CHECK(t[5] == glm::vec3(0, 0, 0));
}
