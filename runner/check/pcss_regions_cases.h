// The pcss_regions check's groups of cases and what they share;
// run_pcss_regions_check (pcss_regions_check.cpp, which states every
// tolerance) runs them in order.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "check/pcss_regions_check.h"
#include "pass_runners/pcss_regions_pass.h"
#include "reference/pcss_regions_reference.h"

namespace pn::pcss_regions_cases {

inline constexpr int kMapSize = 64;
inline constexpr float kDepthShift = 1.0f;  // fixture depths + 1: finite texels in [1, 2]
inline constexpr double kNear = 0.5;
inline constexpr double kUlp = 1.0 / 8388608.0;        // 2^-23
inline constexpr double kSideTolerance = 64.0 * kUlp;  // as the light_model check
inline constexpr double kAmbiguity = 1e-5;             // relative: a decision this close is left out
inline constexpr int kSceneMap = 256, kSceneScreen = 128;
// The boxes scene's far walls need render's resolution: there the paper's lit decision
// (the rounded-down window) marked 258 shadowable receivers lit — issue 11 item 6's scribbles.
inline constexpr int kBoxesMap = 512, kBoxesScreen = 512;
inline constexpr float kBiases[] = {0.0f, 0.01f};
inline constexpr RegionMode kModes[] = {RegionMode::window, RegionMode::exact, RegionMode::centred};
inline constexpr float kNan = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();

const char* mode_name(RegionMode mode);
std::vector<int> iteration_counts();  // 0, 1, the pipeline's default, beyond the loop bound

struct NamedLight {
  std::string name;
  LightModel light;
};
std::vector<NamedLight> fixture_lights(int n);

// The expected and observed values of one group of queries, compared as rows (push_group).
struct EntryGroup {
  std::vector<float> e_decisions, o_decisions;  // lit (1/0), d, x, y
  std::vector<float> e_sides, o_sides;          // s of entries unlit on both sides; -1 else
  std::vector<float> e_regions, o_regions;      // the regions of an entry as the module defines them
  std::vector<float> e_refinements, o_refinements;  // counted searches: the squares whose min was read
  long queries = 0, left_out = 0, regions_tied = 0, lit = 0;
};
// `expected_refinements` >= 0: a counted search's (PcssRegionsQuery::Kind::search_mip_counted) count too.
void add_entry(EntryGroup& g, const RegionEntry& expected, bool ambiguous, const PcssRegionsResult& o,
               int expected_refinements = -1);
// area_edges: pnEntryRect is the area square's cover (area_cover; a bound within rounding of an
// integer may take either rounding, counted as tied).
void add_regions(EntryGroup& g, const PcssRegionsResult& o, int n, RegionMode mode, bool area_edges = false);
void push_group(std::vector<CaseResult>& results, const std::string& name, const EntryGroup& g, const char* what);

// Over the mip chain every other receiver's query is the counted search (pnSearchEntryMipCounted).
std::vector<PcssRegionsQuery> search_queries(const std::vector<RegionReceiver>& receivers, RegionMode mode, int iterations,
                                             float bias, Structure structure = Structure::pyramid);

// The property case: one element per lit receiver checked, 1 where a texel can shadow it.
CaseResult property_case(const std::string& name, const std::vector<float>& violations, const LitCoverage& c,
                         const std::string& extra);
// What the CPU says of a receiver (shadowing_blocker): a texel can shadow it, and whether float
// rounding leaves that open.
struct ShadowingTruth {
  bool shadowable = false;
  bool ambiguous = false;
};
ShadowingTruth shadowing_truth(const DepthScan& scan, const LightModel& light, const RegionReceiver& r, double bias);
// Every receiver's, once for the searches of one scene that share them (the brute force over each
// search square is most of the check's time).
std::vector<ShadowingTruth> shadowing_truths(const DepthScan& scan, const LightModel& light,
                                             const std::vector<RegionReceiver>& receivers, double bias);
// Adds one GPU result to the property's counts (SPEC §4.7 Step 3); `truth` is asked only for a lit
// receiver unless count_shadowable.
void count_receiver(LitCoverage& c, std::vector<float>& violations, const RegionReceiver& r,
                    const PcssRegionsResult& observed, const std::function<ShadowingTruth()>& truth,
                    bool count_shadowable);
// The property over a whole G-buffer's GPU results (in the order of `receivers`, `truths` theirs).
LitCoverage count_lit_coverage(const std::string& name, const std::vector<RegionReceiver>& receivers,
                               const std::vector<ShadowingTruth>& truths, const std::vector<PcssRegionsResult>& observed);

// Search queries compared, and of them left out for rounding: the last case's share.
struct SearchTally {
  long searched = 0, left_out = 0;
};

// pcss_regions_fixture_cases.cpp: search entries on every texture fixture (and the property
// there), then filter entries and given entries with odd sides and centres.
void fixture_cases(const CheckEnvironment& env, const PcssRegionsQueryPass& pass, std::vector<CaseResult>& results,
                   SearchTally& tally);

// pcss_regions_scene_cases.cpp: the tall-blocker scene's own map and G-buffer in every mode, and
// the property on the boxes scene's far field.
void scene_cases(const CheckEnvironment& env, const PcssRegionsQueryPass& pass, std::vector<CaseResult>& results,
                 SearchTally& tally);

}  // namespace pn::pcss_regions_cases
