#version 450
// GTAO pass 1b: one level of the depth chain (spec gtao.md section 4; the CPU's chainLevel in
// src/ao/gtao.cpp): level m + 1 (regionW x regionH = max(1, w / 2) x max(1, h / 2)) from
// level m (srcW x srcH), reads beyond its edge clamped. In t = -z (> 0): each of the 2x2
// values weighs clamp((0.75 Re - (tmax - t)) / (f 0.75 Re), 0, 1) against the block's
// farthest tmax, and the level holds their weighted mean; sky anywhere in the block is sky.
// The levels are stored as z (= -t, exact), the convention of the AO family's images.
#define SSFX_GTAO_TABLES_BINDING 2
#include "gtao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D finer;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D coarser;

float tAt(int x, int y) { return -imageLoad(finer, ivec2(min(x, pc.srcW - 1), min(y, pc.srcH - 1))).r; }

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const float t[4] = float[4](tAt(2 * p.x, 2 * p.y), tAt(2 * p.x + 1, 2 * p.y), tAt(2 * p.x, 2 * p.y + 1),
                                tAt(2 * p.x + 1, 2 * p.y + 1));
    const float tmax = max(max(t[0], t[1]), max(t[2], t[3]));
    float v = tmax;  // sky (+infinity) when the block holds any
    if (!isinf(tmax)) {
        precise float sum = 0.0, wsum = 0.0;
        for (int i = 0; i < 4; ++i) {
            precise float num = gt.rp - (tmax - t[i]);
            const float w = clamp(crDiv(num, gt.fRp), 0.0, 1.0);
            sum += w * t[i];
            wsum += w;
        }
        v = crDiv(sum, wsum);  // wsum >= 1: the farthest weighs 1
    }
    imageStore(coarser, p, vec4(-v));
}
