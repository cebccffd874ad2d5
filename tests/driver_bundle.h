// Helper of the GL tests: whether `penumbra bundle`'s standalone text of a
// module or pass (for the context's target — GL 4.50, or ES 3.10 on an ES context — #line
// markers and all) compiles with the GL driver.
#pragma once

#include <string>

#include "gl/compute_program.h"
#include "gl/objects.h"
#include "gl_test_context.h"
#include "shader/flatten.h"
#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn::test {

inline bool driver_compiles_bundle(const std::string& module) {
  const Context& context = gl_context();
  const SourceTree tree(PENUMBRA_GLSL_DIR);
  const ShaderSource bundle = standalone_source(flatten(tree, module), driver_target(context));
  GlObject shader(context, GlKind::shader, GL_COMPUTE_SHADER);
  const char* text = bundle.text.c_str();
  context.gl().ShaderSource(shader.id(), 1, &text, nullptr);
  context.gl().CompileShader(shader.id());
  GLint ok = 0;
  context.gl().GetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  return ok == GL_TRUE;
}

}  // namespace pn::test
