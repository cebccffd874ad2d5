// A Poisson disk (poisson_disk.h) as a constant array in an engine's language — `penumbra poisson
// --lang`: GLSL for poisson_pcss.glsl's PN_POISSON_DISK_ARRAY, HLSL and MSL for the exports, C++ to
// fill a buffer or a constant block from the host.
#pragma once

#include <cstdint>
#include <string>

#include "sampling/poisson_disk.h"

namespace pn {

enum class SourceLanguage { glsl, hlsl, msl, cpp };

// "glsl", "hlsl", "msl" or "cpp"; throws Error naming --lang and the four.
SourceLanguage parse_source_language(const std::string& name);

// The points as one constant array of `name` with a comment naming the seed and the minimum
// distance: GLSL `const vec2 NAME[n] = vec2[](vec2(x, y), ...);`, HLSL `static const float2
// NAME[n] = {...};`, MSL `constant float2 NAME[n] = {...};`, C++ `constexpr float NAME[n][2] =
// {{x, y}, ...};` — every value printed to 9 significant digits (a float, exactly). Throws Error
// unless `name` is an identifier of the language that is not one of its keywords or reserved
// words (and, for GLSL, without a gl_ prefix or __).
std::string poisson_disk_source(const PoissonDisk& disk, const std::string& name, std::uint32_t seed,
                                SourceLanguage language);

// poisson_disk_source in GLSL.
std::string poisson_disk_glsl(const PoissonDisk& disk, const std::string& name, std::uint32_t seed);

}  // namespace pn
