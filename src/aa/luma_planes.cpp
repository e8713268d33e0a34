// Dispatch of the plane computation (body: LumaPlaneRows in ppaa-inl.h), and of the
// test hooks of ppaa-inl.h (ppaa_hooks.hpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/ppaa-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/ppaa-inl.h"

#if HWY_ONCE
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "src/aa/luma_planes.hpp"
#include "src/aa/ppaa_hooks.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::aa::detail {

HWY_EXPORT(LumaPlaneRows);
HWY_EXPORT(LevelByteMismatches);
HWY_EXPORT(MeanLevelByteMismatches);

std::int64_t levelByteMismatches() { return HWY_DYNAMIC_DISPATCH(LevelByteMismatches)(); }
std::int64_t meanLevelByteMismatches() { return HWY_DYNAMIC_DISPATCH(MeanLevelByteMismatches)(); }

std::uint64_t newPlaneCall() {
    static std::atomic<std::uint64_t> calls{0};
    return ++calls;
}

LumaPlanes planeRowsFor(ImageView<const Rgba8> in, std::uint64_t call, int y, int reach, bool withQuad,
                        TextureFormat format, const DecodedBand& band) {
    // Rows of this thread's ring; tag[slot] = the plane row it holds, -1 for none.
    thread_local struct {
        std::vector<float> buffer;
        std::vector<int> tag;
        std::uint64_t call = 0;
    } ring;
    const int window = 2 * reach + 2;  // rows y - reach .. y + reach + 1
    SSFX_ASSERT(reach >= 0 && window <= kMaxPlaneRing);
    int rows = 1;
    while (rows < window) rows *= 2;
    LumaPlanes planes{nullptr, in.width(), in.height(), withQuad, rows - 1, format, call};
    if (ring.call != call || ring.tag.size() != std::size_t(rows)) {
        ring.call = call;
        ring.buffer.resize(planes.size());
        ring.tag.assign(std::size_t(rows), -1);
    }
    planes.data = ring.buffer.data();
    const int lo = std::max(0, y - reach), hi = std::min(in.height(), y + reach + 1);
    for (int r = lo; r <= hi;) {
        if (ring.tag[planes.slot(r)] == r) {
            ++r;
            continue;
        }
        int end = r + 1;  // a run of missing rows, computed in one call
        while (end <= hi && ring.tag[planes.slot(end)] != end) ++end;
        HWY_DYNAMIC_DISPATCH(LumaPlaneRows)(in, planes, r, end, band);
        for (int k = r; k < end; ++k) ring.tag[planes.slot(k)] = k;
        r = end;
    }
    return planes;
}

}  // namespace ssfx::aa::detail
#endif
