// blur: 3x3 truncated Gaussian, the baseline of the DDAA paper (Klein, section 3.1; spec
// ppaa.md "blur"). Speed reports normalise to it (blur = 100).
#pragma once

#include <array>

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa {

struct BlurParams {
    float sigma = 0.6f;                            //!< Gaussian sigma in pixels; 0.6 gives w1 = 0.2493522
    TextureFormat texture = TextureFormat::Unorm;  //!< rgba8unorm or rgba8unorm_srgb reads (kTextureDoc)
};
//! BlurParams' table (params.hpp): ranges, docs; defaults are the initialisers above.
inline constexpr std::array kBlurParams{
    real<&BlurParams::sigma>("sigma", "px", 0.05, 10,
                             "Gaussian sigma (section 3.1: 0.6); weights 1, w1 = exp(-1 / (2 sigma^2)) at the edges, "
                             "w1^2 at the corners"),
    choice<&BlurParams::texture>("texture", kTextureFormatNames, kTextureDoc),
};

//! The blur's weights from its params (spec ppaa.md "blur"): 1 at the centre, w1 at the
//! direct neighbours, w2 = w1^2 at the corners, and norm = 1 / (1 + 4 w1 + 4 w2) (the
//! spec normalises by multiplying with the reciprocal). The CPU kernel and the GPU pass
//! (ssfx/gpu/aa.hpp) both take them from here. Throws ssfx::Error for invalid params.
struct BlurWeights {
    float w1;    //!< direct neighbours: exp(-1 / (2 sigma^2))
    float w2;    //!< corners: w1^2
    float norm;  //!< 1 / (1 + 4 w1 + 4 w2)
};
BlurWeights blurWeights(const BlurParams& params);

//! Blurs RGB; alpha is copied from the centre pixel. Clamp-to-edge at the borders.
ImageRgba8 blur(ImageView<const Rgba8> in, const BlurParams& params = {}, const Exec& exec = {});
//! Writes into `out` (same size as `in`, must not alias it).
void blur(ImageView<const Rgba8> in, ImageView<Rgba8> out, const BlurParams& params = {}, const Exec& exec = {});
//! Scalar oracle: one pixel at a time, single-threaded.
ImageRgba8 blurReference(ImageView<const Rgba8> in, const BlurParams& params = {});

}  // namespace ssfx::aa
