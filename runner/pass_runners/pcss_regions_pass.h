// Runner side of glsl/passes/pcss_regions_query.comp: pcss_regions.glsl's search
// entry (over a pyramid), filter entry, and the regions of an entry, over a batch
// of queries.
#pragma once

#include <array>
#include <vector>

#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "modules/pcss_regions_face.h"
#include "pass_runners/query_pass.h"
#include "scene/light_model.h"
#include "shader/source_tree.h"

namespace pn {

struct PcssRegionsQuery {
  // PN_PCSS_REGIONS_QUERY_* (pcss_regions_query.h); search_mip_counted and search_mip_plane also
  // report their refinements
  enum class Kind {
    search = 0, filter = 1, entry = 2, search_mip = 3, search_mip_counted = 4, search_mip_plane = 5, search_plane = 6
  };
  Kind kind = Kind::search;
  RegionMode mode = RegionMode::window;
  std::array<float, 4> input{};  // search: receiver (u, v, d, valid); filter: search entry; entry: the entry
  float bias = 0.0f;             // search
  int iterations = 0;            // search
  float blocker_mean = 0.0f;     // filter
  bool has_blocker = false;      // filter
  float filter_scale = 1.0f;     // filter
  std::array<float, 2> gradient{};  // search_mip_plane, search_plane: the receiver plane's (receiver_plane.glsl)
};

struct PcssRegionsResult {
  std::array<float, 4> entry{};   // (d, x, y, s); s < 0: lit
  std::array<float, 4> rect{};    // pnEntryRect: origin x, y, size x, y
  std::array<float, 4> window{};  // pnEntryWindow in the query's mode: origin x, y, side; then pnEntryLit (1 or 0)
  std::array<float, 4> key{};     // pnEntryLinkKey in the query's mode
  int refinements = 0;            // search_mip_counted, _plane: the search's count (else 0)
};

class PcssRegionsQueryPass {
 public:
  // area_edges: the pass compiled with PN_AREA_EDGES 1 (issue 51; the module's default): the searches
  // read the area squares' covers, pnEntryRect is the cover; false: PN_AREA_EDGES 0, the integer squares.
  PcssRegionsQueryPass(const QueryDevice& device, const SourceTree& tree, bool area_edges = false);

  // One result per query; the light's map size must be the pyramid's N, and the mip
  // chain's when given (search_mip queries need it). Throws Error otherwise.
  std::vector<PcssRegionsResult> run(const DepthPyramid& pyramid, const LightModel& light,
                                     const std::vector<PcssRegionsQuery>& queries,
                                     const MinMaxMipChain* mip = nullptr) const;

 private:
  QueryPass query_;
  std::unique_ptr<DeviceTexture> no_mip_;  // bound where no chain is given
};

}  // namespace pn
