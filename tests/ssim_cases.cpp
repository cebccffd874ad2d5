// Writes image pairs and penumbra's SSIM of each for tests/ssim_skimage.py,
// which recomputes them with scikit-image and compares.
// Usage: penumbra_ssim_cases OUT_DIR. Files: case_K_a.f64, case_K_b.f64 (row-major
// doubles), cases.txt with one line per case: "K width height ssim".
#include <cstdio>
#include <fstream>
#include <iostream>

#include "fixture_images/texture_fixture.h"
#include "metrics/ssim.h"
#include "reference/blur_reference.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: penumbra_ssim_cases OUT_DIR\n";
    return 2;
  }
  const std::string out = argv[1];
  std::ofstream list(out + "/cases.txt");
  int k = 0;
  const auto write = [&](const pn::Image& a, const pn::Image& b) {
    for (const auto& [image, suffix] : {std::pair{&a, "a"}, std::pair{&b, "b"}}) {
      std::ofstream f(out + "/case_" + std::to_string(k) + "_" + suffix + ".f64", std::ios::binary);
      for (float v : image->texels) {
        const double d = v;
        f.write(reinterpret_cast<const char*>(&d), sizeof d);
      }
    }
    char line[128];
    std::snprintf(line, sizeof line, "%d %d %d %.17g\n", k, a.width, a.height, pn::ssim(a, b));
    list << line;
    ++k;
  };
  using pn::find_fixture;
  using pn::generate_fixture;
  for (auto [w, h] : {std::pair{11, 11}, std::pair{64, 64}, std::pair{100, 37}}) {
    const pn::Image noise = generate_fixture(find_fixture("noise"), w, h);
    const pn::Image boxes = generate_fixture(find_fixture("boxes"), w, h);
    write(noise, pn::blur_reference(noise, {3, 1.0, false, 0.0}));
    write(boxes, pn::blur_reference(boxes, {2, 0.8, false, 0.0}));
    write(generate_fixture(find_fixture("ramp"), w, h), generate_fixture(find_fixture("step_edge"), w, h));
    write(generate_fixture(find_fixture("checker"), w, h), generate_fixture(find_fixture("fine_checker"), w, h));
    write(generate_fixture(find_fixture("constant"), w, h), generate_fixture(find_fixture("constant"), w, h));
    write(noise, boxes);
  }
  return list ? 0 : 1;
}
