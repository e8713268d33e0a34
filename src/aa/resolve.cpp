// Mitchell-Netravali resolve and resampling (spec ppaa.md "ssaax2, ssaax4", "Upsampling").
//
// ssaax2 uses the reference shader's 12 bilinear reads: each read at a fractional offset
// between two texel pairs stands for 4 weighted taps, so 12 reads cover the 4x4 support
// (the paper's "optimized to take just 12 texture samples", section 3.4.2).
// Other factors use direct taps at texel centres, normalised by the weight sum.
#include "ssfx/aa/resolve.hpp"

#include <cmath>
#include <vector>

#include "src/aa/ppaa_common.hpp"

namespace ssfx::aa {

float mitchell(float t, float B, float C) {
    t = std::fabs(t);
    if (t < 1.0f)
        return ((12.0f - 9.0f * B - 6.0f * C) * t * t * t + (-18.0f + 12.0f * B + 6.0f * C) * t * t +
                (6.0f - 2.0f * B)) /
               6.0f;
    if (t <= 2.0f)
        return ((-B - 6.0f * C) * t * t * t + (6.0f * B + 30.0f * C) * t * t + (-12.0f * B - 48.0f * C) * t +
                (8.0f * B + 24.0f * C)) /
               6.0f;
    return 0.0f;
}

namespace {

void checkMitchell(const char* method, const MitchellParams& p) { validateParams(kMitchellParams, &p, method); }

// Tap offsets (source pixels) and weights of the 12-read x2 resolve (spec, B = C = 1/3).
struct Tap2 {
    float dx, dy, w;
};
constexpr float kA = 0.746677f, kWa = 0.269867f;
constexpr float kB = 2.886093f, kC = 0.746066f, kWb = -0.009934f;
constexpr Tap2 kTaps2[12] = {
    {-kA, -kA, kWa}, {kA, -kA, kWa}, {-kA, kA, kWa},  {kA, kA, kWa},  {-kB, -kC, kWb}, {kB, -kC, kWb},
    {-kB, kC, kWb},  {kB, kC, kWb},  {-kC, -kB, kWb}, {kC, -kB, kWb}, {-kC, kB, kWb},  {kC, kB, kWb},
};

// Taps along one axis for output coordinate f (source pixel units, texel centres at i + 0.5).
struct AxisTaps {
    int first = 0;               // source index of the first tap (before clamping)
    std::vector<float> weights;  // k(t / s) per tap
};

AxisTaps axisTaps(float f, float support, float s, const MitchellParams& p) {
    const int n = int(support);
    const float fracS = support - float(n);
    int base, dLo, dHi;
    if (fracS <= 0.5f) {  // odd kernel around the texel containing f
        base = int(std::floor(f));
        dLo = -n, dHi = n;
    } else {                            // even kernel around the nearest texel boundary
        base = int(std::nearbyint(f));  // ties to even
        dLo = -n - 1, dHi = n;
    }
    dLo = std::max(dLo, -8), dHi = std::min(dHi, 7);  // the GPU's texel-offset range
    AxisTaps a;
    a.first = base + dLo;
    for (int d = dLo; d <= dHi; ++d) a.weights.push_back(mitchell((float(base + d) + 0.5f - f) / s, p.B, p.C));
    return a;
}

}  // namespace

namespace {
void checkDivisible(const char* method, ImageView<const Rgba8> in, int m) {
    detail::checkInput(method, in);
    if (in.width() % m != 0 || in.height() % m != 0)
        throw Error(fmt::format("{}: input size {}x{} is not divisible by {}", method, in.width(), in.height(), m));
}
}  // namespace

ImageRgba8 ssaax2(ImageView<const Rgba8> in, Filtering filtering, const Exec& exec, TextureFormat format) {
    checkDivisible("ssaax2", in, 2);
    ImageRgba8 out(in.width() / 2, in.height() / 2);
    ssaax2(in, out.view(), filtering, exec, format);
    return out;
}

void ssaax2(ImageView<const Rgba8> in, ImageView<Rgba8> out, Filtering filtering, const Exec& exec,
            TextureFormat format) {
    checkDivisible("ssaax2", in, 2);
    detail::checkOutput("ssaax2", in, out, 1, 2);
    const Texture tex(in, filtering, format);
    const float invW = tex.invW(), invH = tex.invH();
    const float outW = float(out.width()), outH = float(out.height());
    detail::forEachPixel(out, exec, [&](int x, int y) {
        const float u = (float(x) + 0.5f) / outW, v = (float(y) + 0.5f) / outH;
        Rgb sum;
        for (const Tap2& t : kTaps2) {
            const Rgb c = tex.sample(u + t.dx * invW, v + t.dy * invH);
            sum.r += c.r * t.w, sum.g += c.g * t.w, sum.b += c.b * t.w;
        }
        // The weights sum to 0.9999961 and are deliberately not renormalised (spec).
        const Rgba8 a = in(2 * x, 2 * y);  // alpha: the top-left source pixel of the 2x2 block
        return detail::toRgba8(sum, a.a, format);
    });
}

namespace {
struct ResampleShape {
    bool shrink;
    int m;
    std::int64_t w, h;
};
ResampleShape resampleShape(ImageView<const Rgba8> in, int factor) {
    detail::checkInput("mitchell", in);
    if (factor == 0 || factor == -1 || factor > 64 || factor < -64)
        throw Error(fmt::format("mitchell: factor {} is not in [2, 64] (shrink) or [-64, -2] (magnify), or 1", factor));
    const bool shrink = factor >= 1;
    const int m = shrink ? factor : -factor;
    if (shrink && (in.width() % m != 0 || in.height() % m != 0))
        throw Error(fmt::format("mitchell: input size {}x{} is not divisible by {}", in.width(), in.height(), m));
    const std::int64_t ow = shrink ? in.width() / m : std::int64_t(in.width()) * m;
    const std::int64_t oh = shrink ? in.height() / m : std::int64_t(in.height()) * m;
    checkDimensions(ow, oh, "mitchell output");
    return {shrink, m, ow, oh};
}
}  // namespace

ImageRgba8 resampleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params, const Exec& exec) {
    const ResampleShape shape = resampleShape(in, factor);
    ImageRgba8 out{int(shape.w), int(shape.h)};
    resampleMitchell(in, factor, out.view(), params, exec);
    return out;
}

