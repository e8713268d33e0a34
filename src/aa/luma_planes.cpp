// Dispatch of the plane computation (body: LumaPlaneRows in ppaa_simd-inl.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/ppaa_simd-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/ppaa_simd-inl.h"

#if HWY_ONCE
#include <vector>

#include "src/aa/luma_planes.hpp"

namespace ssfx::aa::detail {

HWY_EXPORT(LumaPlaneRows);

LumaPlanes scratchLumaPlanes(ImageView<const Rgba8> in, bool withQuad, const Exec& exec) {
    thread_local std::vector<float> buffer;
    LumaPlanes planes{nullptr, in.width(), in.height(), withQuad};
    const std::size_t quadSize = withQuad ? std::size_t(in.height() + 1) * std::size_t(in.width() + 1) : 0;
    buffer.resize(planes.sizeH() + planes.sizeV() + quadSize);
    planes.data = buffer.data();
    parallelRows(in.height(), exec,
                 [&](int y0, int y1) { HWY_DYNAMIC_DISPATCH(LumaPlaneRows)(in, y0, y1, planes); });
    return planes;
}

}  // namespace ssfx::aa::detail
#endif
