// The runner side of glsl/passes/tile_list.glsl: the 8×8 tiles of a texel
// grid that a set of rectangles touches, as runs of one storage buffer (one
// run a level of a structure, or one for a map), so that an incremental
// update is one dispatch a level however many rectangles it covers.
#pragma once

#include <vector>

#include "core/texel_rect.h"
#include "gl/objects.h"

namespace pn {

inline constexpr int kTileSide = 8;  // glsl/passes/tile_list.glsl's PN_TILE_SIDE
inline constexpr int kMaxTileGroups = 65535;  // GL's least GL_MAX_COMPUTE_WORK_GROUP_COUNT[0]

struct TileRun {
  int first = 0, count = 0;
};

class TileList {
 public:
  // Starts a new list; runs are added in order.
  void clear() { tiles_.clear(); }
  // The tiles of a width × height grid that `rects` touch (each once, row by row); rects are clipped to the grid.
  TileRun add(const std::vector<TexelRect>& rects, int width, int height);
  // Uploads the list into buffer() (grown when it is too small); binds nothing.
  void upload(const Context& context);
  const GlObject& buffer() const { return buffer_; }
  size_t size() const { return tiles_.size() / 2; }

 private:
  GlObject buffer_;
  size_t capacity_ = 0;  // bytes of buffer_
  std::vector<int> tiles_;  // (x, y) pairs
  std::vector<unsigned char> marks_;
};

}  // namespace pn
