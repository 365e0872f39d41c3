#!/usr/bin/python3
"""Reference SSIM and MS-SSIM values for src/core/tests/metrics_reference_test.cpp.

Computes, once, the values the C++ metrics (src/core/metrics.cpp) must reproduce on a few
textured image pairs, with an implementation that shares no code with ours:

- SSIM: scikit-image's structural_similarity (Gaussian window, sigma 1.5, 11 taps, population
  covariance, K1 = 0.01, K2 = 0.03, data range 1), the configuration of Wang et al. (2004).
- MS-SSIM: Wang, Simoncelli and Bovik (2003) as in Wang's reference code (msssim.m): at each scale
  the mean contrast-structure term over the valid windows, at the coarsest scale the mean SSIM
  (luminance times contrast-structure per window), 2x2 mean downsampling between scales
  (scikit-image's downscale_local_mean), weights 0.0448, 0.2856, 0.3001, 0.2363, 0.1333. The
  per-scale statistics come from scipy.ndimage filters, and the script checks that the first
  scale's mean SSIM equals scikit-image's SSIM. Our documented rule for small images (as many
  scales as keep an 11-pixel window, weights renormalised) is applied the same way.

The images are made from integers only (a triangle-wave pattern plus a 32-bit hash), so this
script and the C++ test build bit-identical inputs; each image's integer sum is written too and
the test checks it. Run it to regenerate the header (needs Debian's python3-skimage, which is not
a build dependency):

    apt-get install python3-skimage
    /usr/bin/python3 scripts/ssim-reference-values.py > src/core/tests/ssim_reference_values.h
"""

import numpy as np
from scipy import ndimage
from skimage.metrics import structural_similarity
from skimage.transform import downscale_local_mean

MASK = 0xFFFFFFFF
WEIGHTS = [0.0448, 0.2856, 0.3001, 0.2363, 0.1333]
C1 = 0.01**2
C2 = 0.03**2


def hash32(x, y, seed):
    h = (x * 374761393 + y * 668265263 + seed * 2246822519) & MASK
    h = ((h ^ (h >> 13)) * 1274126177) & MASK
    return h ^ (h >> 16)


def tri(v, period):
    return abs(v % period - period // 2)


def base_level(x, y):
    # 30..211: three triangle waves of different periods and directions plus hashed grain.
    return 30 + 3 * tri(x, 40) + 4 * tri(y, 28) + 2 * tri(x + y, 18) + hash32(x, y, 1) % 48


def clamp(v):
    return max(0, min(255, v))


# The test images, as 8-bit levels. Each kind is a function of (x, y); the C++ test mirrors them.
KINDS = {
    "base": base_level,
    # Shifted a pixel, darker, with different grain: structure, contrast and luminance all differ.
    "shifted": lambda x, y: clamp(3 * base_level(x + 1, y) // 4 + 45 + hash32(x, y, 2) % 33 - 16),
    # Same structure, brighter: mostly a luminance difference.
    "brighter": lambda x, y: clamp(9 * base_level(x, y) // 10 + 60),
    # Coarse blocks of the base: fine structure lost, coarse structure kept.
    "blocky": lambda x, y: base_level(x - x % 4, y - y % 4),
}

# (width, height, reference kind, test kind). 192x176 has all five scales, 64x48 three (the
# renormalised weights), 80x80 four.
PAIRS = [
    (192, 176, "base", "shifted"),
    (192, 176, "base", "brighter"),
    (192, 176, "base", "blocky"),
    (64, 48, "base", "shifted"),
    (80, 80, "base", "brighter"),
]


def levels(kind, w, h):
    f = KINDS[kind]
    return np.array([[f(x, y) for x in range(w)] for y in range(h)], dtype=np.int64)


def as_image(lv):
    # The C++ test stores level / 255 as float.
    return (lv.astype(np.float64) / 255.0).astype(np.float32).astype(np.float64)


def gaussian_window():
    x = np.arange(11) - 5.0
    g = np.exp(-(x * x) / (2 * 1.5 * 1.5))
    g /= g.sum()
    return np.outer(g, g)


def ssim_maps(a, b):
    """Luminance and contrast-structure maps over the windows that fit (valid region)."""
    win = gaussian_window()

    def filt(img):
        # correlate centres the window; crop the 5-pixel border where it would leave the image.
        return ndimage.correlate(img, win, mode="constant")[5:-5, 5:-5]

    ma, mb = filt(a), filt(b)
    va = filt(a * a) - ma * ma
    vb = filt(b * b) - mb * mb
    cov = filt(a * b) - ma * mb
    lum = (2 * ma * mb + C1) / (ma * ma + mb * mb + C1)
    cs = (2 * cov + C2) / (va + vb + C2)
    return lum, cs


def ms_ssim(a, b):
    h, w = a.shape
    scales = 1
    while scales < 5 and (w >> scales) >= 11 and (h >> scales) >= 11:
        scales += 1
    weights = np.array(WEIGHTS[:scales])
    weights /= weights.sum()
    result = 1.0
    for s in range(scales):
        lum, cs = ssim_maps(a, b)
        term = np.mean(lum * cs) if s + 1 == scales else np.mean(cs)
        result *= max(term, 0.0) ** weights[s]
        if s + 1 < scales:
            a = downscale_local_mean(a, (2, 2))
            b = downscale_local_mean(b, (2, 2))
    return result


def main():
    rows = []
    for w, h, ref_kind, test_kind in PAIRS:
        ra, rb = levels(ref_kind, w, h), levels(test_kind, w, h)
        a, b = as_image(ra), as_image(rb)
        s = structural_similarity(a, b, data_range=1.0, gaussian_weights=True, sigma=1.5,
                                  use_sample_covariance=False)
        lum, cs = ssim_maps(a, b)
        assert abs(np.mean(lum * cs) - s) < 1e-12, "the per-scale statistics must match skimage"
        rows.append((w, h, ref_kind, test_kind, int(ra.sum()), int(rb.sum()), s, ms_ssim(a, b)))

    print("// Generated by scripts/ssim-reference-values.py (scikit-image %s); do not edit."
          % __import__("skimage").__version__)
    print("// Width, height, reference and test image kinds, their level sums, SSIM, MS-SSIM.")
    print("#pragma once\n")
    print("namespace ssim_reference {\n")
    print("struct Case {\n    int width;\n    int height;\n    const char* reference;\n"
          "    const char* test;\n    long long referenceSum;\n    long long testSum;\n"
          "    double ssim;\n    double msSsim;\n};\n")
    print("inline constexpr Case kCases[] = {")
    for w, h, rk, tk, rs, ts, s, ms in rows:
        print('    {%d, %d, "%s", "%s", %d, %d, %.12f, %.12f},' % (w, h, rk, tk, rs, ts, s, ms))
    print("};\n")
    print("} // namespace ssim_reference")


if __name__ == "__main__":
    main()
