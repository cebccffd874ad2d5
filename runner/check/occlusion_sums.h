// The cases of a batch of occlusion queries (pcf, poisson_pcss): per query the
// occluder count, the count of texels or samples taken, and the occluders'
// depth sum. Counts are exact; the float sum of n non-negative depths lies
// within the rigorous relative bound (n + 1)·u·(1 + n·u), u = 2⁻²⁴, n the
// largest occluder count of the batch.
#pragma once

#include <string>
#include <vector>

#include "check/module_check.h"

namespace pn {

struct OcclusionSums {
  double occluders = 0.0, depth_sum = 0.0, taken = 0.0;  // taken: texels covered or samples
};

struct OcclusionBatch {
  std::vector<OcclusionSums> expected, observed;
  long left_out = 0;  // queries within rounding of a decision, not in the batch
};

// Two cases — "<name>: occluders, <taken>" and "<name>: depth sum" — query k at (k, 0); `left_out_why`
// names the reason a query was left out (printed with the count when there are any). None for an empty batch.
void add_occlusion_cases(std::vector<CaseResult>& results, const std::string& name, const OcclusionBatch& batch,
                         const char* taken, const char* left_out_why);

}  // namespace pn
