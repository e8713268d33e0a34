#version 450
// Pass 1: hardware depth -> camera-space z (SAO paper eq. 2; spec sao.md "Passes" 1; the
// CPU's ao::depthToZ), for the whole buffer, guard band included. The depth view is any of
// D16, D24 and D32F (a sampled view of the depth aspect): texelFetch gives d in [0, 1].
// d = 1 (nothing drawn) is sky, z = -infinity, for any far plane; so is a D32F value that is
// NaN or outside [0, 1] (the CPU refuses those with an error; the upload path checks them
// before they reach here).
//
// Float arithmetic, not the CPU's double: z = zn zf / (zf (1 - d) + zn d) for a finite far
// plane (eq. 2 rearranged so that the denominator adds two terms of one sign: no
// cancellation as d -> 1, where c0 / (d c1 + c2) loses |zf / zn| ulps), zn / (1 - d) for an
// infinite one; every step correctly rounded, so z is within a few ulps of the CPU's
// correctly rounded value (the bound is derived in tests/gpu/test_gpu_ao.cpp).
#include "ao.glsl"

layout(set = 0, binding = 0) uniform sampler2D depthTex;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D zOut;

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const float d = texelFetch(depthTex, p, 0).r;
    float z = -1.0 / 0.0;
    if (d >= 0.0 && d < 1.0) {
        precise float oneMinus = 1.0 - d;
        if (isinf(pc.zFar)) {
            z = crDiv(pc.zNear, oneMinus);
        } else {
            precise float den = pc.zFar * oneMinus + pc.zNear * d;
            z = crDiv(pc.zNearFar, den);
        }
    }
    imageStore(zOut, p, vec4(z));
}
