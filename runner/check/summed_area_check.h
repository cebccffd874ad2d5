// What the summed_area check's two files of cases share: the rectangles'
// place in the query grid, the exact digits of a 64-bit sum, and cases whose
// every element has its own bound. summed_area_check.cpp holds the depth-sum
// table's cases, summed_area_moments_check.cpp the moments tables'.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "check/module_check.h"
#include "reference/summed_area_reference.h"

namespace pn {

inline constexpr int kSummedAreaGridWidth = 1024;  // query k at (k mod 1024, k / 1024), as query_image lays them out

// 24, 24 and 16 bits of a 64-bit sum (which = 0, 1, 2): each exact as a float.
float summed_area_digit(std::uint64_t v, int which);

// Each element within its own bound; the worst is the one closest to (or furthest beyond) its
// bound, and the case's tolerance is that element's bound. Element i is channel i mod `channels`
// of query queries[i / channels], reported at that query's place in the grid.
CaseResult summed_area_bounded_case(const std::string& name, const std::vector<double>& expected,
                                    const std::vector<float>& observed, const std::vector<double>& bounds, int channels,
                                    const std::vector<int>& queries);

// A failing case names the rectangle of its worst element.
void name_summed_area_worst_rect(CaseResult& r, const std::vector<Rect>& rects);

// The check's two halves, callable on their own (the GL tests run each on its broken copies):
// the depth-sum table's cases (summed_area_check.cpp) and the moments tables'
// (summed_area_moments_check.cpp). run_summed_area_check runs both.
std::vector<CaseResult> summed_area_depth_cases(const CheckEnvironment& env);
std::vector<CaseResult> summed_area_moments_cases(const CheckEnvironment& env);

}  // namespace pn
