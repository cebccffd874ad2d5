// A technique's override value (`name:key=value`) read as a number, with the one
// error every technique gives for a value that is not one: "technique 'NAME': KEY=VALUE:
// expected an integer" (or "a number"); and the one error for a key it does not own.
#pragma once

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "modules/receiver_plane_face.h"

namespace pn {

inline Error bad_setting_value(const std::string& technique, const std::string& key, const std::string& value,
                               const char* expected) {
  return Error("technique '" + technique + "': " + key + "=" + value + ": expected " + expected);
}

inline int setting_integer(const std::string& technique, const std::string& key, const std::string& value) {
  try {
    size_t used = 0;
    const int v = std::stoi(value, &used);
    if (used == value.size()) return v;
  } catch (const std::exception&) {
  }
  throw bad_setting_value(technique, key, value, "an integer");
}

inline float setting_real(const std::string& technique, const std::string& key, const std::string& value) {
  // Decimal only (issue 39 C15): std::stof would read 0x10 as hexadecimal.
  if (value.find_first_of("xX") != std::string::npos) throw bad_setting_value(technique, key, value, "a decimal number");
  try {
    size_t used = 0;
    const float v = std::stof(value, &used);
    if (used == value.size()) return v;
  } catch (const std::out_of_range&) {  // past float's range, or a nonzero value that underflows it
    throw bad_setting_value(technique, key, value, "a number float holds (0, or 1.2e-38 to 3.4e38 in magnitude)");
  } catch (const std::exception&) {
  }
  throw bad_setting_value(technique, key, value, "a number");
}

// `receiver-plane=off|on|TAN`: 0 (no plane), kReceiverPlaneTan, or the slope clamp as a tangent,
// finite and >= 0.
inline float setting_receiver_plane(const std::string& technique, const std::string& key, const std::string& value) {
  if (value == "off") return 0.0f;
  if (value == "on") return kReceiverPlaneTan;
  const float tan = setting_real(technique, key, value);
  if (!std::isfinite(tan) || tan < 0.0f) throw bad_setting_value(technique, key, value, "off, on or a finite tangent >= 0");
  return tan;
}

// "technique 'NAME': unknown setting 'KEY': expected k1, k2, …" (`keys`: the technique's own).
inline Error unknown_setting(const std::string& technique, const std::string& key, const std::vector<std::string>& keys) {
  std::string known;
  for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
  return Error("technique '" + technique + "': unknown setting '" + key + "': expected " + known);
}

}  // namespace pn
