// The cascades check's groups of cases and what they share; run_cascades_check
// (cascades_check.cpp, which states every tolerance) runs them in order.
#pragma once

#include <string>
#include <vector>

#include "check/module_check.h"
#include "pass_runners/cascades_query_pass.h"

namespace pn {

// One float ulp at 1 (u = 2^-24), the unit of the cases' tolerances.
inline constexpr double kCascadeUlp = 1.0 / (1 << 24);

// A case comparing two lists of values.
CaseResult row_case(const std::string& name, const std::vector<float>& expected, const std::vector<float>& observed,
                    const Tolerance& tolerance);

// cascades_math_cases.cpp: cascades.h and cascades.glsl through the query pass against the
// definitions in double, and the runner's splits (cascade_math.h) against the same.
void split_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results);
void selection_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results);
void sphere_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results);  // and the snap

// cascades_render_cases.cpp: the blend pass, and the city's cascaded hard shadow and seams.
void blend_pass_cases(const CheckEnvironment& env, std::vector<CaseResult>& results);
void city_cases(const CheckEnvironment& env, std::vector<CaseResult>& results);

// cascades_fit_cases.cpp: the runner's fit along a camera path (CPU).
void stability_cases(std::vector<CaseResult>& results);

}  // namespace pn
