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
#pragma once

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

}  // namespace ssfx::eval
