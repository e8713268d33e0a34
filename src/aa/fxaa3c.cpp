// fxaa3c: FXAA 3.11 "console" (T. Lottes, NVIDIA 2011): direction from the four diagonal
// lumas, two short and two long taps along it, no edge search (spec ppaa.md "fxaa3c").
// Deviation from Lottes' shader, as in the DDAA paper: diagonals at +-1 pixel, not +-0.5
// (Fxaa3cParams::diagonalOffset).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/fxaa3c-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/fxaa3c-inl.h"

#if HWY_ONCE
#include "src/aa/luma_driver.hpp"
#include "ssfx/aa/fxaa.hpp"

namespace ssfx::aa {

namespace detail {
HWY_EXPORT(Fxaa3cRowSimd);

namespace {

Rgb scale(const Rgb& a, float k) { return {a.r * k, a.g * k, a.b * k}; }
Rgb add(const Rgb& a, const Rgb& b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }

void validate(const Fxaa3cParams& p) { validateParams(kFxaa3cParams, &p, "fxaa3c"); }

void run(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3cParams& p, const Exec& exec, bool reference) {
    checkInput("fxaa3c", in);
    checkOutput("fxaa3c", in, out);
    validate(p);
    const Texture tex(in, p.filtering, p.texture);
    // At +-1 pixel the diagonal reads land on pixel centres, which return the pixel
    // (spec section 1): luma plane lookups.
    const bool centres = p.diagonalOffset == 1.0f;
    const float du = p.diagonalOffset * tex.invW(), dv = p.diagonalOffset * tex.invH();
    const int w = in.width(), h = in.height();
    // The scalar kernel, reading luma from L (a band's rows or the whole plane).
    auto pixel = [&](const LumaRows& L, int x, int y) -> Rgba8 {
        const Rgba8 m = in(x, y);
        const float u = tex.centreU(x), v = tex.centreV(y);
        auto diag = [&](int sx, int sy) {
            return centres ? L.row(y + sy)[std::clamp(x + sx, 0, w - 1)]
                           : edgeLuma(tex.sample(u + float(sx) * du, v + float(sy) * dv), p.chromaWeight);
        };
        const float lumaNW = diag(-1, -1), lumaSW = diag(-1, +1), lumaSE = diag(+1, +1);
        const float lumaNE = diag(+1, -1) + 1.0f / 384.0f;  // FXAA: keeps dir from being 0
        const float lumaM = L.row(y)[x];
        const float lumaMax = maxf(maxf(lumaNE, lumaSE), maxf(lumaNW, lumaSW));
        const float lumaMin = minf(minf(lumaNE, lumaSE), minf(lumaNW, lumaSW));
        if (maxf(lumaMax, lumaM) - minf(lumaMin, lumaM) < maxf(p.edgeThresholdMin, lumaMax * p.edgeThreshold)) return m;

        const float swMinusNe = lumaSW - lumaNE, seMinusNw = lumaSE - lumaNW;
        const float dirX = swMinusNe + seMinusNw, dirY = swMinusNe - seMinusNw;
        const float len = std::sqrt(dirX * dirX + dirY * dirY);
        // No direction at all (possible only on exact float ties): a GPU would normalise 0
        // to NaN and read at NaN coordinates; we define it as "leave the pixel".
        if (!(len > 0.0f)) return m;
        const float d1x = dirX / len, d1y = dirY / len;

        const float hs = 0.5f;  // first pair of taps at +-0.5 px along the edge
        const Rgb n1 = tex.sample(u - d1x * hs * tex.invW(), v - d1y * hs * tex.invH());
        const Rgb p1 = tex.sample(u + d1x * hs * tex.invW(), v + d1y * hs * tex.invH());
        const float minAbs = minf(std::fabs(d1x), std::fabs(d1y)) * p.edgeSharpness;
        // fmax/fmin return the non-NaN operand, as GPU clamp does for 0/0.
        const float d2x = std::fmin(std::fmax(d1x / minAbs, -2.0f), 2.0f);
        const float d2y = std::fmin(std::fmax(d1y / minAbs, -2.0f), 2.0f);
        const Rgb n2 = tex.sample(u - d2x * 2.0f * tex.invW(), v - d2y * 2.0f * tex.invH());
        const Rgb p2 = tex.sample(u + d2x * 2.0f * tex.invW(), v + d2y * 2.0f * tex.invH());
        const Rgb A = add(n1, p1);
        const Rgb B = add(scale(add(n2, p2), 0.25f), scale(A, 0.25f));
        const float lumaB = edgeLuma(B, p.chromaWeight);
        const Rgb result = (lumaB < lumaMin || lumaB > lumaMax) ? scale(A, 0.5f) : B;
        return toRgba8(result, m.a, p.texture);
    };
    // Reference path and the colour-aware measure (chromaWeight > 0): the luma plane pixel
    // by pixel, the scalar kernel everywhere, on all threads.
    if (reference || p.chromaWeight != 0.0f) {
        const ImageF plane = lumaPlaneReference(in, p.chromaWeight, p.texture);
        const LumaRows L{plane.data(), w, h, 0};
        parallelRows(h, exec, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < w; ++x) out(x, y) = pixel(L, x, y);
        });
        return;
    }
    // Fast path, in bands of rows with their luma rows (SIMD, same bits). The vector kernel
    // across pixels covers the default (GPU model, diagonals at +-1 px); the first pixel and
    // the tail of each row take the scalar kernel. Either encoding (an sRGB texture's luma
    // rows are its decoded texels').
    const bool vector = centres && p.filtering == Filtering::Gpu;
    parallelRows(
        h, exec,
        [&](int y0, int y1) {
            const LumaRows L = bandLumaRows(in, y0, y1, p.texture);
            for (int y = y0; y < y1; ++y) {
                Rgba8* row = out.row(y);
                int x = 0;
                if (vector) {
                    row[0] = pixel(L, 0, y);
                    x = HWY_DYNAMIC_DISPATCH(Fxaa3cRowSimd)(tex, L, y, p, in.row(y), row);
                }
                for (; x < w; ++x) row[x] = pixel(L, x, y);
            }
        },
        kBandRows);
}

}  // namespace
}  // namespace detail

Fxaa3cParams fxaa3cParamsFor(Preset preset) { return detail::withPreset(Fxaa3cParams{}, preset); }

void fxaa3c(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3cParams& p, const Exec& exec) {
    detail::run(in, out, p, exec, false);
}
ImageRgba8 fxaa3c(ImageView<const Rgba8> in, const Fxaa3cParams& p, const Exec& exec) {
    return detail::newOutput("fxaa3c", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, exec, false); });
}
ImageRgba8 fxaa3cReference(ImageView<const Rgba8> in, const Fxaa3cParams& p) {
    return detail::newOutput("fxaa3c", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, Exec{1}, true); });
}

}  // namespace ssfx::aa
#endif  // HWY_ONCE
