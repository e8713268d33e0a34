// ddaa1: directional diffusion without edge search (Klein, DDAA, sections 2.1-2.2;
// spec ppaa.md "ddaa1"). The per-pixel pieces are in ddaa_kernel.hpp, shared with ddaa2.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/ddaa-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/ddaa-inl.h"

#if HWY_ONCE
#include "src/aa/ddaa_kernel.hpp"
#include "src/aa/luma_driver.hpp"
#include "ssfx/aa/ddaa.hpp"

namespace ssfx::aa {

namespace detail {
HWY_EXPORT(Ddaa1RowSimd);
}  // namespace detail

namespace detail {
namespace {
void run(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa1Params& p, const Exec& exec, bool reference) {
    checkInput("ddaa1", in);
    checkOutput("ddaa1", in, out);
    validateParams(kDdaa1Params, &p, "ddaa1");
    const Texture tex(in, p.filtering, p.texture);
    // The colour-aware measure (chromaWeight > 0) runs the scalar kernel, on all threads.
    const bool scalar = reference || p.chromaWeight != 0.0f;
    auto pixel = [&](int x, int y, const Luma3x3& n, float) {
        const Diffusion d = diffusion(n, edgeSides(n), p);
        return diffuse(tex, x, y, d, p.maxDiffusion, 0.0f, 0.0f);
    };
    // The vector kernel across pixels covers the GPU filtering model (the default), on
    // either texture encoding.
    auto rows = [&](int y, const LumaRows& band, const LumaPlanes&, std::uint8_t* mask, const Rgba8* src, Rgba8* dst) {
        if (!scalar && p.filtering == Filtering::Gpu)
            HWY_DYNAMIC_DISPATCH(Ddaa1RowSimd)(tex, band, y, mask, p, src, dst);
    };
    runLumaMethod(in, out, scalar, p.chromaWeight, p.texture, p.edgeThresholdMin, p.edgeThreshold, exec, PlaneNeeds{},
                  pixel, rows);
}
}  // namespace
}  // namespace detail

Ddaa1Params ddaa1ParamsFor(Preset preset) { return detail::withPreset(Ddaa1Params{}, preset); }

void ddaa1(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa1Params& p, const Exec& exec) {
    detail::run(in, out, p, exec, false);
}
ImageRgba8 ddaa1(ImageView<const Rgba8> in, const Ddaa1Params& p, const Exec& exec) {
    return detail::newOutput("ddaa1", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, exec, false); });
}
ImageRgba8 ddaa1Reference(ImageView<const Rgba8> in, const Ddaa1Params& p) {
    return detail::newOutput("ddaa1", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, Exec{1}, true); });
}

}  // namespace ssfx::aa
#endif  // HWY_ONCE