void resampleMitchell(ImageView<const Rgba8> in, int factor, ImageView<Rgba8> out, const MitchellParams& params,
                      const Exec& exec) {
    const ResampleShape shape = resampleShape(in, factor);
    if (out.width() != shape.w || out.height() != shape.h)
        throw Error(
            fmt::format("mitchell: output is {}x{}, expected {}x{}", out.width(), out.height(), shape.w, shape.h));
    checkMitchell("mitchell", params);
    const bool shrink = shape.shrink;
    const int m = shape.m;
    const float s = shrink ? float(m) : 1.0f;  // kernel scale: max(factor, 1)
    const float support = 1.999f * s;
    auto coord = [&](int i) { return shrink ? (float(i) + 0.5f) * float(m) : (float(i) + 0.5f) / float(m); };
    std::vector<AxisTaps> tx(std::size_t(out.width())), ty(std::size_t(out.height()));
    for (int x = 0; x < out.width(); ++x) tx[std::size_t(x)] = axisTaps(coord(x), support, s, params);
    for (int y = 0; y < out.height(); ++y) ty[std::size_t(y)] = axisTaps(coord(y), support, s, params);
    const float* d = decodeTable(params.texture);
    detail::forEachPixel(out, exec, [&](int x, int y) {
        const AxisTaps& ax = tx[std::size_t(x)];
        const AxisTaps& ay = ty[std::size_t(y)];
        const int nx = int(ax.weights.size()), ny = int(ay.weights.size());
        const bool skipCorners = nx > 6;  // wide kernels skip their four corner taps (spec)
        Rgb sum;
        float wsum = 0.0f;
        for (int j = 0; j < ny; ++j) {
            const Rgba8* row = in.row(std::clamp(ay.first + j, 0, in.height() - 1));
            for (int i = 0; i < nx; ++i) {
                if (skipCorners && (i == 0 || i == nx - 1) && (j == 0 || j == ny - 1)) continue;
                const float w = ax.weights[std::size_t(i)] * ay.weights[std::size_t(j)];
                const Rgba8 c = row[std::clamp(ax.first + i, 0, in.width() - 1)];
                sum.r += d[c.r] * w, sum.g += d[c.g] * w, sum.b += d[c.b] * w;
                wsum += w;
            }
        }
        const Rgb r{sum.r / wsum, sum.g / wsum, sum.b / wsum};
        const int sx = shrink ? x * m : x / m, sy = shrink ? y * m : y / m;
        return detail::toRgba8(r, in(sx, sy).a, params.texture);
    });
}

ImageRgba8 ssaax4(ImageView<const Rgba8> in, const MitchellParams& params, const Exec& exec) {
    checkDivisible("ssaax4", in, 4);
    return resampleMitchell(in, 4, params, exec);
}

void ssaax4(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MitchellParams& params, const Exec& exec) {
    checkDivisible("ssaax4", in, 4);
    resampleMitchell(in, 4, out, params, exec);
}

ImageRgba8 upscaleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params, const Exec& exec) {
    if (factor == 1) return ImageRgba8::copyOf(in);
    if (factor < 1) throw Error(fmt::format("mitchell: upscale factor {} must be at least 1", factor));
    return resampleMitchell(in, -factor, params, exec);
}

ImageRgba8 downscaleMitchell(ImageView<const Rgba8> in, int factor, const MitchellParams& params, const Exec& exec) {
    if (factor == 1) return ImageRgba8::copyOf(in);
    if (factor < 1) throw Error(fmt::format("mitchell: downscale factor {} must be at least 1", factor));
    return resampleMitchell(in, factor, params, exec);
}

}  // namespace ssfx::aa
