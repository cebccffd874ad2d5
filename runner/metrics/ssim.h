// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004), the quality measure of seed 000
// §5.4: 11×11 Gaussian window (sigma 1.5), K1 = 0.01, K2 = 0.03, population
// (co)variances, averaged over the pixels whose whole window lies inside the
// image — the same definition as scikit-image's
// structural_similarity(gaussian_weights=True, sigma=1.5, use_sample_covariance=False).
#pragma once

#include "core/image.h"

namespace pn {

struct SsimParams {
  int radius = 5;  // 11×11 window: int(3.5 sigma + 0.5), as scipy truncates a Gaussian
  double sigma = 1.5;
  double k1 = 0.01;
  double k2 = 0.03;
  double data_range = 1.0;  // L: the dynamic range of the values (1 for shadow maps)
};

// Mean SSIM of two single-channel images of the same size. Throws Error for
// different sizes, images smaller than the window or non-finite values.
double ssim(const Image& a, const Image& b, const SsimParams& params = {});

// The same SSIM map averaged over the pixels whose window fits and whose `mask` texel is non-zero
// (1 when there are none). Throws Error also for a mask of another size.
double ssim(const Image& a, const Image& b, const Image& mask, const SsimParams& params = {});

}  // namespace pn
