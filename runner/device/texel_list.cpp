#include "device/texel_list.h"

#include <algorithm>

#include "core/error.h"

namespace pn {

TexelRun TexelList::add(const std::vector<TexelRect>& rects, int width, int height) {
  TexelRun run{static_cast<int>(texels_.size() / 2), 0, false};
  long long total = 0;
  for (const TexelRect& r : rects) total += intersection(r, {0, 0, width, height}).area();
  if (total > kMaxListedTexels) {
    run.whole = true;
    return run;
  }
  for (const TexelRect& r : rects) {
    const TexelRect c = intersection(r, {0, 0, width, height});
    for (int y = c.y0; y < c.y1; ++y)
      for (int x = c.x0; x < c.x1; ++x) {
        texels_.push_back(x);
        texels_.push_back(y);
      }
  }
  run.count = static_cast<int>(total);
  return run;
}

void TexelList::upload(const QueryDevice& device) {
  const size_t bytes = std::max<size_t>(texels_.size(), 2) * sizeof(int);
  if (capacity_ < bytes || device_ != &device) {
    capacity_ = 2 * bytes;
    buffer_ = device.make_buffer(capacity_);
    device_ = &device;
  }
  if (!texels_.empty()) device.write_buffer(*buffer_, 0, texels_.size() * sizeof(int), texels_.data());
}

const DeviceBuffer& TexelList::buffer() const {
  if (!buffer_) throw Error("texel list: read before its first upload");
  return *buffer_;
}

std::pair<int, int> texel_run_grid(const TexelRun& run, int width, int height) {
  if (run.whole) return {width, height};
  if (run.count <= 0) return {0, 0};
  const int groups = (run.count + kTexelListGroup - 1) / kTexelListGroup;
  return {groups * 8, 8};  // groups × 1 work groups of 8×8
}

}  // namespace pn
