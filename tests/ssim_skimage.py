#!/usr/bin/python3
"""Recomputes penumbra's SSIM cases with scikit-image and compares.

Usage: ssim_skimage.py DIR (written by penumbra_ssim_cases). skimage's
structural_similarity with gaussian_weights=True, sigma=1.5,
use_sample_covariance=False, data_range=1 is Wang et al. 2004's definition.
Passes when every case agrees to 1e-9 (both compute in double).
"""
import sys

import numpy as np
from skimage.metrics import structural_similarity

directory = sys.argv[1]
worst = 0.0
for line in open(f"{directory}/cases.txt"):
    k, w, h, ours = line.split()
    w, h, ours = int(w), int(h), float(ours)
    a = np.fromfile(f"{directory}/case_{k}_a.f64", dtype="<f8").reshape(h, w)
    b = np.fromfile(f"{directory}/case_{k}_b.f64", dtype="<f8").reshape(h, w)
    theirs = structural_similarity(a, b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
                                   data_range=1.0)
    error = abs(ours - theirs)
    print(f"case {k} ({w}x{h}): penumbra {ours:.12f}  skimage {theirs:.12f}  |difference| {error:.2e}")
    worst = max(worst, error)
print(f"worst |difference| {worst:.2e} (tolerance 1e-9)")
sys.exit(0 if worst <= 1e-9 else 1)
