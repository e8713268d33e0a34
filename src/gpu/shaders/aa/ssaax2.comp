#version 450
// ssaax2: the 2x supersampling resolve, Mitchell-Netravali (B = C = 1/3) in the reference
// shader's 12 bilinear reads (DDAA paper section 3.4.2; spec ppaa.md "ssaax2"; the CPU's
// src/aa/resolve.cpp). The input is the 2x render; the weights sum to 0.9999961 and are
// deliberately not renormalised (spec).
#include "ppaa.glsl"

const float kA = 0.746677, kWa = 0.269867;
const float kB = 2.886093, kC = 0.746066, kWb = -0.009934;
const vec3 kTaps[12] = vec3[12](vec3(-kA, -kA, kWa), vec3(kA, -kA, kWa), vec3(-kA, kA, kWa), vec3(kA, kA, kWa),
                                vec3(-kB, -kC, kWb), vec3(kB, -kC, kWb), vec3(-kB, kC, kWb), vec3(kB, kC, kWb),
                                vec3(-kC, -kB, kWb), vec3(kC, -kB, kWb), vec3(-kC, kB, kWb), vec3(kC, kB, kWb));

void main() {
    ivec2 p;
    if (!outputPixel(p)) return;
    EXACT float cx = float(p.x) + 0.5;
    EXACT float cy = float(p.y) + 0.5;
    const float u = divide(cx, float(pc.outWidth)), v = divide(cy, float(pc.outHeight));
    EXACT vec3 sum = vec3(0.0);
    for (int i = 0; i < 12; ++i) {
        EXACT float tu = u + kTaps[i].x * pc.invW;
        EXACT float tv = v + kTaps[i].y * pc.invH;
        const vec3 c = sampleUV(tu, tv);
        sum = sum + c * kTaps[i].z;
    }
    // Alpha: the top-left source pixel of the 2x2 block.
    store(p, sum, alphaAt(2 * p.x, 2 * p.y));
}
