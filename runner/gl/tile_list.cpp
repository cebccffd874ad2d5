#include "gl/tile_list.h"

#include <algorithm>

namespace pn {

TileRun TileList::add(const std::vector<TexelRect>& rects, int width, int height) {
  const int tw = (width + kTileSide - 1) / kTileSide, th = (height + kTileSide - 1) / kTileSide;
  marks_.assign(static_cast<size_t>(tw) * th, 0);
  for (const TexelRect& r : rects) {
    const TexelRect c = intersection(r, {0, 0, width, height});
    if (c.empty()) continue;
    for (int y = c.y0 / kTileSide; y <= (c.y1 - 1) / kTileSide; ++y)
      for (int x = c.x0 / kTileSide; x <= (c.x1 - 1) / kTileSide; ++x) marks_[static_cast<size_t>(y) * tw + x] = 1;
  }
  TileRun run{static_cast<int>(tiles_.size() / 2), 0};
  for (int y = 0; y < th; ++y)
    for (int x = 0; x < tw; ++x)
      if (marks_[static_cast<size_t>(y) * tw + x]) {
        tiles_.push_back(x);
        tiles_.push_back(y);
        ++run.count;
      }
  return run;
}

void TileList::upload(const Context& context) {
  const size_t bytes = std::max<size_t>(tiles_.size(), 2) * sizeof(int);
  if (capacity_ < bytes) {
    capacity_ = 2 * bytes;
    buffer_ = make_buffer(context, capacity_, nullptr, GL_DYNAMIC_DRAW);
  }
  if (!tiles_.empty()) write_buffer(context, buffer_, 0, tiles_.size() * sizeof(int), tiles_.data());
}

}  // namespace pn
