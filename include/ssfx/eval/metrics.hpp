// Image quality metrics of the evaluation (spec ppaa.md section 3).
//
// All metrics compare the R, G and B channels (alpha is ignored) as values in [0, 1]
// (8-bit level / 255) and throw ssfx::Error when the two images differ in size.
//
//  - mse:  sum over pixels and RGB of squared differences / (H * W * 3)   (the paper's)
//  - psnr: 10 log10(1 / mse); +infinity for identical images.
//  - ssim: SSIM of Wang, Bovik, Sheikh and Simoncelli (IEEE TIP 2004, eq. 13) with uniform
//          weights on non-overlapping 8x8 windows aligned at (0, 0) (rows and columns that
//          do not fill a whole window at the right and bottom edges are left out),
//          population (co)variances, C1 = (0.01)^2, C2 = (0.03)^2; computed per channel
//          and averaged over all windows and the three channels. On the x8 pairs of the
//          quality protocol each window is exactly the footprint of one 1x pixel.
//
// The truth protocol's extra figures (docs/evaluation.md) are statistics of the per-pixel
// error e = max(|dR|, |dG|, |dB|) in 8-bit levels (0..255): its largest value and its 99th
// percentile (nearest rank: the smallest e that at least 99 % of the pixels do not exceed).
// Every metric can be restricted to a mask (e.g. the edge pixels): a pixel (x, y) counts when
// mask(x / maskScale, y / maskScale) != 0, so a 1x mask selects the 8x8 blocks of x8 images;
// SSIM then averages the windows that hold at least one counted pixel.
#pragma once

#include <cstdint>

#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"

namespace ssfx::eval {

double mse(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec = {});
//! The same over float images (AO visibility in [0, 1]): the mean of the squared differences.
double mse(ImageView<const float> a, ImageView<const float> b);
double psnrFromMse(double mse);
double psnr(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec = {});
//! Needs images of at least 8x8.
double ssim(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec = {});

//! Which pixels a metric counts (see above); an empty mask counts every pixel.
struct PixelMask {
    ImageView<const std::uint8_t> mask;
    int scale = 1;  //!< image pixels per mask pixel along each axis
};

//! The error figures over the counted pixels (psnr, maxError and p99Error are NaN and
//! pixels 0 when none counts).
struct ErrorStats {
    std::int64_t pixels = 0;  //!< pixels counted
    double psnr = 0;          //!< dB, +infinity when they are all equal
    double maxError = 0;      //!< levels
    double p99Error = 0;      //!< levels
};
ErrorStats errorStats(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask = {},
                      const Exec& exec = {});
//! SSIM over the 8x8 windows with a counted pixel (NaN when none has one).
double ssim(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask, const Exec& exec = {});
//! 1 where the two images differ in R, G or B, else 0 (e.g. the truth and the aliased input).
Image<std::uint8_t> differenceMask(ImageView<const Rgba8> a, ImageView<const Rgba8> b);

}  // namespace ssfx::eval
