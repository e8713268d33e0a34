#version 450
// ssaax4: the 4x supersampling resolve, Mitchell-Netravali with direct taps at texel
// centres (spec ppaa.md "x4 and other factors"; the CPU's src/aa/resolve.cpp): a 16 x 16
// kernel without its four corner taps, normalised by the weight sum. Output pixel x has
// its centre at source position 4 x + 2, so tap d (-8..7) is always at t = d + 0.5 and its
// weight k(t / 4) is the same for every pixel: tables.mitchell4, from the CPU's mitchell().
#include "ppaa.glsl"

void main() {
    ivec2 p;
    if (!outputPixel(p)) return;
    const int firstX = 4 * p.x + 2 - 8, firstY = 4 * p.y + 2 - 8;
    EXACT vec3 sum = vec3(0.0);
    EXACT float wsum = 0.0;
    for (int j = 0; j < 16; ++j) {
        for (int i = 0; i < 16; ++i) {
            if ((i == 0 || i == 15) && (j == 0 || j == 15)) continue;  // wide kernels skip their corners
            EXACT float w = tables.mitchell4[i] * tables.mitchell4[j];
            sum = sum + texelValue(firstX + i, firstY + j) * w;
            wsum = wsum + w;
        }
    }
    const vec3 r = vec3(divide(sum.r, wsum), divide(sum.g, wsum), divide(sum.b, wsum));
    store(p, r, alphaAt(4 * p.x, 4 * p.y));
}
