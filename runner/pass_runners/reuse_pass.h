// Runner side of glsl/passes/reuse_link.comp and reuse_gather.comp: parent
// codes for a map of entries, then every pixel's representative and the value
// it takes from it.
#pragma once

#include <memory>

#include "device/query_device.h"
#include "modules/reuse_face.h"
#include "shader/source_tree.h"

namespace pn {

class ReusePass {
 public:
  // Runs on any executor (device/query_device.h).
  ReusePass(const QueryDevice& device, const SourceTree& tree);

  // R32F parent codes (PN_REUSE_NONE, PN_REUSE_LEFT, PN_REUSE_TOP: glsl/reuse.h) of a width × height
  // RGBA32F (d, x, y, s) entry texture.
  std::unique_ptr<DeviceTexture> link(const DeviceTexture& entries, int width, int height,
                                      const ReuseParams& params) const;

  // RGBA32F (representative x, y, value at the representative, 0) for every pixel.
  std::unique_ptr<DeviceTexture> gather(const DeviceTexture& parents, const DeviceTexture& values, int width,
                                        int height, int tile) const;

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> link_, gather_;
};

}  // namespace pn
