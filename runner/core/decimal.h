// A run of decimal digits as an int, saturating: compiler logs and #line
// markers carry numbers the user's source chose (`#line 99999999999`), and a
// number beyond int must map to "far away", not throw out of std::stoi.
#pragma once

#include <climits>
#include <string>

namespace pn {

// `digits`: one or more of 0-9 (what the callers' regexes matched); INT_MAX when the value exceeds it.
inline int saturating_decimal(const std::string& digits) {
  long long value = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') break;
    value = value * 10 + (c - '0');
    if (value > INT_MAX) return INT_MAX;
  }
  return static_cast<int>(value);
}

}  // namespace pn
