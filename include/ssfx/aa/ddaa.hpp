// DDAA: Directional Diffusion Anti-Aliasing (A. Klein, JCGT). ddaa1 = diffusion along the
// Scharr-estimated edge direction (paper sections 2.1-2.2); ddaa2 = ddaa1 combined with a
// clean, batched edge search (sections 2.3-2.5), the proposed method; ddaa2p = ddaa2 on a
// 2x render followed by the ssaax2 resolve (section 4). Semantics: spec ppaa.md section 2.
#pragma once

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa {

struct Ddaa1Params {
    float edgeThresholdMin = 0.0625f;  //!< [0, 1] absolute luma contrast needed (preset "medium")
    float edgeThreshold = 0.166f;      //!< [0, 1] contrast relative to the local max luma
    float strength = 3.0f;             //!< [0, 100] DDAA_STRENGTH: diffusion = min(1, strength*sqrt(|e|))
    float maxDiffusion = 0.51f;        //!< [0, 1] px; largest sample offset (paper Fig. 5: ~half a pixel)
    float ridgeFactor = 10.0f;         //!< [0, 1000] small-structure preservation (section 2.2)
    //! [0, 4] opt-in colour-aware contrast (our extension, spec section 4): edges are found on
    //! luma + chromaWeight * chroma (ssfx::edgeLuma) so equal-luma colours differ. 0 = the
    //! paper's luma (default, outputs unchanged). Non-zero runs the scalar kernel.
    float chromaWeight = 0.0f;
    Filtering filtering = Filtering::Gpu;
};

struct Ddaa2Params : Ddaa1Params {
    //! Edge search: samples per round (EDGE_STEP_LIST = [3,3,3,3,3], 15 px per side). The
    //! batch of 3 is the paper's tuned value (section 2.5); rounds set the reach.
    int searchRounds = 5;  //!< [1, 5]
};

Ddaa1Params ddaa1ParamsFor(Preset p);
Ddaa2Params ddaa2ParamsFor(Preset p);

ImageRgba8 ddaa1(ImageView<const Rgba8> in, const Ddaa1Params& params = {}, const Exec& exec = {});
void ddaa1(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa1Params& params = {}, const Exec& exec = {});
ImageRgba8 ddaa1Reference(ImageView<const Rgba8> in, const Ddaa1Params& params = {});

ImageRgba8 ddaa2(ImageView<const Rgba8> in, const Ddaa2Params& params = {}, const Exec& exec = {});
void ddaa2(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa2Params& params = {}, const Exec& exec = {});
ImageRgba8 ddaa2Reference(ImageView<const Rgba8> in, const Ddaa2Params& params = {});

//! ddaa2 on the 2x image `in2x`, then ssaax2: output is half its size (in2x must have even sizes).
ImageRgba8 ddaa2p(ImageView<const Rgba8> in2x, const Ddaa2Params& params = {}, const Exec& exec = {});
//! Into a caller's view of half the input's size (the 2x intermediate is allocated).
void ddaa2p(ImageView<const Rgba8> in2x, ImageView<Rgba8> out, const Ddaa2Params& params = {}, const Exec& exec = {});

}  // namespace ssfx::aa
