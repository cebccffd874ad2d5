// Include resolution and flattening: relative paths, the root boundary,
// cycles, comments, each file once, and the #line markers.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "shader/flatten.h"
#include "temp_tree.h"

using pn::test::TempTree;

namespace {

std::string error_of(const pn::SourceTree& tree, const std::string& entry) {
  try {
    pn::flatten(tree, entry);
  } catch (const pn::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("flatten emits each included file once, with #line markers that restore the includer's numbering") {
  TempTree dir(TempTree::Files{{"a.glsl", "#include \"b.glsl\"\n#include \"c.glsl\"\nfloat a() { return b() + c(); }\n"},
                {"b.glsl", "#include \"c.glsl\"\nfloat b() { return c(); }\n"},
                {"c.glsl", "float c() { return 1.0; }\n"}});
  const pn::SourceTree tree(dir.root());
  const pn::FlatSource flat = pn::flatten(tree, dir.root() / "a.glsl");
  CHECK(flat.files == std::vector<std::string>{"a.glsl", "b.glsl", "c.glsl"});
  CHECK(flat.text ==
        "#line 1 0\n"
        "#line 1 1\n"
        "#line 1 2\n"
        "float c() { return 1.0; }\n"
        "#line 2 1\n"
        "float b() { return c(); }\n"
        "#line 2 0\n"
        "#line 3 0\n"
        "float a() { return b() + c(); }\n");
  CHECK_FALSE(flat.has_main);
}

TEST_CASE("flatten ignores #include inside line and block comments") {
  TempTree dir(TempTree::Files{{"m.glsl", "// #include \"x.glsl\"\n/* start\n#include \"y.glsl\"\n*/ float m;\n"}});
  const pn::FlatSource flat = pn::flatten(pn::SourceTree(dir.root()), "m.glsl");
  CHECK(flat.files.size() == 1);
  CHECK(flat.text.find("#include \"y.glsl\"") != std::string::npos);  // kept as comment text
}

TEST_CASE("include resolves next to the includer first, then at the root") {
  TempTree dir(TempTree::Files{{"passes/p.comp", "#include \"util.glsl\"\n#include \"local.glsl\"\nvoid main() {}\n"},
                {"passes/local.glsl", "float local;\n"},
                {"util.glsl", "float util;\n"}});
  const pn::FlatSource flat = pn::flatten(pn::SourceTree(dir.root()), "passes/p.comp");
  CHECK(flat.files == std::vector<std::string>{"passes/p.comp", "util.glsl", "passes/local.glsl"});
  CHECK(flat.has_main);
}

TEST_CASE("negative: an include cycle is refused at the #include line, naming the chain") {
  TempTree dir(TempTree::Files{{"a.glsl", "float a;\n#include \"b.glsl\"\n"}, {"b.glsl", "\n\n#include \"a.glsl\"\n"}});
  const std::string message = error_of(pn::SourceTree(dir.root()), "a.glsl");
  CHECK(message.find("b.glsl:3: error: include cycle: a.glsl -> b.glsl -> a.glsl") != std::string::npos);
}

TEST_CASE("negative: an include leaving the glsl root is refused") {
  TempTree dir(TempTree::Files{{"root/m.glsl", "#include \"../secret.glsl\"\n"}, {"secret.glsl", "float s;\n"}});
  const std::string message = error_of(pn::SourceTree(dir.root() / "root"), "m.glsl");
  CHECK(message.find("m.glsl:1: error: #include \"../secret.glsl\": leaves the glsl root") != std::string::npos);
}

TEST_CASE("negative: an absolute include path is refused") {
  TempTree dir(TempTree::Files{{"m.glsl", "#include \"/etc/hosts\"\n"}});
  CHECK(error_of(pn::SourceTree(dir.root()), "m.glsl").find("expected a path relative to the glsl root") !=
        std::string::npos);
}

TEST_CASE("negative: a missing include names the includer and line") {
  TempTree dir(TempTree::Files{{"m.glsl", "float m;\n#include \"gone.glsl\"\n"}});
  CHECK(error_of(pn::SourceTree(dir.root()), "m.glsl").find("m.glsl:2: error: #include \"gone.glsl\": no such file") !=
        std::string::npos);
}

TEST_CASE("negative: a missing entry file and a missing root are bad input") {
  TempTree dir(TempTree::Files{{"m.glsl", "float m;\n"}});
  CHECK(error_of(pn::SourceTree(dir.root()), "nothing.glsl").find("'nothing.glsl': no such file") != std::string::npos);
  try {
    pn::SourceTree tree(dir.root() / "not-a-dir");
    FAIL("a missing root was accepted");
  } catch (const pn::Error& e) {
    CHECK(std::string(e.what()).find("expected an existing directory") != std::string::npos);
    CHECK(e.code() == pn::ExitCode::bad_input);
  }
}

TEST_CASE("flatten scans 50,000-character lines and include paths without recursing per character (negative)") {
  const std::string spaces(50000, ' ');
  const std::string long_name(100000, 'x');
  TempTree dir(TempTree::Files{{"a.glsl", spaces + "float x;\n" + spaces + "#  include \"b.glsl\"" + spaces + "\n" +
                                              "void  main (){}\n"},
                               {"b.glsl", "float b;\n"},
                               {"c.glsl", "#include \"" + long_name + ".glsl\"\n"}});
  const pn::SourceTree tree(dir.root());
  const pn::FlatSource flat = pn::flatten(tree, dir.root() / "a.glsl");
  CHECK(flat.files == std::vector<std::string>{"a.glsl", "b.glsl"});
  CHECK(flat.has_main);
  CHECK(flat.text.find("float b;") != std::string::npos);
  CHECK(error_of(tree, (dir.root() / "c.glsl").string()).find("c.glsl:1: error: ") != std::string::npos);
}

TEST_CASE("what is not an include, an include extension or main stays code") {
  TempTree dir(TempTree::Files{{"a.glsl", "# includes \"b.glsl\"\n#extension GL_GOOGLE_include_directive_x : enable\n"
                                          "void mainly() {}\nvoidmain() {}\n"}});
  const pn::SourceTree tree(dir.root());
  const pn::FlatSource flat = pn::flatten(tree, dir.root() / "a.glsl");
  CHECK(flat.files == std::vector<std::string>{"a.glsl"});
  CHECK_FALSE(flat.has_main);
  CHECK(flat.text.find("#extension GL_GOOGLE_include_directive_x") != std::string::npos);
}
