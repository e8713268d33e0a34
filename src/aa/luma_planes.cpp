// Dispatch of the plane computation (body: LumaPlaneRows in ppaa_simd-inl.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/ppaa_simd-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/ppaa_simd-inl.h"

#if HWY_ONCE
#include <algorithm>
#include <vector>

#include "src/aa/luma_planes.hpp"

namespace ssfx::aa::detail {

HWY_EXPORT(LumaPlaneRows);

LumaPlanes bandLumaPlanes(ImageView<const Rgba8> in, int y0, int y1, int reach, bool withQuad) {
    thread_local std::vector<float> buffer;
    LumaPlanes planes{nullptr, in.width(), in.height(), withQuad};
    planes.first = std::max(0, y0 - reach);
    planes.rows = std::min(in.height(), y1 + reach) - planes.first + 1;
    buffer.resize(planes.size());
    planes.data = buffer.data();
    HWY_DYNAMIC_DISPATCH(LumaPlaneRows)(in, planes);
    return planes;
}

}  // namespace ssfx::aa::detail
#endif
