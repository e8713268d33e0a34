// blur: 3x3 truncated Gaussian (DDAA paper section 3.1, the "poor result" baseline and the
// speed baseline: every timing is reported relative to it). Spec ppaa.md "blur".
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/blur-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/blur-inl.h"

#if HWY_ONCE
#include <cmath>

#include "src/aa/blur_kernel.hpp"
#include "src/aa/ppaa_common.hpp"
#include "ssfx/aa/blur.hpp"

namespace ssfx::aa {

namespace detail {
HWY_EXPORT(BlurRows);
}  // namespace detail

BlurWeights blurWeights(const BlurParams& p) {
    validateParams(kBlurParams, &p, "blur");
    BlurWeights w;
    w.w1 = std::exp(-1.0f / (2.0f * p.sigma * p.sigma));  // sigma 0.6: 0.2493522
    w.w2 = w.w1 * w.w1;
    // Normalisation by multiplying with the reciprocal of the weight sum (spec).
    w.norm = 1.0f / (1.0f + 4.0f * w.w1 + 4.0f * w.w2);
    return w;
}

ImageRgba8 blurReference(ImageView<const Rgba8> in, const BlurParams& params) {
    detail::checkInput("blur", in);
    const BlurWeights w = blurWeights(params);
    ImageRgba8 out(in.width(), in.height());
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) out(x, y) = detail::blurPixel(in, x, y, w, params.texture);
    return out;
}

void blur(ImageView<const Rgba8> in, ImageView<Rgba8> out, const BlurParams& params, const Exec& exec) {
    detail::checkInput("blur", in);
    detail::checkOutput("blur", in, out);
    const BlurWeights w = blurWeights(params);
    parallelRows(in.height(), exec, [&](int y0, int y1) {
        HWY_DYNAMIC_DISPATCH(detail::BlurRows)(in, out, y0, y1, w, params.texture);
    });
}

ImageRgba8 blur(ImageView<const Rgba8> in, const BlurParams& params, const Exec& exec) {
    detail::checkInput("blur", in);
    ImageRgba8 out(in.width(), in.height());
    blur(in, out.view(), params, exec);
    return out;
}

}  // namespace ssfx::aa
#endif  // HWY_ONCE
