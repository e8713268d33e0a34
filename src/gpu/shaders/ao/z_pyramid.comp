#version 450
// Pass 2: one level of the z pyramid (SAO paper section 2.2 and Table 1; spec sao.md
// "Passes" 2; the CPU's ao::zPyramidLevel): level m + 1 (regionW x regionH, max(1, w / 2) x
// max(1, h / 2) of level m) from level m (srcW x srcH), reads beyond level m's edge clamped.
// The filter is a specialization constant. Selections and the correctly rounded means give
// the CPU's bits from the same level m.
#include "ao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D finer;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D coarser;

float finerAt(int x, int y) { return imageLoad(finer, ivec2(min(x, pc.srcW - 1), min(y, pc.srcH - 1))).r; }

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const int x = p.x, y = p.y;
    float v;
    if (spec_filter == 0) {  // rotated grid: a real scene value, no averaging across depth edges
        v = finerAt(2 * x + (y & 1), 2 * y + (x & 1));
    } else {
        const float a = finerAt(2 * x, 2 * y), b = finerAt(2 * x + 1, 2 * y);
        const float c = finerAt(2 * x, 2 * y + 1), d = finerAt(2 * x + 1, 2 * y + 1);
        if (spec_filter == 1) {  // mean
            precise float s = ((a + b) + c) + d;
            precise float m = s * 0.25;
            v = m;
        } else if (spec_filter == 2) {  // harmonic mean: 4 / sum(1 / z); every z <= 0, so the
            // sum is -0 only when all four are sky (1 / -inf), and 4 / -0 = -inf
            precise float s = ((crDiv(1.0, a) + crDiv(1.0, b)) + crDiv(1.0, c)) + crDiv(1.0, d);
            v = s == 0.0 ? -1.0 / 0.0 : crDiv(4.0, s);
        } else if (spec_filter == 3) {  // min: the farthest
            v = min(min(a, b), min(c, d));
        } else {  // max: the nearest
            v = max(max(a, b), max(c, d));
        }
    }
    imageStore(coarser, p, vec4(v));
}
