// Runtime dispatch of the vector GTAO main pass (gtao-inl.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/ao/gtao-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/ao/gtao-inl.h"

#if HWY_ONCE
namespace ssfx::ao::detail {
HWY_EXPORT(GtaoRowSimd);
HWY_EXPORT(GtaoEdgesNormalsRow);
HWY_EXPORT(GtaoDenoiseRow);
HWY_EXPORT(GtaoTexelMismatches);
std::int64_t gtaoTexelMismatches(int n, int wm) { return HWY_DYNAMIC_DISPATCH(GtaoTexelMismatches)(n, wm); }
int gtaoDenoiseRowSimd(const GtaoDenoiseInput& in, int y, int x0, int x1, float* out) {
    return HWY_DYNAMIC_DISPATCH(GtaoDenoiseRow)(in, y, x0, x1, out);
}
int gtaoEdgesNormalsRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, std::uint8_t* edges, float* normals) {
    return HWY_DYNAMIC_DISPATCH(GtaoEdgesNormalsRow)(in, y, x0, x1, edges, normals);
}
int gtaoRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, float* out) {
    return HWY_DYNAMIC_DISPATCH(GtaoRowSimd)(in, y, x0, x1, out);
}
}  // namespace ssfx::ao::detail
#endif
