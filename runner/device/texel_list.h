// The runner side of glsl/passes/texel_list.glsl: the texels of a set of
// rectangles of a grid, as runs of one storage buffer (one run a level of a
// structure, or one for a map), so that an incremental update is one
// dispatch a level however many rectangles it covers, and touches no texel
// outside them.
#pragma once

#include <vector>

#include <memory>
#include <utility>

#include "core/texel_rect.h"
#include "device/query_device.h"

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
  // Uploads the list into buffer() on `device` (grown when it is too small); binds nothing.
  void upload(const QueryDevice& device);
  // The list as uploaded last. Throws Error before the first upload.
  const DeviceBuffer& buffer() const;

 private:
  std::vector<int> texels_;  // (x, y) pairs
  std::unique_ptr<DeviceBuffer> buffer_;
  const QueryDevice* device_ = nullptr;  // where buffer_ lives
  size_t capacity_ = 0;                  // bytes of buffer_
};

// The grid of invocations that runs a pass of 8×8 work groups (texel_list.glsl) over a run: its
// listed texels (groups × 1 groups), the whole width × height grid for a run too long to list,
// nothing (0 × 0) for an empty run. The pass's block carries the run (first, count; count 0 for
// the whole grid).
std::pair<int, int> texel_run_grid(const TexelRun& run, int width, int height);

}  // namespace pn
