// Lookup by name in a registry — the module checks, the techniques, the
// shadow-map sources, the scenes and fixtures: any range of entries with a
// `name` member (const char* or std::string), searched in its order.
#pragma once

#include <iterator>
#include <string>

#include "core/error.h"

namespace pn {

// "a, b, c": every entry's name, in order, for an error that lists what exists.
template <class Range>
std::string known_names(const Range& entries) {
  std::string out;
  for (const auto& e : entries) out += (out.empty() ? "" : ", ") + std::string(e.name);
  return out;
}

// The entry called `name`, or null.
template <class Range>
const auto* find_named_or_null(const Range& entries, const std::string& name) {
  for (const auto& e : entries)
    if (name == e.name) return &e;
  return static_cast<decltype(&*std::begin(entries))>(nullptr);
}

// The entry called `name`; throws Error "<unknown>: expected one of <names>" when there is none
// (`unknown` names the input, e.g. "unknown technique 'slow'").
template <class Range>
const auto& find_named(const Range& entries, const std::string& name, const std::string& unknown) {
  if (const auto* e = find_named_or_null(entries, name)) return *e;
  throw Error(unknown + ": expected one of " + known_names(entries));
}

}  // namespace pn
