#include "reference/region_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pn {
namespace {

// Binary digits of w >= 1, most significant first.
std::vector<int> binary_digits(int w) {
  std::vector<int> digits;
  for (; w > 0; w /= 2) digits.insert(digits.begin(), w % 2);
  return digits;
}

int power_of_two(int e) { return 1 << e; }

// Steps 3–4 for one extent.
int round_extent(int w) {
  const std::vector<int> bits = binary_digits(w);
  const int floor_lb = static_cast<int>(bits.size()) - 1;  // floor(lb w)
  const bool lb_is_integer = std::count(bits.begin(), bits.end(), 1) == 1;
  if (lb_is_integer) return w;                            // Step 3
  return bits[1] == 1 ? power_of_two(floor_lb + 1)        // Step 4: second-highest bit
                      : power_of_two(floor_lb);
}

int largest_power_of_two_at_most(int n) {
  int p = 1;
  while (p * 2 <= n) p *= 2;
  return p;
}

float finite_or_zero(float v) { return std::isnan(v) ? 0.0f : v; }

struct Steps1to5 {
  int l, t, side;
};

Steps1to5 steps_1_to_5(float x, float y, float side, int e) {
  const float s = std::max(finite_or_zero(side), 0.0f);
  x = finite_or_zero(x), y = finite_or_zero(y);
  // Step 1, float32 as in the shader.
  const float lf = std::floor(x - s * 0.5f), rf = std::ceil(x + s * 0.5f);
  const float tf = std::floor(y - s * 0.5f), bf = std::ceil(y + s * 0.5f);
  // Step 2, every bound into [0, e − 1].
  const auto clamp_bound = [e](float b) { return static_cast<int>(std::clamp(b, 0.0f, static_cast<float>(e - 1))); };
  const int l = clamp_bound(lf), r = clamp_bound(rf), t = clamp_bound(tf), b = clamp_bound(bf);
  // Steps 3–4.
  const int w2 = round_extent(r - l + 1), h2 = round_extent(b - t + 1);
  // Step 5, with the cap in both branches.
  const int cap = largest_power_of_two_at_most(e);
  const int s2 = w2 == h2 ? w2 : std::min(std::min(w2, h2) * 2, cap);
  return {l, t, std::min(s2, cap)};
}

int level_of(int side) { return static_cast<int>(binary_digits(side).size()) - 1; }

}  // namespace

RegionWindow region_reference(float x, float y, float side, int n) {
  const int e = std::max(n, 1);
  const Steps1to5 r = steps_1_to_5(x, y, side, e);
  // Step 6.
  double cx = r.l + r.side / 2.0, cy = r.t + r.side / 2.0;
  // Step 7.
  if (cx + r.side / 2.0 - 1 >= e) cx = e - 1 - r.side / 2.0 + 1;
  if (cy + r.side / 2.0 - 1 >= e) cy = e - 1 - r.side / 2.0 + 1;
  return {static_cast<int>(cx - r.side / 2.0), static_cast<int>(cy - r.side / 2.0), r.side, level_of(r.side)};
}

RegionWindow region_centred_reference(float x, float y, float side, int n) {
  const int e = std::max(n, 1);
  const int s = steps_1_to_5(x, y, side, e).side;
  const auto origin = [&](float c) {
    const float o = std::floor(finite_or_zero(c) - static_cast<float>(s) * 0.5f + 0.5f);
    return static_cast<int>(std::clamp(o, 0.0f, static_cast<float>(e - s)));
  };
  return {origin(x), origin(y), s, level_of(s)};
}

}  // namespace pn
