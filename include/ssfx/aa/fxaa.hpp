// FXAA 3.11 (T. Lottes, NVIDIA 2009/2011), the two variants the DDAA paper compares with:
// fxaa3c ("console", no edge search) and fxaa3d ("desktop"/quality, edge search with
// 12 iterations). Semantics: spec ppaa.md section 2, which fixes the details of the
// shaders used for the paper's numbers.
#pragma once

#include <array>

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa {

struct Fxaa3cParams {
    float edgeThresholdMin = 0.0625f;  //!< absolute luma contrast needed (preset "medium")
    float edgeThreshold = 0.166f;      //!< contrast relative to the local max luma
    float edgeSharpness = 8.0f;        //!< FXAA console sharpness: limits the long taps
    float diagonalOffset = 1.0f;       //!< px; 1 as in the DDAA paper, 0.5 in Lottes' shader
    //! Opt-in colour-aware contrast (our extension, spec section 4): edges are found on
    //! luma + chromaWeight * chroma (ssfx::edgeLuma) so equal-luma colours differ. 0 = the
    //! paper's luma (default, outputs unchanged). Non-zero runs the scalar kernel.
    float chromaWeight = 0.0f;
    Filtering filtering = Filtering::Gpu;
    TextureFormat texture = TextureFormat::Unorm;  //!< rgba8unorm or rgba8unorm_srgb reads (kTextureDoc)
};
//! Fxaa3cParams' table (params.hpp); the defaults are the initialisers above.
inline constexpr std::array kFxaa3cParams{
    real<&Fxaa3cParams::edgeThresholdMin>("edgeThresholdMin", "luma", 0, 1, kEdgeThresholdMinDoc),
    real<&Fxaa3cParams::edgeThreshold>("edgeThreshold", "ratio", 0, 1, kEdgeThresholdDoc),
    real<&Fxaa3cParams::edgeSharpness>(
        "edgeSharpness", "", 1, 64,
        "FXAA_CONSOLE__EDGE_SHARPNESS: d2 = clamp(d1 / (min(|d1.x|, |d1.y|) edgeSharpness), -2, 2)"),
    real<&Fxaa3cParams::diagonalOffset>(
        "diagonalOffset", "px", 1e-3, 2,
        "offset of the diagonal reads (the DDAA paper's comparison: 1; Lottes' shader: 0.5)"),
    real<&Fxaa3cParams::chromaWeight>("chromaWeight", "", 0, 4, kChromaWeightDoc),
    choice<&Fxaa3cParams::texture>("texture", kTextureFormatNames, kTextureDoc),
};

struct Fxaa3dParams {
    float edgeThresholdMin = 0.0625f;  //!< absolute luma contrast needed (preset "medium")
    float edgeThreshold = 0.166f;      //!< contrast relative to the local max luma
    float subpix = 0.75f;              //!< FXAA's sub-pixel aliasing removal amount
    //! The shader of the paper's comparison steps back one pixel on side 2 after its first
    //! read (spec ppaa.md fxaa3d step 4). true reproduces the paper; false gives FXAA 3.11
    //! as Lottes wrote it.
    bool paperSearchQuirk = true;
    float chromaWeight = 0.0f;  //!< as Fxaa3cParams::chromaWeight
    Filtering filtering = Filtering::Gpu;
    TextureFormat texture = TextureFormat::Unorm;  //!< rgba8unorm or rgba8unorm_srgb reads (kTextureDoc)
};
//! Fxaa3dParams' table (params.hpp); the defaults are the initialisers above.
inline constexpr std::array kFxaa3dParams{
    real<&Fxaa3dParams::edgeThresholdMin>("edgeThresholdMin", "luma", 0, 1, kEdgeThresholdMinDoc),
    real<&Fxaa3dParams::edgeThreshold>("edgeThreshold", "ratio", 0, 1, kEdgeThresholdDoc),
    real<&Fxaa3dParams::subpix>("subpix", "", 0, 1, "fxaaQualitySubpix: the sub-pixel aliasing removal amount"),
    boolean<&Fxaa3dParams::paperSearchQuirk>(
        "paperSearchQuirk",
        "1: side 2 steps back after its first read, as in the paper's shader; 0: FXAA 3.11 as written"),
    real<&Fxaa3dParams::chromaWeight>("chromaWeight", "", 0, 4, kChromaWeightDoc),
    choice<&Fxaa3dParams::texture>("texture", kTextureFormatNames, kTextureDoc),
};

Fxaa3cParams fxaa3cParamsFor(Preset p);
Fxaa3dParams fxaa3dParamsFor(Preset p);

ImageRgba8 fxaa3c(ImageView<const Rgba8> in, const Fxaa3cParams& params = {}, const Exec& exec = {});
void fxaa3c(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3cParams& params = {}, const Exec& exec = {});
ImageRgba8 fxaa3cReference(ImageView<const Rgba8> in, const Fxaa3cParams& params = {});

ImageRgba8 fxaa3d(ImageView<const Rgba8> in, const Fxaa3dParams& params = {}, const Exec& exec = {});
void fxaa3d(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3dParams& params = {}, const Exec& exec = {});
ImageRgba8 fxaa3dReference(ImageView<const Rgba8> in, const Fxaa3dParams& params = {});

}  // namespace ssfx::aa
