#version 450
// blur: 3x3 truncated Gaussian (DDAA paper section 3.1; spec ppaa.md "blur"; the CPU's
// src/aa/blur_kernel.hpp). Weights from gpu::aaConstants (the CPU's blurWeights). Texel
// reads only, so both sampling modes give the CPU's bytes. Each tap is fetched and decoded
// where it is used: no workgroup tile (its loads cost more than the fetches on lavapipe, and
// blur has no luma to share).
#include "ppaa.glsl"

void main() {
    ivec2 p;
    if (!outputPixel(p)) return;
    const int x = p.x, y = p.y;
    const vec3 c = texelValue(x, y), w = texelValue(x - 1, y), e = texelValue(x + 1, y);
    const vec3 s = texelValue(x, y - 1), n = texelValue(x, y + 1);
    const vec3 sw = texelValue(x - 1, y - 1), se = texelValue(x + 1, y - 1);
    const vec3 nw = texelValue(x - 1, y + 1), ne = texelValue(x + 1, y + 1);
    // Sum order: centre, the direct neighbours W, E, S, N, then the corners.
    EXACT vec3 direct = ((w + e) + (s + n)) * pc.blurW1;
    EXACT vec3 corner = ((sw + se) + (nw + ne)) * pc.blurW2;
    EXACT vec3 result = ((c + direct) + corner) * pc.blurNorm;
    store(p, result, alphaAt(x, y));
}
