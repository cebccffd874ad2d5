// Batches of per-texel queries for query passes: k-th query at texel
// (k mod width, k / width) of an RGBA image, the tail padded with a copy of the
// first query so that every texel is a valid query with a reference.
#pragma once

#include <array>
#include <vector>

#include "core/image.h"

namespace pn {

using Query = std::array<float, 4>;

inline Image query_image(const std::vector<Query>& queries, int width = 1024) {
  const int count = static_cast<int>(queries.size());
  const int w = count < width ? (count > 0 ? count : 1) : width;
  const int h = (count + w - 1) / w > 0 ? (count + w - 1) / w : 1;
  Image image(w, h, 4);
  for (int k = 0; k < w * h; ++k) {
    const Query& q = k < count ? queries[static_cast<size_t>(k)] : queries.front();
    for (int c = 0; c < 4; ++c) image.at(k % w, k / w, c) = q[static_cast<size_t>(c)];
  }
  return image;
}

// Result k of a query pass: the four channels of texel (k mod width, k / width) of its result image.
inline Query query_result(const Image& results, size_t k) {
  const int x = static_cast<int>(k % static_cast<size_t>(results.width)), y = static_cast<int>(k / static_cast<size_t>(results.width));
  return {results.at(x, y, 0), results.at(x, y, 1), results.at(x, y, 2), results.at(x, y, 3)};
}

}  // namespace pn
