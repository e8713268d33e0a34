// Supersampling resolve and resampling with the Mitchell-Netravali cubic (D. Mitchell and
// A. Netravali, "Reconstruction Filters in Computer Graphics", SIGGRAPH 1988), evaluated the
// way the DDAA paper's reference shaders do (spec ppaa.md, "ssaax2, ssaax4" and "Upsampling").
#pragma once

#include <array>

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa {

struct MitchellParams {
    float B = 1.0f / 3.0f;  //!< Mitchell-Netravali B (blur); 1/3 is their recommendation
    float C = 1.0f / 3.0f;  //!< Mitchell-Netravali C (ringing)
    //! sRGB: the input decoded to linear light, filtered there, the result encoded back.
    TextureFormat texture = TextureFormat::Unorm;
};
//! MitchellParams' table (params.hpp); the defaults are the initialisers above.
inline constexpr std::array kMitchellParams{
    real<&MitchellParams::B>("B", "", 0, 1, "Mitchell-Netravali B"),
    real<&MitchellParams::C>("C", "", 0, 1, "Mitchell-Netravali C"),
    choice<&MitchellParams::texture>("texture", kTextureFormatNames, kTextureDoc),
};

//! ssaax2's only parameter: its taps and weights are fixed (spec).
struct Ssaax2Params {
    TextureFormat texture = TextureFormat::Unorm;  //!< as MitchellParams::texture
};
inline constexpr std::array kSsaax2Params{
    choice<&Ssaax2Params::texture>("texture", kTextureFormatNames, kTextureDoc),
};

//! The 1-D Mitchell-Netravali kernel k(t) (support |t| < 2).
float mitchell(float t, float B, float C);

//! ssaax2: the 12-tap bilinear resolve of a 2x image (even sizes) to half its size.
//! Its tap positions and weights are fixed for B = C = 1/3 (spec), so it takes no params.
//! `format`: the 2x image read as an sRGB texture (ddaa2p with texture=srgb resolves in
//! linear light and encodes the result back).
ImageRgba8 ssaax2(ImageView<const Rgba8> in2x, Filtering filtering = Filtering::Gpu, const Exec& exec = {},
                  TextureFormat format = TextureFormat::Unorm);
//! Into a caller's view of half the input's size.
void ssaax2(ImageView<const Rgba8> in2x, ImageView<Rgba8> out, Filtering filtering = Filtering::Gpu,
            const Exec& exec = {}, TextureFormat format = TextureFormat::Unorm);
//! ssaax4: direct-tap Mitchell resolve of a 4x image (sizes divisible by 4).
ImageRgba8 ssaax4(ImageView<const Rgba8> in4x, const MitchellParams& params = {}, const Exec& exec = {});
void ssaax4(ImageView<const Rgba8> in4x, ImageView<Rgba8> out, const MitchellParams& params = {},
            const Exec& exec = {});

//! Mitchell resampling by an integer factor: factor > 1 shrinks (`in` size divisible by
//! factor), factor < -1 magnifies by -factor (e.g. -8 is the evaluation's x8 upscale).
//! Direct taps at texel centres, clamp-to-edge (spec "x4 and other factors").
ImageRgba8 resampleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params = {},
                            const Exec& exec = {});
//! Into a caller's view of the output size.
void resampleMitchell(ImageView<const Rgba8> in, int factor, ImageView<Rgba8> out, const MitchellParams& params = {},
                      const Exec& exec = {});
//! Convenience: magnify by an integer factor >= 1.
ImageRgba8 upscaleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params = {},
                           const Exec& exec = {});
//! Convenience: shrink by an integer factor >= 1.
ImageRgba8 downscaleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params = {},
                             const Exec& exec = {});

}  // namespace ssfx::aa
