// Programs built from flattened passes (GL 4.50 or ES 3.10 wrapper); driver diagnostics
// are mapped back to module files and lines.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "shader/loop_guard.h"
#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn {

// Compiles each stage (its type from ShaderSource::stage) and links them.
// Throws Error(ExitCode::failed) naming `name` on a compile or link error.
GlObject link_program(const Context& context, const std::string& name, const std::vector<const ShaderSource*>& stages);

class ComputeProgram {
 public:
  // `name` is used in messages (and as the pass of a loop census record, with `defines`: what
  // it was compiled with). Throws Error(ExitCode::failed) on a compile or link error.
  ComputeProgram(const Context& context, const std::string& name, const ShaderSource& source,
                 const std::vector<Define>& defines = {});

  // Runs the program over a width × height grid of invocations (rounded up to
  // whole work groups) and waits for image writes to become visible.
  void dispatch(int width, int height) const;

  // Runs the number of work groups held by the first three uints of `buffer`
  // (glDispatchComputeIndirect), after making earlier shader writes to it visible.
  void dispatch_indirect(const GlObject& buffer) const;

  GLuint id() const { return program_.id(); }

 private:
  // Issues the dispatch; under the context's DispatchBounds, with the loop guard's state bound
  // and cleared, then waits for it with the deadline and throws Error(ExitCode::failed)
  // naming the pass on a timeout or a loop that passed the guard's limit.
  void run(const std::string& what, const std::function<void()>& issue) const;
  // Under a loop census: issues the dispatch of groups[0] × groups[1] work groups with a zeroed
  // count buffer bound, and adds its record to the census.
  void run_counted(const std::string& what, const int groups[2], const std::function<void()>& issue) const;

  const Context* context_;
  std::string name_;
  GlObject program_;
  GLint local_size_[3] = {1, 1, 1};
  // Under DispatchBounds: the loops of the source (shader/loop_guard.h) and the guard's buffer.
  std::vector<GuardedLoop> loops_;
  GLuint guard_binding_ = 0;
  GlObject guard_state_;
  // Compiled under a loop census: its loops and where their counts go.
  std::vector<Define> defines_;
  std::vector<CensusLoop> census_loops_;
  LoopCensus* census_ = nullptr;
};

// The GLSL target a context's driver compiles: es310 on an OpenGL ES context, else gl450 —
// the wrapper `penumbra bundle --target` writes.
Target driver_target(const Context& context);

// Flattens `pass` (a path under the glsl root, e.g. "passes/blur.comp") from
// `tree`, wraps it for the context's target (driver_target) with `defines`, and compiles it.
ComputeProgram compile_pass(const Context& context, const SourceTree& tree, const std::string& pass,
                            const std::vector<Define>& defines = {});

// Links `stem`.vert and `stem`.frag (paths under the glsl root, e.g. "passes/gbuffer").
GlObject link_raster_pass(const Context& context, const SourceTree& tree, const std::string& stem);
// Links a vertex and a fragment pass (paths under the glsl root), both wrapped with `defines`.
GlObject link_raster_pass(const Context& context, const SourceTree& tree, const std::string& vertex,
                          const std::string& fragment, const std::vector<Define>& defines);

}  // namespace pn
