#include "reference/backprojection_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "backprojection.h"

namespace pn {

BackprojectionSamplePoint backprojection_sample(int k, int side) {
  const std::uint32_t h = PN_BACKPROJECTION_HASH(static_cast<std::uint32_t>(k));
  const int bits = PN_BACKPROJECTION_JITTER_BITS;
  const float unit = 1.0f / static_cast<float>(1 << bits);
  const float jx = static_cast<float>(h >> (32 - bits)) * unit;
  const float jy = static_cast<float>(h & ((1u << bits) - 1u)) * unit;
  const float scale = 1.0f / static_cast<float>(side * side);
  const int column = k / side, row = k % side;  // its stratum; fine column k, fine row row · side + column
  return {(static_cast<float>(k) + jx) * scale - 0.5f, (static_cast<float>(row * side + column) + jy) * scale - 0.5f};
}

namespace {

// The ray from the receiver toward one light sample, in the light's frame: its texel coordinate
// on one axis at depth z, and the depth at which it reaches a texel coordinate.
struct RayAxis {
  const LightModel* light;
  double receiver_world;  // the receiver's lateral position on this axis (world units, from the axis)
  double target;          // area light: the light point's lateral position; sun: its spread (per unit depth);
                          // the ray's texel coordinate grows from the receiver's toward the light when > 0
  double depth;           // dP
  double centre;          // N / 2: the axis in texels

