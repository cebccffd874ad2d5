// Upper bounds on what the user may ask for, checked before any allocation or GL work.
#pragma once

#include <cstddef>
#include <string>

#include "core/error.h"

namespace pn {

// The most entries a list option (sizes, leaf sizes, widths, scenes, techniques) may hold:
// each entry is a whole measurement, so more is a typo, not a bench.
inline constexpr size_t kMaxListEntries = 32;

// Throws Error("<what>: <count> entries: expected 1..<most>") for a list the user gave.
inline void require_list_length(const std::string& what, size_t count, size_t most = kMaxListEntries) {
  if (count < 1 || count > most)
    throw Error(what + ": " + std::to_string(count) + " entries: expected 1.." + std::to_string(most));
}

}  // namespace pn
