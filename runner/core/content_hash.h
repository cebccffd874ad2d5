// The hash that names a file's exact bytes in a manifest or a header: FNV-1a 64 as 16 hex digits
// (render's and isa's manifests, the exports' list of files).
#pragma once

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>

namespace pn {

inline std::string content_hash(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  char out[17];
  std::snprintf(out, sizeof out, "%016" PRIx64, h);
  return out;
}

}  // namespace pn
