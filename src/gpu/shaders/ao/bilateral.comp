#version 450
// One separable bilateral pass (SAO paper section 2.4; the CPU's ao::bilateralPass),
// horizontal or vertical (spec_horizontal). A is read over the source region (srcX, srcY,
// srcW x srcH in buffer pixels; the image holds that region), taps clamped to it or, with
// spec_zeroOutside (the released passes), weighing 0 beyond it; the pass writes the dispatch
// region (the source region, or for the last pass the output region within it). A tap's
// weight is its spatial weight times max(0, 1 - edgeSharpness |z_tap - z|), summed in the
// CPU's tap order; sky pixels stay 1. z is read in buffer pixels (level 0, or the packed key).
#define SSFX_AO_TABLES_BINDING 3
#include "ao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D aIn;      // the source region
layout(set = 0, binding = 1, r32f) uniform writeonly image2D aOut;    // the dispatch region
layout(set = 0, binding = 2, r32f) uniform readonly image2D zBuffer;  // buffer pixels

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    // The pixel in source-region coordinates.
    const ivec2 src = ivec2(pc.regionX - pc.srcX, pc.regionY - pc.srcY) + p;
    const ivec2 origin = ivec2(pc.srcX, pc.srcY);
    const float zc = imageLoad(zBuffer, origin + src).r;
    float result = 1.0;
    if (!isinf(zc)) {
        precise float s = 0.0, ws = 0.0;
        const int n = spec_horizontal != 0 ? pc.srcW : pc.srcH;
        const int at0 = spec_horizontal != 0 ? src.x : src.y;
        for (int k = 0; k < tables.taps; ++k) {
            const int at = at0 + int(tables.blurOffset[k]) * tables.blurStride;
            if (spec_zeroOutside != 0 && (at < 0 || at >= n)) continue;  // weight 0
            const int t = clamp(at, 0, n - 1);
            const ivec2 tap = spec_horizontal != 0 ? ivec2(t, src.y) : ivec2(src.x, t);
            const float zt = imageLoad(zBuffer, origin + tap).r;
            // std::max(0, x) is (0 < x ? x : 0), also for NaN (edgeSharpness 0 next to sky)
            precise float x = 1.0 - tables.edgeSharpness * abs(zt - zc);
            precise float wt = tables.blurWeight[k] * (x > 0.0 ? x : 0.0);
            s += wt * imageLoad(aIn, tap).r;
            ws += wt;
        }
        precise float den = ws + tables.blurEpsilon;
        result = crDiv(s, den);
        if (spec_packOutput != 0) result = packAo(result);
    }
    imageStore(aOut, p, vec4(result));
}
