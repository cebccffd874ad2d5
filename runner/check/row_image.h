// A list of values as a one-row image of `channels` channels (values.size() / channels texels,
// one at least), so compare() can judge lists as it judges images.
#pragma once

#include <algorithm>
#include <vector>

#include "core/image.h"

namespace pn {

inline Image row_image(const std::vector<float>& values, int channels = 1) {
  const int n = static_cast<int>(values.size()) / channels;
  Image image(std::max(n, 1), 1, channels);
  std::copy(values.begin(), values.end(), image.texels.begin());
  return image;
}

}  // namespace pn
