// lowbias32 (Chris Wellons): a well-mixed, portable 32-bit integer hash, so
// seeded noise (fixtures, the truth's jitter) is identical on every platform
// and standard library.
#pragma once

#include <cstdint>

namespace pn {

constexpr std::uint32_t integer_hash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

}  // namespace pn
