// The bench's GPU cost proxy (issue 25): llvmpipe's times are not a GPU's,
// but a GPU's time for a shading pass follows the texel fetches its lanes
// make, and a SIMD group (32 or 64 lanes: an 8×8 tile of pixels, the
// passes' local size) costs its slowest lane. From a frame's per-pixel fetch
// counts, over the pixels that see a surface: their mean, and the mean when
// each is charged its 8×8 tile's maximum (what it costs in a group that waits
// for its slowest lane; >= the mean, equal when every tile is uniform).
#pragma once

#include <vector>

#include "core/image.h"
#include "frame/technique.h"  // NamedValues

namespace pn {

inline constexpr int kFetchTile = 8;  // pixels a side: a SIMD group of 64 lanes

// The stats (TechniqueFrame::stats) that carry it.
inline constexpr const char* kFetchStat = "fetch/px";
inline constexpr const char* kFetchTileMaxStat = "fetch tile max";

struct FetchProxy {
  double per_receiver = 0.0;  // fetches per pixel that sees a surface
  double tile_max = 0.0;      // mean over receivers of their tile's largest count
};

// `fetches`: one count per pixel (channel 0); `receiver(x, y)`: whether pixel (x, y) sees a surface.
template <class Receiver>
FetchProxy fetch_proxy(const Image& fetches, Receiver receiver) {
  FetchProxy p;
  long receivers = 0;
  for (int ty = 0; ty < fetches.height; ty += kFetchTile)
    for (int tx = 0; tx < fetches.width; tx += kFetchTile) {
      double most = 0.0;
      long in_tile = 0;
      for (int y = ty; y < ty + kFetchTile && y < fetches.height; ++y)
        for (int x = tx; x < tx + kFetchTile && x < fetches.width; ++x) {
          if (!receiver(x, y)) continue;
          ++in_tile;
          p.per_receiver += fetches.at(x, y);
          most = most > fetches.at(x, y) ? most : fetches.at(x, y);
        }
      receivers += in_tile;
      p.tile_max += most * static_cast<double>(in_tile);
    }
  if (receivers > 0) p.per_receiver /= static_cast<double>(receivers), p.tile_max /= static_cast<double>(receivers);
  return p;
}

// A technique whose call makes a fixed number of fetches a receiver (its module's bound: pcf, vsm,
// savsm) reports it as both figures.
inline NamedValues constant_fetch_stats(double per_receiver) {
  return {{kFetchStat, per_receiver}, {kFetchTileMaxStat, per_receiver}};
}

}  // namespace pn
