#include "pipeline/pcss_settings.h"

#include <cmath>
#include <exception>

#include "core/error.h"
#include "frame/setting_value.h"
#include "core/format.h"

namespace pn {

void PcssSettings::validate() const {
  const auto bad = [&](const std::string& what, double v, const char* expected) {
    return Error("technique '" + name + "': " + what + " " + format_number("%g", v) + ": expected " + expected);
  };
  if (!std::isfinite(bias) || bias < 0) throw bad("bias", bias, "a finite number >= 0");
  if (!valid_filter_scale(filter_scale)) throw bad("filter scale", filter_scale, expected_filter_scale().c_str());
  const std::string iterations = "0.." + std::to_string(PN_REFINE_MAX_ITERATIONS);  // pcss_regions.glsl's loop bound
  if (refine_iterations < 0 || refine_iterations > PN_REFINE_MAX_ITERATIONS)
    throw bad("refine iterations", refine_iterations, iterations.c_str());
  if (leaf_side < 1 || leaf_side > 8192) throw bad("leaf side", leaf_side, "1..8192");
  const std::string budgets = "1.." + std::to_string(PN_TRAVERSAL_NO_BUDGET) + " (traversal.h: a budget that never binds)";
  if (node_budget < 1 || node_budget > PN_TRAVERSAL_NO_BUDGET) throw bad("node budget", node_budget, budgets.c_str());
  if (leaf_divisor < 0 || leaf_divisor > 8192) throw bad("leaf divisor", leaf_divisor, "0 (off) or 1..8192");
  const std::string grids = "0 (off) or 1.." + std::to_string(PN_GRID_MAX_CELLS);  // traversal.h's loop bound
  if (grid < 0 || grid > PN_GRID_MAX_CELLS) throw bad("grid", grid, grids.c_str());
  if (grid > 0 && structure != Structure::mip)
    throw Error("technique '" + name + "': grid: expected structure=mip (the grid reads the aligned min/max mip chain)");
  const std::string tiles = "0 (off) or 1.." + std::to_string(kReuseMaxTile);  // reuse.glsl
  if (search_tile < 0 || search_tile > kReuseMaxTile) throw bad("search reuse tile", search_tile, tiles.c_str());
  if (filter_tile < 0 || filter_tile > kReuseMaxTile) throw bad("filter reuse tile", filter_tile, tiles.c_str());
  for (float s : {sigma1, sigma2, sigma3})
    if (!(s >= 0) || !std::isfinite(s)) throw bad("similarity bound", s, "a finite number >= 0");
  const bool vogel = blockers == Estimator::vogel || occlusion == Estimator::vogel;
  if (vogel && (blockers != occlusion || staged || one_call(*this) != OneCall::vogel))
    throw Error("technique '" + name + "': the Vogel disk runs only as its one call (pnVogelPcss): expected "
                "blockers=vogel with occlusion=vogel, refine 0, no reuse, no blur, stages off");
  if (!std::isfinite(receiver_plane_tan) || receiver_plane_tan < 0)
    throw bad("receiver plane tangent", receiver_plane_tan, "0 (off) or a finite number > 0");
  const std::optional<OneCall> call = one_call(*this);
  if (receiver_plane_tan > 0 && (staged || !call)) {
    // Name what asked for the staged passes (issue 54 X13: `fast:blur=on` blamed receiver-plane and
    // stages, neither given — `fast` has the plane by default).
    const std::string why = blur ? "blur=on needs the staged passes (the blur reads neighbours)"
                            : search_tile > 0 || filter_tile > 0
                                ? "reuse needs the staged passes (a tile shares its neighbours' results)"
                            : staged ? "stages=on runs the staged passes"
                                     : "these estimators and structures are no one call (fast, exact, poisson, vogel "
                                       "or hqepcss: pnFastPcss, pnExactPcss, pnPoissonPcss, pnVogelPcss, pnHqepcss)";
    throw Error("technique '" + name + "': " + why + ", which take no receiver plane: add receiver-plane=off");
  }
  // HQEPCSS's filter is always an exact square; Fast PCSS's windows are the paper's integer squares.
  if (edges.value_or(false) && !has_area_squares(*this))
    throw Error("technique '" + name + "': edges=area: expected exact PCSS, HQEPCSS (pnExactPcss, pnHqepcss, or "
                "their staged passes) or Fast PCSS over exact regions (pnFastPcss, or its staged passes: "
                "region=exact); the other techniques have no squares (docs/area-regions.md)");
  // poisson_pcss.glsl's disk array, or vogel_pcss.glsl's loop bound
  const int most = vogel ? kVogelMaxSamples : kPoissonMaxSamples;
  const std::string samples = "1.." + std::to_string(most);
  if (blocker_samples < 1 || blocker_samples > most) throw bad("blocker samples", blocker_samples, samples.c_str());
  if (filter_samples < 1 || filter_samples > most) throw bad("filter samples", filter_samples, samples.c_str());
  // Checked with blur off too (issue 39 C22): a setting given is a setting meant.
  try {
    blur_params.validate();
  } catch (const Error& e) {
    throw Error("technique '" + name + "': " + e.what());
  }
}

bool has_area_squares(const PcssSettings& s) {
  const std::optional<OneCall> call = one_call(s);
  return call == OneCall::exact || call == OneCall::hqepcss || (call == OneCall::fast && s.region == RegionMode::exact);
}

bool PcssSettings::area_edges() const {
  return edges.value_or(has_area_squares(*this));
}

std::optional<OneCall> one_call(const PcssSettings& s) {
  if (s.search_tile > 0 || s.filter_tile > 0 || s.blur) return std::nullopt;
  if (s.structure == Structure::mip && s.blockers == Estimator::traversal && s.occlusion == Estimator::traversal)
    return OneCall::fast;
  if (s.blockers == Estimator::poisson && s.occlusion == Estimator::poisson && s.refine_iterations == 0)
    return OneCall::poisson;
  if (s.blockers == Estimator::scan && s.occlusion == Estimator::scan && s.refine_iterations == 0)
    return OneCall::exact;
  if (s.blockers == Estimator::vogel && s.occlusion == Estimator::vogel && s.refine_iterations == 0)
    return OneCall::vogel;
  const LeafMode blocker_leaves = s.blocker_leaf_mode.value_or(s.leaf_mode);
  if (s.structure == Structure::pyramid && s.blockers == Estimator::traversal && blocker_leaves == LeafMode::min &&
      s.occlusion == Estimator::scan)
    return OneCall::hqepcss;
  return std::nullopt;
}

bool shipped_call_settings(const PcssSettings& s) {
  const std::optional<OneCall> call = one_call(s);
  if (!call || *call == OneCall::exact) return false;
  PcssSettings d = *call == OneCall::fast      ? fast_pcss()
                   : *call == OneCall::poisson ? poisson_pcss()
                   : *call == OneCall::vogel   ? vogel_pcss()
                                               : hqepcss();
  if (*call == OneCall::fast && sampled_leaves(s.leaf_mode)) {  // the work budget: the engine form's defines
    d.leaf_divisor = s.leaf_divisor;
    d.leaf_mode = s.leaf_mode;
  }
  const auto blocker_leaves = [](const PcssSettings& x) { return x.blocker_leaf_mode.value_or(x.leaf_mode); };
  return s.filter_scale == d.filter_scale && s.refine_iterations == d.refine_iterations && s.region == d.region &&
         s.structure == d.structure && s.depth_sums == d.depth_sums && s.leaf_side == d.leaf_side &&
         s.leaf_divisor == d.leaf_divisor && s.grid == d.grid && s.leaf_mode == d.leaf_mode &&
         blocker_leaves(s) == blocker_leaves(d) && s.node_budget == d.node_budget &&
         s.blocker_samples == d.blocker_samples && s.filter_samples == d.filter_samples;
}

PcssSettings exact_pcss() {
  PcssSettings s;
  s.name = "exact";
  s.refine_iterations = 0;
  s.region = RegionMode::exact;
  s.blockers = s.occlusion = Estimator::scan;
  s.search_tile = s.filter_tile = 0;
  s.blur = false;
  s.staged = true;  // llvmpipe's loop cap (PcssSettings::staged); exact:stages=off runs pnExactPcss
  return s;
}

PcssSettings poisson_pcss() {
  PcssSettings s = exact_pcss();
  s.name = "poisson";
  s.staged = false;
  s.blockers = s.occlusion = Estimator::poisson;
  return s;
}

PcssSettings vogel_pcss() {
  PcssSettings s = poisson_pcss();
  s.name = "vogel";
  s.blockers = s.occlusion = Estimator::vogel;
  s.blocker_samples = kVogelBlockerSamples;
  s.filter_samples = kVogelPcfSamples;
  return s;
}

PcssSettings hqepcss() {
  PcssSettings s = exact_pcss();
  s.name = "hqepcss";  // staged as exact PCSS is; hqepcss:stages=off runs pnHqepcss
  s.refine_iterations = kHqepcssRefineIterations;
  s.region = RegionMode::window;
  s.blockers = Estimator::traversal;
  s.leaf_side = kHqepcssLeafSide;
  s.leaf_mode = LeafMode::min;
  return s;
}

PcssSettings fast_paper_pcss() {
  PcssSettings s;
  s.name = "fast-paper";
  return s;
}

PcssSettings fast_pcss() {
  // Chosen with `penumbra bench pipeline` (docs/benchmarks.md, "Choosing Fast PCSS's defaults"):
  // closest to the ray-traced truth and fastest on llvmpipe of the settings measured.
  PcssSettings s = fast_paper_pcss();
  s.name = "fast";
  s.structure = Structure::mip;
  s.region = RegionMode::exact;
  s.depth_sums = DepthSums::midpoint;
  s.refine_iterations = kFastPcssRefineIterations;
  s.leaf_side = kFastPcssLeafSide;
  s.leaf_divisor = kFastPcssLeafDivisor;  // the work budget (fast_pcss.h): leaves of at least the region's side / 12,
  s.leaf_mode = kFastPcssLeafMode;        // each of 4 samples
  s.search_tile = s.filter_tile = 0;
  s.blur = false;
  s.blur_params.adaptive = true;  // when switched on (fast-blur): the radius follows the filter size
  return s;
}

PcssSettings shipped_fast_pcss() {
  PcssSettings s = fast_pcss();
  s.receiver_plane_tan = kShippedReceiverPlaneTan;
  return s;
}

PcssSettings fast_pcss_all_off() {
  PcssSettings s = fast_pcss();
  s.name = "fast-all-off";
  s.refine_iterations = 0;
  s.leaf_side = 1;
  s.leaf_divisor = 0;  // leaves of side 1 at every width
  s.leaf_mode = LeafMode::sampled;
  s.depth_sums = DepthSums::table;  // exact blocker sums: the mip chain's traversal at leaf 1 is brute force
  s.search_tile = s.filter_tile = 0;
  s.region = RegionMode::exact;
  s.blur = false;
  return s;
}

const std::vector<std::string>& pcss_setting_keys() {
  static const std::vector<std::string> keys{"refine", "region", "structure", "depth-sums", "leaf-divisor", "grid", "blocker-leaf-mode", "leaf", "leaf-mode", "budget", "reuse",
                                             "search-tile", "filter-tile", "skip", "blur", "blur-radius",
                                             "blur-sigma", "blur-depth-aware", "blur-depth-tolerance", "blur-adaptive", "bias", "c", "sigma1", "sigma2", "sigma3",
                                             "blockers", "occlusion", "blocker-samples", "filter-samples", "stages",
                                             "receiver-plane", "edges"};
  return keys;
}

void set_pcss_setting(PcssSettings& s, const std::string& key, const std::string& value) {
  const auto bad = [&](const char* expected) { return bad_setting_value(s.name, key, value, expected); };
  const auto integer = [&] { return setting_integer(s.name, key, value); };
  const auto real = [&] { return setting_real(s.name, key, value); };
  const auto on_off = [&] {
    if (value == "on") return true;
    if (value == "off") return false;
    throw bad("on or off");
  };
  const auto leaf_mode = [&] {
    if (value == "sampled") return LeafMode::sampled;
    if (value == "min") return LeafMode::min;
    if (value == "ramp") return LeafMode::ramp;
    if (value == "quad") return LeafMode::quad;
    throw bad("sampled, quad, min or ramp");
  };
  const auto estimator = [&] {
    if (value == "scan") return Estimator::scan;
    if (value == "traversal") return Estimator::traversal;
    if (value == "poisson") return Estimator::poisson;
    if (value == "vogel") return Estimator::vogel;
    throw bad("scan, traversal, poisson or vogel");
  };
  if (key == "refine") s.refine_iterations = integer();
  else if (key == "region") {
    if (value == "window") s.region = RegionMode::window;
    else if (value == "exact") s.region = RegionMode::exact;
    else if (value == "centred") s.region = RegionMode::centred;
    else throw bad("window, exact or centred");
  } else if (key == "structure") {
    if (value == "pyramid") s.structure = Structure::pyramid;
    else if (value == "mip") s.structure = Structure::mip;
    else throw bad("pyramid or mip");
  } else if (key == "depth-sums") {
    if (value == "table") s.depth_sums = DepthSums::table;
    else if (value == "midpoint") s.depth_sums = DepthSums::midpoint;
    else throw bad("table or midpoint");
  } else if (key == "leaf") s.leaf_side = integer();
  else if (key == "leaf-divisor") s.leaf_divisor = integer();
  else if (key == "grid") s.grid = integer();
  else if (key == "blocker-leaf-mode") s.blocker_leaf_mode = leaf_mode();
  else if (key == "leaf-mode") s.leaf_mode = leaf_mode();
  else if (key == "budget") s.node_budget = integer();
  else if (key == "reuse") {
    const bool on = on_off();
    s.search_tile = on ? 4 : 0;
    s.filter_tile = on ? 2 : 0;
  } else if (key == "search-tile") s.search_tile = integer();
  else if (key == "filter-tile") s.filter_tile = integer();
  else if (key == "skip") {
    if (value == "list") s.skip = WorkSkip::list;
    else if (value == "branch") s.skip = WorkSkip::branch;
    else throw bad("list or branch");
  } else if (key == "blur") s.blur = on_off();
  else if (key == "blur-radius") s.blur_params.radius = integer();
  else if (key == "blur-sigma") s.blur_params.sigma = real();
  else if (key == "blur-depth-aware") s.blur_params.depth_aware = on_off();
  else if (key == "blur-depth-tolerance") s.blur_params.depth_tolerance = real();
  else if (key == "blur-adaptive") s.blur_params.adaptive = on_off();
  else if (key == "bias") s.bias = real();
  else if (key == "c") s.filter_scale = real();
  else if (key == "sigma1") s.sigma1 = real();
  else if (key == "sigma2") s.sigma2 = real();
  else if (key == "sigma3") s.sigma3 = real();
  else if (key == "blockers") s.blockers = estimator();
  else if (key == "occlusion") s.occlusion = estimator();
  else if (key == "blocker-samples") s.blocker_samples = integer();
  else if (key == "filter-samples") s.filter_samples = integer();
  else if (key == "stages") s.staged = on_off();
  else if (key == "receiver-plane") s.receiver_plane_tan = setting_receiver_plane(s.name, key, value);
  else if (key == "edges") {
    if (value == "texel") s.edges = false;
    else if (value == "area") s.edges = true;
    else throw bad("texel or area");
  }
  else throw unknown_setting(s.name, key, pcss_setting_keys());
}

}  // namespace pn
