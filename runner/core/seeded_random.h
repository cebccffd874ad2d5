// Deterministic random numbers (check cases, sample tables): std::mt19937's raw output is
// fixed by the C++ standard (unlike its distributions), so the same seed gives
// the same cases with every compiler and standard library.
#pragma once

#include <cstdint>
#include <random>

namespace pn {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint32_t seed) : engine_(seed) {}

  // Uniform in [lo, hi] (inclusive), by rejection so there is no modulo bias.
  int uniform_int(int lo, int hi) {
    const std::uint32_t span = static_cast<std::uint32_t>(hi - lo) + 1u;
    const std::uint32_t limit = span == 0 ? 0 : (0xffffffffu / span) * span;
    std::uint32_t x = engine_();
    while (limit != 0 && x >= limit) x = engine_();
    return lo + static_cast<int>(span == 0 ? x : x % span);
  }

  // Uniform in [lo, hi) with 24 random bits.
  float uniform_float(float lo, float hi) {
    return lo + (hi - lo) * (static_cast<float>(engine_() >> 8) * (1.0f / 16777216.0f));
  }

 private:
  std::mt19937 engine_;
};

}  // namespace pn
