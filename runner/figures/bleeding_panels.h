// The layout the light-bleeding figures share (vsm_bleeding.png,
// savsm_bleeding.png): the depth map and the exact PCF visibility, then each
// technique's visibility above its signed error against the exact PCF (red:
// light that bleeds), an optional line under each, and the error's colour bar.
#pragma once

#include <string>
#include <vector>

#include "core/image.h"
#include "draw/canvas.h"

namespace pn {

struct BleedingPanel {
  std::string name;
  Image visibility;    // the map's size, 1 lit, 0 in shadow
  std::string footer;  // under the error map; empty: none
};

Canvas bleeding_panels(const Image& map, const Image& exact, const std::string& exact_name,
                       const std::vector<BleedingPanel>& panels);

}  // namespace pn
