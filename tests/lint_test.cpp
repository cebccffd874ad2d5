// glslang front end: the library's modules compile for every target, and an
// error is reported at the file and line where it is, inside included files.
#include <catch2/catch.hpp>

#include "shader/lint.h"
#include "temp_tree.h"

using pn::test::TempTree;

namespace {

const pn::GlslangProcess& glslang() {
  static const pn::GlslangProcess process;
  return process;
}

}  // namespace

TEST_CASE("every module and pass in glsl/ compiles for gl450, vulkan and es310") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const auto files = pn::collect_glsl_files(PENUMBRA_GLSL_DIR);
  REQUIRE(files.size() >= 2);
  for (const auto& file : files) {
    const pn::LintResult result = pn::lint_file(glslang(), tree, file);
    INFO(result.file);
    for (const auto& d : result.diagnostics) INFO(d.str());
    CHECK(result.ok);
  }
}

TEST_CASE("negative: a compile error inside an included file is reported at that file and line, for all targets") {
  TempTree dir(TempTree::Files{{"outer.glsl", "#include \"inner.glsl\"\nfloat outer() { return inner(); }\n"},
                {"inner.glsl", "float inner() {\n  float x = 1.0;\n  return x + undefined_name;\n}\n"}});
  const pn::SourceTree tree(dir.root());
  const pn::LintResult result = pn::lint_file(glslang(), tree, dir.root() / "outer.glsl");
  CHECK_FALSE(result.ok);
  REQUIRE(result.diagnostics.size() == 1);
  const pn::LintDiagnostic& d = result.diagnostics.front();
  CHECK(d.diagnostic.file == tree.diagnostic_path(tree.root() / "inner.glsl"));
  CHECK(d.diagnostic.line == 3);
  CHECK(d.diagnostic.message.find("undefined_name") != std::string::npos);
  CHECK(d.targets.size() == 3);
}

TEST_CASE("negative: ES 3.10 rejects what desktop GLSL accepts, and only ES is blamed") {
  TempTree dir(TempTree::Files{{"m.glsl", "double twice(double x) { return 2.0lf * x; }\n"}});
  const pn::LintResult result = pn::lint_file(glslang(), pn::SourceTree(dir.root()), dir.root() / "m.glsl");
  CHECK_FALSE(result.ok);
  REQUIRE_FALSE(result.diagnostics.empty());
  for (const auto& d : result.diagnostics) CHECK(d.targets == std::vector<pn::Target>{pn::Target::es310});
  CHECK(result.diagnostics.front().diagnostic.line == 1);
}

TEST_CASE("negative: Vulkan rejects a pass with an unbound plain uniform, GL accepts it") {
  TempTree dir(TempTree::Files{{"p.comp", "layout(local_size_x = 1) in;\nuniform float scale;\nvoid main() { float s = scale; }\n"}});
  const pn::LintResult result = pn::lint_file(glslang(), pn::SourceTree(dir.root()), dir.root() / "p.comp");
  CHECK_FALSE(result.ok);
  REQUIRE_FALSE(result.diagnostics.empty());
  CHECK(result.diagnostics.front().targets == std::vector<pn::Target>{pn::Target::vulkan});
  CHECK(result.diagnostics.front().diagnostic.line == 2);
}
