// Soft shadows by back-projection behind the technique seam (registry entry
// `backprojection`, issues 28 and 42): backprojection.glsl's pnBackprojection
// per screen pixel (passes/backprojection_shade.comp / .frag) over the map's
// aligned min/max mip chain — the source's when it keeps one, else built —
// and, by default, over slabs down to the map's back-face layer (which the
// frame draws when the technique asks: TechniqueConfig::second_layer).
// Stages: mip chain (when built), the second layer's chain, shade. No stats.
#pragma once

#include <memory>

#include "frame/technique.h"

namespace pn {

// The registry's entry; override keys: bias (light-depth units, >= 0; default 0.02), samples
// (16, 64 or 256 light samples; default 256), tolerance (a node of depth range <= tolerance · its
// distance to the receiver stands as one patch, finite >= 0; 0: every texel; default 0.05),
// budget (nodes a pixel, 1..60000; default 4096), gap (texel widths: the depth step neighbours of
// one surface may take, joined by a wall; finite >= 0; default 3), thickness (a silhouette's wall
// reaches this share of the way from the occluder to the receiver, [0, 1]; default
// PN_BACKPROJECTION_DEFAULT_THICKNESS), layer (none, peeled or back-faces: the map's second layer,
// every texel a slab down to it — the frame draws it; gap and thickness serve only layer=none;
// default back-faces).
std::unique_ptr<TechniqueConfig> backprojection_config(const char* name);

}  // namespace pn
