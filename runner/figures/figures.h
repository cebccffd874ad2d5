// The pictures in docs/modules/ (and docs/cli.md's techniques), drawn from what the modules compute on the
// GPU (not from the references), by `penumbra figures`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

// Writes blur.png, pyramid_levels.png, region_snapping.png, sample_table.png
// traversal_nodes.png, reuse_groups.png, pipeline_stages.png, vsm_bleeding.png, savsm_bleeding.png,
// cascades_splits.png, backprojection.png, backprojection_layers.png, techniques.png and area_edges.png into `out`
// (created if missing), all drawn before any is written; returns the paths written.
std::vector<std::filesystem::path> write_figures(const Context& context, const SourceTree& tree,
                                                 const std::filesystem::path& out);

// The names write_figures writes (blur.png, …), for probing `out` before any work (issue 39 C8, C9).
std::vector<std::string> figure_file_names();

// Fast PCSS's stages on the boxes scene, 256² (pipeline_figure.cpp).
Canvas pipeline_stages_figure(const Context& context, const SourceTree& tree);

// Light bleeding on the two-occluder map, without and with the reduction (vsm_figure.cpp).
Canvas vsm_bleeding_figure(const Context& context, const SourceTree& tree);
Canvas savsm_bleeding_figure(const Context& context, const SourceTree& tree);

// The city camera's frustum from above with its cascades' splits and spheres (cascades_figure.cpp).
Canvas cascades_splits_figure();

// The colour of a receiver's work in the node-count pictures: black through red and yellow to
// white, by the square root of its share of the most work (0..1).
Rgb node_heat(float share);

// Every technique render draws by default (the registry's `rendered` entries) and the truth, on
// the boxes scene at 128² (techniques_figure.cpp).
Canvas techniques_figure(const Context& context, const SourceTree& tree);

// One penumbra of the boxes scene at 128² on a 512² screen, zoomed: integer squares against squares
// with area-weighted edges (issue 51; area_edges_figure.cpp).
Canvas area_edges_figure(const Context& context, const SourceTree& tree);

// pnBackprojection over a boxes map under the sun: the map, the visibility, the nodes visited
// (backprojection_figure.cpp).
Canvas backprojection_figure(const Context& context, const SourceTree& tree);

// The tall blocker under a light 4x as wide: the map, its back-face layer, the truth, and
// back-projection's error without the layer and over slabs (backprojection_layers_figure.cpp).
Canvas backprojection_layers_figure(const Context& context, const SourceTree& tree);

}  // namespace pn
