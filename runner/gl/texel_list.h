// The runner side of glsl/passes/texel_list.glsl: the texels of a set of
// rectangles of a grid, as runs of one storage buffer (one run a level of a
// structure, or one for a map), so that an incremental update is one
// dispatch a level however many rectangles it covers, and touches no texel
// outside them.
#pragma once

#include <vector>

#include "core/texel_rect.h"
#include "gl/objects.h"

namespace pn {

// texel_list.glsl's work group: 8×8 invocations, flattened.
inline constexpr int kTexelListGroup = 64;
// More listed texels than this in one run are dispatched as the whole grid instead (GL's least
// GL_MAX_COMPUTE_WORK_GROUP_COUNT[0], 65535 groups).
inline constexpr long long kMaxListedTexels = 65535LL * kTexelListGroup;

struct TexelRun {
  int first = 0, count = 0;
  bool whole = false;  // too many texels to list: dispatch the whole grid
};

class TexelList {
 public:
  void clear() { texels_.clear(); }
  // The texels of `rects` clipped to a width × height grid, rectangle after rectangle (a texel in two
  // overlapping rectangles is listed twice: merge them first, merged_rects, to list it once).
  TexelRun add(const std::vector<TexelRect>& rects, int width, int height);
  // Uploads the list into buffer() (grown when it is too small); binds nothing.
  void upload(const Context& context);
  const GlObject& buffer() const { return buffer_; }

 private:
  std::vector<int> texels_;  // (x, y) pairs
  GlObject buffer_;
  size_t capacity_ = 0;  // bytes of buffer_
};

// Dispatches `program` (8×8 local size, texel_list.glsl) over a run: its listed texels, the whole
// width × height grid for a run too long to list, nothing for an empty run. The caller has bound
// the list and the block that carries the run (first, count; count 0 for the whole grid).
class ComputeProgram;
void dispatch_texel_run(const ComputeProgram& program, const TexelRun& run, int width, int height);

}  // namespace pn
