// DDAA: Directional Diffusion Anti-Aliasing (A. Klein, JCGT). ddaa1 = diffusion along the
// Scharr-estimated edge direction (paper sections 2.1-2.2); ddaa2 = ddaa1 combined with a
// clean, batched edge search (sections 2.3-2.5), the proposed method; ddaa2p = ddaa2 on a
// 2x render followed by the ssaax2 resolve (section 4). Semantics: spec ppaa.md section 2.
#pragma once

#include <array>

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa {

struct Ddaa1Params {
    float edgeThresholdMin = 0.0625f;  //!< absolute luma contrast needed (preset "medium")
    float edgeThreshold = 0.166f;      //!< contrast relative to the local max luma
    float strength = 3.0f;             //!< DDAA_STRENGTH: diffusion = min(1, strength*sqrt(|e|))
    float maxDiffusion = 0.51f;        //!< px; largest sample offset (paper Fig. 5: ~half a pixel)
    float ridgeFactor = 10.0f;         //!< small-structure preservation (section 2.2)
    float chromaWeight = 0.0f;         //!< as Fxaa3cParams::chromaWeight
    Filtering filtering = Filtering::Gpu;
    TextureFormat texture = TextureFormat::Unorm;  //!< rgba8unorm or rgba8unorm_srgb reads (kTextureDoc)
};

struct Ddaa2Params : Ddaa1Params {
    //! Edge search: samples per round (EDGE_STEP_LIST = [3,3,3,3,3], 15 px per side). The
    //! batch of 3 is the paper's tuned value (section 2.5); rounds set the reach.
    int searchRounds = 5;
};
namespace detail {
// P is Ddaa1Params or Ddaa2Params: the rows bind Ddaa1Params' members in a P (and read P's
// defaults).
template <class P>
constexpr std::array<ParamInfo, 5> ddaa1Rows() {
    return {{
        realIn<P, &Ddaa1Params::edgeThresholdMin>("edgeThresholdMin", "luma", 0, 1, kEdgeThresholdMinDoc),
        realIn<P, &Ddaa1Params::edgeThreshold>("edgeThreshold", "ratio", 0, 1, kEdgeThresholdDoc),
        realIn<P, &Ddaa1Params::strength>("strength", "", 0, 100,
                                          "DDAA_STRENGTH: diffusion = min(1, strength * sqrt(|gradient|))"),
        realIn<P, &Ddaa1Params::maxDiffusion>("maxDiffusion", "px", 0, 1,
                                              "largest offset of the two reads (\"about half a pixel\", Figure 5)"),
        realIn<P, &Ddaa1Params::ridgeFactor>(
            "ridgeFactor", "", 0, 1000,
            "ridges and valleys diffuse less: strength *= 1 - min(1, ridgeFactor min(|g1|, |g2|))"),
    }};
}
}  // namespace detail
//! Ddaa1Params' and Ddaa2Params' tables (params.hpp); the defaults are the initialisers above.
inline constexpr auto kDdaa1Params =
    concat(detail::ddaa1Rows<Ddaa1Params>(),
           std::array{real<&Ddaa1Params::chromaWeight>("chromaWeight", "", 0, 4, kChromaWeightDoc),
                      choice<&Ddaa1Params::texture>("texture", kTextureFormatNames, kTextureDoc)});
inline constexpr auto kDdaa2Params = concat(
    detail::ddaa1Rows<Ddaa2Params>(),
    std::array{integer<&Ddaa2Params::searchRounds>("searchRounds", "", 1, 5, "edge-search rounds of 3 pixels per side"),
               realIn<Ddaa2Params, &Ddaa1Params::chromaWeight>("chromaWeight", "", 0, 4, kChromaWeightDoc),
               choiceIn<Ddaa2Params, &Ddaa1Params::texture>("texture", kTextureFormatNames, kTextureDoc)});

Ddaa1Params ddaa1ParamsFor(Preset p);
Ddaa2Params ddaa2ParamsFor(Preset p);

ImageRgba8 ddaa1(ImageView<const Rgba8> in, const Ddaa1Params& params = {}, const Exec& exec = {});
void ddaa1(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa1Params& params = {}, const Exec& exec = {});
ImageRgba8 ddaa1Reference(ImageView<const Rgba8> in, const Ddaa1Params& params = {});

ImageRgba8 ddaa2(ImageView<const Rgba8> in, const Ddaa2Params& params = {}, const Exec& exec = {});
void ddaa2(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa2Params& params = {}, const Exec& exec = {});
ImageRgba8 ddaa2Reference(ImageView<const Rgba8> in, const Ddaa2Params& params = {});
//! True when, on a width x height image (GPU filtering model), every read of ddaa2's edge
//! search with `searchRounds` rounds lands exactly half-way between two texels across the
//! edge and on a texel along it, so it is a function of those two texels (true for every
//! realistic size; the CPU's vector kernel and the GPU pass rely on it). O(W + H), and
//! remembered for the last size asked on the calling thread.
bool ddaa2SearchReadsArePairReads(int width, int height, int searchRounds);

//! ddaa2 on the 2x image `in2x`, then ssaax2: output is half its size (in2x must have even sizes).
ImageRgba8 ddaa2p(ImageView<const Rgba8> in2x, const Ddaa2Params& params = {}, const Exec& exec = {});
//! Into a caller's view of half the input's size (the 2x intermediate is allocated).
void ddaa2p(ImageView<const Rgba8> in2x, ImageView<Rgba8> out, const Ddaa2Params& params = {}, const Exec& exec = {});

}  // namespace ssfx::aa