  // The ray's texel coordinate at depth z (the projection of its point at that depth).
  double texel_at(double z) const {
    if (light->orthographic()) return centre + (receiver_world + target * (depth - z)) / light->texel_world;
    const double c = light->near_plane_width() / (light->near_plane * light->map_size);
    return centre + (receiver_world + (target - receiver_world) * (depth - z) / depth) / (z * c);
  }
  // The depth z at which the ray's texel coordinate is `u`.
  double depth_at(double u) const {
    const double b = u - centre;
    if (light->orthographic()) return depth - (b * light->texel_world - receiver_world) / target;
    const double c = light->near_plane_width() / (light->near_plane * light->map_size);
    return target / (b * c + (target - receiver_world) / depth);
  }
};

// The rays of light sample l from the receiver at lateral (px, py), depth `depth`.
struct SampleRays {
  RayAxis x, y;
};
SampleRays sample_rays(const LightModel& light, double px, double py, double depth, BackprojectionSamplePoint l) {
  // Area light: the light point at depth 0; the sun: the spread per unit depth.
  const double scale = light.orthographic() ? light.spread : light.width, centre = 0.5 * light.map_size;
  return {{&light, px, l.x * scale, depth, centre}, {&light, py, l.y * scale, depth, centre}};
}

// The texels [first, last] of one axis the ray can cross between the receiver (u0) and its point
// at `floor_depth` (nothing lies nearer the light: only to skip the other texels).
void texel_span(const RayAxis& ray, double u0, double floor_depth, double margin, int n, int& first, int& last) {
  const double far = ray.texel_at(floor_depth);
  first = std::max(0, static_cast<int>(std::floor(std::min(u0, far) - 2 * margin)) - 1);
  last = std::min(n - 1, static_cast<int>(std::floor(std::max(u0, far) + 2 * margin)) + 1);
}

// The map's nearest finite depth (+Inf: none).
double nearest_depth(const Image& map) {
  double nearest = INFINITY;
  for (const float d : map.texels)
    if (std::isfinite(d)) nearest = std::min(nearest, static_cast<double>(d));
  return nearest;
}

// Whether the ray lies inside texel (i, j)'s column, its square grown by m (shrunk for m < 0), at
// some depth of [z0, z1]. Each axis's texel coordinate is monotone in depth (or constant: a ray
// along the axis of projection), so the depths inside the square form an interval; if it meets
// [z0, z1], the lowest common depth is z0 or a depth where the ray crosses one of the square's
// four edges — the candidates tested.
bool inside_column(const SampleRays& rays, int i, int j, double m, double z0, double z1) {
  if (!(z0 <= z1)) return false;
  const double lo_x = i - m, hi_x = i + 1 + m, lo_y = j - m, hi_y = j + 1 + m;
  double candidates[6] = {z0, z1, z0, z0, z0, z0};
  int count = 2;
  for (const auto& [ray, lo, hi] : {std::tuple{&rays.x, lo_x, hi_x}, std::tuple{&rays.y, lo_y, hi_y}}) {
    if (ray->target == 0.0) continue;  // its coordinate does not move along the ray
    for (const double edge : {lo, hi}) {
      const double z = ray->depth_at(edge);
      if (z > z0 && z < z1) candidates[count++] = z;
    }
  }
  for (int c = 0; c < count; ++c) {
    const double x = rays.x.texel_at(candidates[c]), y = rays.y.texel_at(candidates[c]);
    const double slack = 1e-9 * (1.0 + std::fabs(x) + std::fabs(y));  // a crossing solved at an edge
    if (x >= lo_x - slack && x <= hi_x + slack && y >= lo_y - slack && y <= hi_y + slack) return true;
  }
  return false;
}

// What both references share: every light sample's ray from the receiver, the texels it can
// cross, and the verdicts of `texel_verdict(rays, i, j, dz)` — (blocked for sure, blocked
// possibly) for texel (i, j) — counted into the interval.
template <class TexelVerdict>
BackprojectionBounds sample_verdicts(const Image& map, const LightModel& light, double u, double v, double depth,
                                     double bias, int side, double margin, double depth_margin,
                                     TexelVerdict texel_verdict) {
  BackprojectionBounds out;
  if (!(depth > 0.0) || !std::isfinite(depth)) return out;
  side = std::clamp(side, PN_BACKPROJECTION_MIN_SIDE, PN_BACKPROJECTION_MAX_SIDE);
  const int count = side * side, n = light.map_size;
  // The receiver's lateral position in the light's frame.
  const double texel = light.texel_world_at(depth);
  const double px = (u - 0.5 * n) * texel, py = (v - 0.5 * n) * texel;
  const double dz = depth_margin * depth;
  // Nothing lies nearer the light than the map's nearest texel: the texels a ray can cross lie
  // between the receiver and the ray's point at that depth (only to skip the others).
  const double nearest = nearest_depth(map);
  if (!(nearest + bias - dz < depth)) return out;
  const double floor_depth = std::max(nearest - dz, light.orthographic() ? -INFINITY : 1e-9 * depth);
  int sure = 0, possible = 0;
  for (int k = 0; k < count; ++k) {
    const SampleRays rays = sample_rays(light, px, py, depth, backprojection_sample(k, side));
    int i0, i1, j0, j1;
    texel_span(rays.x, u, floor_depth, margin, n, i0, i1);
    texel_span(rays.y, v, floor_depth, margin, n, j0, j1);
    bool blocked_sure = false, blocked_possible = false;
    for (int j = j0; j <= j1 && !blocked_sure; ++j)
      for (int i = i0; i <= i1 && !blocked_sure; ++i) {
        const auto [sure_hit, possible_hit] = texel_verdict(rays, i, j, dz);
        blocked_sure = blocked_sure || sure_hit;
        blocked_possible = blocked_possible || possible_hit;
      }
    sure += blocked_sure ? 1 : 0;
    possible += (blocked_sure || blocked_possible) ? 1 : 0;
  }
  out.visibility_hi = 1.0 - static_cast<double>(sure) / count;
  out.visibility_lo = 1.0 - static_cast<double>(possible) / count;
  out.ambiguous = possible - sure;
  return out;
}

}  // namespace

BackprojectionBounds backprojection_slab_reference(const Image& map, const Image& second, const LightModel& light,
                                                   double u, double v, double depth, double bias, int side,
                                                   double margin, double depth_margin) {
  return sample_verdicts(map, light, u, v, depth, bias, side, margin, depth_margin,
                         [&](const SampleRays& rays, int i, int j, double dz) -> std::pair<bool, bool> {
                           const double d = map.at(i, j);
                           if (!std::isfinite(d) || !(d + bias - dz < depth)) return {false, false};
                           // The slab: from d down to the second layer's depth (non-finite: to the
                           // receiver; not past d: flat), only what lies in front of the receiver.
                           const double back = std::isfinite(second.at(i, j)) ? second.at(i, j) : INFINITY;
                           const double bottom = back > d ? std::min(back, depth - bias) : d;
                           const bool thick = bottom - d > 2 * dz;
                           return {d + bias + dz < depth && inside_column(rays, i, j, -margin, thick ? d + dz : d,
                                                                          thick ? bottom - dz : d),
                                   inside_column(rays, i, j, margin, d - dz, bottom + dz)};
                         });
}

BackprojectionBounds backprojection_reference(const Image& map, const LightModel& light, double u, double v,
                                              double depth, double bias, int side, double gap, double thickness,
                                              double margin, double depth_margin) {
  const int n = light.map_size;
  const auto depth_of = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < n && j < n && std::isfinite(map.at(i, j)) ? static_cast<double>(map.at(i, j))
                                                                              : INFINITY;
  };
  return sample_verdicts(
      map, light, u, v, depth, bias, side, margin, depth_margin,
      [&](const SampleRays& rays, int i, int j, double dz) -> std::pair<bool, bool> {
        const RayAxis &rx = rays.x, &ry = rays.y;
        bool sure = false, possible = false;
        const auto decide = [&](bool possible_hit, bool sure_hit) {
          possible = possible || possible_hit;
          sure = sure || sure_hit;
        };
        const double d = depth_of(i, j);
        if (!(d + bias - dz < depth)) return {false, false};
        // The patch: where the ray is at depth d; grown by the margins (possible) and shrunk by
        // them (sure).
        const double x = rx.texel_at(d), y = ry.texel_at(d);
        const auto patch = [&](double m, double t) {
          return d + bias + t < depth && x >= i - m && x <= i + 1 + m && y >= j - m && y <= j + 1 + m;
        };
        decide(patch(margin, -dz), patch(-margin, dz));
        // The walls: on the square's edge toward each deeper neighbour, from d down to that
        // neighbour's depth when it is within gap texel widths (one surface), else down to
        // thickness · (depth - d) below d, if the neighbour is not nearer (a silhouette); never
        // past the receiver's depth less the bias.
        const double step = gap * light.texel_world_at(d);
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
          const double neighbour = depth_of(i + di, j + dj);
          if (!(neighbour > d)) continue;
          const double bottom = neighbour - d <= step ? neighbour : std::min(neighbour, d + thickness * (depth - d));
          const bool across_x = di != 0;
          const RayAxis& along = across_x ? rx : ry;  // the axis the wall stands across
          const RayAxis& other = across_x ? ry : rx;
          const double start = across_x ? u : v;
          const double edge = across_x ? (di > 0 ? i + 1 : i) : (dj > 0 ? j + 1 : j);
          const int cell = across_x ? j : i;
          // The ray meets the wall's line only when it moves toward it from the receiver.
          if (along.target == 0.0 || (along.target > 0.0) != (edge > start)) continue;
          const double z = along.depth_at(edge);
          const double other_at = other.texel_at(z);
          const auto wall = [&](double m, double t) {
            return z >= d - t && z <= std::min(bottom, depth - bias) + t && other_at >= cell - m &&
                   other_at <= cell + 1 + m;
          };
          decide(wall(margin, dz), wall(-margin, -dz));
        }
        return {sure, possible};
      });
}

}  // namespace pn
