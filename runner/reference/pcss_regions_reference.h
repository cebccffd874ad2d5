// CPU definition of the search and filter regions of PCSS (glsl/pcss_regions.glsl),
// written from SPEC §4.7 Steps 3–4 and the light model (scene/light_model.h),
// in double precision, never ported from the shader:
//
// - an entry (d, x, y, s) of the search- or filter-region map is the receiver's
//   light depth, the region's centre (texels) and its side (texels); s < 0
//   marks a pixel known to be lit;
// - the region an entry stands for: the exact square (pcss_square), or the
//   power-of-two window of SPEC §4.2 (region_reference.h), literal or centred;
// - Step 3: PCSS's search width for d (blockers as near as the near plane),
//   refined at most `iterations` times (the module's bound is 16): read zmin,
//   the min depth over a square covering the exact region, in every mode; zmin >= d - bias
//   → lit; the width a blocker at zmin needs; stop when it no longer shrinks;
// - Step 4: side = c · penumbra (Eq. 1, in texels at the receiver), lit when
//   there is no blocker;
// - SPEC §4.7 Step 3's property: a receiver is lit only when no texel can shadow
//   it — no texel at depth z < d - bias lies in the square of the width a blocker
//   at z needs (shadowing_blocker).
//
// Depths are read through a DepthScan of the sanitized map (NaN, ±Inf: +Inf,
// "no occluder", SPEC §3): the min over a rectangle by scanning every texel.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>

#include "core/image.h"
#include "core/texel_rect.h"
#include "modules/pcss_regions_face.h"
#include "modules/traversal_face.h"
#include "scene/light_model.h"

namespace pn {

struct RegionEntry {
  double depth = 0.0, x = 0.0, y = 0.0, side = kRegionLit;
  bool lit() const { return !(side >= 0.0); }  // NaN sides too
};

// The square of side `side` around (x, y) clipped to an n×n map: the m×m texels,
// m = max(1, round(s)) (at most 4n), whose centres are nearest (x, y), i.e. origin
// floor(c - m/2 + 1/2) — empty when it misses the map. A NaN or negative side
// reads as 0 and +Inf as 4n (the map covered); a NaN centre coordinate as 0, ±Inf
// clamps (the square misses the map). `margin` (optional): how far (texels) the
// rounding of its side and origin was from flipping.
Rect pcss_square(double x, double y, double side, int n, double* margin);

// The texels an entry stands for in a region mode: exact: pcss_square; window /
// centred: the power-of-two window of region_reference / region_centred_reference
// (evaluated from the entry's float values, as SPEC §4.2's Step 1 is in float32).
Rect entry_region(const RegionEntry& entry, int n, RegionMode mode);

// The square whose min depth Step 3 reads for an entry, in every region mode: the
// square of side max(w, h) at the exact region's origin, moved inside the map — it
// covers the region (SPEC §4.7); empty when the region is.
Rect search_min_square(const RegionEntry& entry, int n);
// The same square for any rectangle inside the map: side max(w, h) at its origin, moved inside the map.
Rect covering_square(const Rect& r, int n);

// The texels the square with area-weighted edges touches (pnRegionArea's cover, issue 51): per axis
// [floor(c - s/2), ceil(c + s/2)), s = clamp(side, 1, 4n) — a NaN or negative side read as 0, a
// NaN centre coordinate as 0, the centre clamped to [-4n, 5n] — the bounds clipped to [0, n].
Rect area_cover(double x, double y, double side, int n);

// The rectangle whose min depth Step 3 reads from the aligned mip chain
// (pn_searchRegionMinMip): the aligned nodes of side 2^l, l = max(2, ceil(log2 m) - 1),
// that touch the square of side m = max(w, h) at the exact region's origin (clipped
// to the map), themselves clipped to the map — a superset of search_min_square's
// texels when both lie in the map; empty when the region is.
Rect mip_search_cover(const RegionEntry& entry, int n);
// The same for a rectangle inside the map (pnMipSquareMinMax of its origin and side max(w, h)):
// the aligned nodes that cover that square, clipped to the map; empty for an empty rectangle.
Rect mip_square_cover(const Rect& rect, int n);

// Min sanitized depth over rectangles of one map, by scanning every texel of each
// (remembered per rectangle: refinement and the check's cases read the same ones often).
class DepthScan {
 public:
  explicit DepthScan(const Image& map);  // any single-channel map; depths sanitized here
  double min(const Rect& r) const;       // +Inf for an empty rectangle
  const Image& depths() const { return depths_; }
  int size() const { return depths_.width; }

 private:
  Image depths_;
  mutable std::unordered_map<std::uint64_t, double> mins_;
};

// A receiver as the G-buffer holds it (float): shadow-map position, light depth, valid.
struct RegionReceiver {
  float u = 0.0f, v = 0.0f, depth = 0.0f, valid = 1.0f;
};

// How close a computation came to a decision that float and double may take
// apart: `relative` is the relative uncertainty of a float width (and a float
// position) — a decision within it is ambiguous.
struct Rounding {
  double relative = 1e-5;
  bool ambiguous = false;  // set by the functions below, never cleared
};

// Flags (rounding.ambiguous) an entry whose region's texels float rounding of its side, or the float
// evaluation of its position, could change.
void note_region(const RegionEntry& entry, int n, RegionMode mode, Rounding& rounding);

// Step 3. Invalid receivers and NaN depths: lit (0, 0, 0, lit). `iterations` is
// bounded by kRefineMaxIterations; 0 gives PCSS's search width as is.
// `structure`: which square's min refinement reads (search_min_square, or mip_search_cover);
// `refinements` (optional): how many squares' mins it read. `area_edges` (PN_AREA_EDGES, issue 51):
// the squares read cover area_cover instead of pcss_square. `gradient` (pnSearchEntryMipPlane): the
// receiver plane's (depth a texel along u, v): lit when zmin is not below the plane's highest
// threshold over the square's texels q, d - bias + g · (q + ½ − (u, v)), taken at most d - bias.
RegionEntry search_entry(const DepthScan& scan, const LightModel& light, const RegionReceiver& receiver, double bias,
                         int iterations, Rounding* rounding = nullptr, Structure structure = Structure::pyramid,
                         int* refinements = nullptr, bool area_edges = false,
                         std::array<double, 2> gradient = {0.0, 0.0});

// Step 4, from the search entry and the blocker mean of its pixel.
RegionEntry filter_entry(const LightModel& light, const RegionEntry& search, double blocker_mean, bool has_blocker,
                         double filter_scale);

// SPEC §4.7 Step 3's property: whether some texel can shadow the receiver — a texel
// at depth z < d - bias inside pcss_square(u, v, blocker_window_texels(d, z)).
// Every such texel lies in PCSS's search square and, the blocker window being
// decreasing in z, in every refined square: a "lit" decision that reads a square
// covering the region never misses it. `rounding` flags texels whose membership
// or comparison lies within float rounding of flipping.
bool shadowing_blocker(const DepthScan& scan, const LightModel& light, const RegionReceiver& receiver, double bias,
                       Rounding* rounding = nullptr);

}  // namespace pn
