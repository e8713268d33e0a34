// Pieces shared by the luma-based PPAA methods (fxaa3c, fxaa3d, ddaa1, ddaa2): parameter
// validation, the 3x3 luma neighbourhood, the early exit and the edge orientation test
// (spec ppaa.md section 1 and fxaa3d steps 2-3).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "ssfx/aa/presets.hpp"
#include "ssfx/core/color.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa::detail {

inline void checkInput(const char* method, ImageView<const Rgba8> in) {
    checkDimensions(in.width(), in.height(), fmt::format("{} input", method));
}

inline void checkOutput(const char* method, ImageView<const Rgba8> in, ImageView<Rgba8> out, int factorNum = 1,
                        int factorDen = 1) {
    const int ew = in.width() * factorNum / factorDen, eh = in.height() * factorNum / factorDen;
    if (out.width() != ew || out.height() != eh)
        throw Error(fmt::format("{}: output is {}x{}, expected {}x{}", method, out.width(), out.height(), ew, eh));
    const auto* ib = reinterpret_cast<const char*>(in.data());
    const auto* ob = reinterpret_cast<const char*>(out.data());
    const auto* ie = reinterpret_cast<const char*>(in.row(in.height() - 1) + in.width());
    const auto* oe = reinterpret_cast<const char*>(out.row(out.height() - 1) + out.width());
    if (ob < ie && ib < oe) throw Error(fmt::format("{}: output must not overlap the input", method));
}

//! max/min for values that are never NaN (luma, distances). std::fmax/fmin are out-of-line
//! libm calls because of their NaN rules; these compile to maxss/minss.
inline float maxf(float a, float b) { return a < b ? b : a; }
inline float minf(float a, float b) { return b < a ? b : a; }

//! A filtered colour back to 8 bits in its texture's encoding (unorm: toUnorm8; sRGB:
//! encodeSrgb8, round to nearest, as a GPU writes an sRGB render target).
inline Rgba8 toRgba8(const Rgb& c, std::uint8_t alpha, TextureFormat format = TextureFormat::Unorm) {
    return {encode8(c.r, format), encode8(c.g, format), encode8(c.b, format), alpha};
}

//! Luma of the 3x3 neighbourhood. Names as in the reference shader (spec section 1):
//! S = (0, -1) is the row above, N = (0, +1) the row below.
struct Luma3x3 {
    float C, W, E, S, N, SW, NW, SE, NE;
};

//! Early exit of section 1: true when the pixel is left unchanged. `range` receives
//! lumaMax - lumaMin over the centre and its four direct neighbours.
inline bool belowEdgeThreshold(const Luma3x3& n, float thresholdMin, float threshold, float* range) {
    const float lumaMax = maxf(maxf(maxf(n.S, n.N), maxf(n.W, n.E)), n.C);
    const float lumaMin = minf(minf(minf(n.S, n.N), minf(n.W, n.E)), n.C);
    *range = lumaMax - lumaMin;
    return *range < maxf(thresholdMin, lumaMax * threshold);
}

//! Edge orientation (FXAA 3.11 quality, spec fxaa3d steps 2-3). Sums left to right as
//! written in the spec. Side 1 is the negative direction across the edge (S or W).
struct EdgeSides {
    bool horizontal;  //!< the edge runs along x; "across" is y
    float luma1, luma2;
    float g1, g2;  //!< luma1 - C, luma2 - C
};

inline EdgeSides edgeSides(const Luma3x3& n) {
    const float edgeH = std::fabs(-2.0f * n.W + (n.SW + n.NW)) + std::fabs(-2.0f * n.C + (n.S + n.N)) * 2.0f +
                        std::fabs(-2.0f * n.E + (n.SE + n.NE));
    const float edgeV = std::fabs(-2.0f * n.N + (n.NE + n.NW)) + std::fabs(-2.0f * n.C + (n.W + n.E)) * 2.0f +
                        std::fabs(-2.0f * n.S + (n.SW + n.SE));
    EdgeSides s;
    s.horizontal = edgeH >= edgeV;
    s.luma1 = s.horizontal ? n.S : n.W;
    s.luma2 = s.horizontal ? n.N : n.E;
    s.g1 = s.luma1 - n.C;
    s.g2 = s.luma2 - n.C;
    return s;
}

//! The preset's thresholds on top of a params struct's other defaults.
template <class P>
P withPreset(P params, aa::Preset preset) {
    params.edgeThresholdMin = aa::thresholdsFor(preset).edgeThresholdMin;
    params.edgeThreshold = aa::thresholdsFor(preset).edgeThreshold;
    return params;
}

//! Allocates the output of a same-size method and lets `fill` write it.
template <class Fill>
ImageRgba8 newOutput(const char* method, ImageView<const Rgba8> in, const Fill& fill) {
    checkInput(method, in);
    ImageRgba8 out(in.width(), in.height());
    fill(out.view());
    return out;
}

//! Runs kernel(x, y) -> Rgba8 for every pixel, rows in parallel blocks.
template <class Kernel>
void forEachPixel(ImageView<Rgba8> out, const Exec& exec, const Kernel& kernel) {
    parallelRows(out.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            Rgba8* row = out.row(y);
            for (int x = 0; x < out.width(); ++x) row[x] = kernel(x, y);
        }
    });
}

//! Luma plane computed one pixel at a time (the scalar oracle of lumaPlane()); with a
//! non-zero chromaWeight, the colour-aware edgeLuma() instead. `format`: the texels as the
//! texture reads them (an sRGB texture's luma is that of the decoded, linear values).
inline ImageF lumaPlaneReference(ImageView<const Rgba8> in, float chromaWeight = 0.0f,
                                 TextureFormat format = TextureFormat::Unorm) {
    const float* d = decodeTable(format);
    ImageF L(in.width(), in.height());
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            const Rgba8 p = in(x, y);
            L(x, y) = edgeLuma(Rgb{d[p.r], d[p.g], d[p.b]}, chromaWeight);
        }
    return L;
}

}  // namespace ssfx::aa::detail
