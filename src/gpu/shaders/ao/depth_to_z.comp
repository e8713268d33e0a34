#version 450
// Pass 1: hardware depth -> camera-space z (SAO paper eq. 2; spec sao.md "Passes" 1; the
// CPU's ao::depthToZ), for the whole buffer, guard band included. The depth view is any of
// D16, D24 and D32F (a sampled view of the depth aspect): texelFetch gives d in [0, 1].
// d = 1 (nothing drawn) is sky, z = -infinity, for any far plane; so is a D32F value that is
// NaN or outside [0, 1] (the CPU refuses those with an error; the upload path checks them
// before they reach here).
//
// The CPU evaluates eq. 2 in double and rounds once; so does this pass, in float pairs of
// about 46 bits (exact.glsl), as z = zn zf / (zf (1 - d) + zn d) for a finite far plane and
// zn / (1 - d) for an infinite one, zn, zf and zn zf given as pairs from the host's doubles:
// z is the CPU's float but where the exact value lies within about 2^-40 (the CPU's own
// error near the far plane) of a rounding boundary, then one ulp away (tests/gpu/test_gpu_ao.cpp).
#include "ao.glsl"

layout(set = 0, binding = 0) uniform sampler2D depthTex;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D zOut;

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const float d = texelFetch(depthTex, p, 0).r;
    float z = -1.0 / 0.0;
    if (d >= 0.0 && d < 1.0) {
        float s, e;
        twoSum(1.0, -d, s, e);
        const vec2 oneMinus = vec2(s, e);  // 1 - d, exactly
        const vec2 zNear = vec2(pc.zNear, pc.zNearLo);
        if (isinf(pc.zFar)) {
            z = pairDivToFloat(zNear, oneMinus);
        } else {
            const vec2 den = pairAdd(pairMul(vec2(pc.zFar, pc.zFarLo), oneMinus), pairMul(zNear, vec2(d, 0.0)));
            z = pairDivToFloat(vec2(pc.zNearFar, pc.zNearFarLo), den);
        }
    }
    imageStore(zOut, p, vec4(z));
}
