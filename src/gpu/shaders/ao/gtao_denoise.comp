#version 450
// GTAO pass 3: one 3x3 pass of the edge-aware denoiser (spec gtao.md section 8; the CPU's
// GtaoDenoise in src/ao/gtao_pixel.hpp), or, with denoisePasses 0, A clamped to [0, 1].
// A is read over the work region (srcX, srcY, srcW x srcH in buffer pixels; the image holds
// that region), neighbours clamped to it; the pass writes the dispatch region: into the
// work-region image (a middle pass), or into the output (the last pass, or the copy; the
// region is then the output region). Mode (pc.levels): 0 copy, 1 a middle pass (centre
// weight betaMiddle, xegtaoStorage's 8 bits after), 2 the last (betaLast, clamped).
#define SSFX_GTAO_TABLES_BINDING 4
#include "gtao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D aIn;     // work region
layout(set = 0, binding = 1, r32f) uniform writeonly image2D aOut;   // work region or output
layout(set = 0, binding = 2, r32f) uniform readonly image2D z0;      // buffer pixels
layout(set = 0, binding = 3, r32f) uniform readonly image2D edges;   // work region

// float(q) / 3 correctly rounded for q = 0 .. 3 (the CPU's division), as constants: 1/3 and
// 2/3 rounded to float.
const float kThirds[4] = float[4](0.0, 0.3333333432674408, 0.6666666865348816, 1.0);
float edgeOf(int packed, int side) { return kThirds[(packed >> (2 * side)) & 3]; }

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const ivec2 origin = ivec2(pc.srcX, pc.srcY);
    const ivec2 at = ivec2(pc.regionX, pc.regionY) + p;  // buffer pixel
    const int mode = pc.levels;
    float result;
    if (mode == 0) {
        result = clamp(imageLoad(aIn, at - origin).r, 0.0, 1.0);
    } else if (isinf(imageLoad(z0, at).r)) {
        result = 1.0;
    } else {
        const ivec2 lo = origin, hi = origin + ivec2(pc.srcW, pc.srcH) - 1;
        const int xm = max(at.x - 1, lo.x), xp = min(at.x + 1, hi.x);
        const int ym = max(at.y - 1, lo.y), yp = min(at.y + 1, hi.y);
        // C, L, R, T, B, TL, TR, BL, BR
        const ivec2 q[9] = ivec2[9](at, ivec2(xm, at.y), ivec2(xp, at.y), ivec2(at.x, ym), ivec2(at.x, yp),
                                    ivec2(xm, ym), ivec2(xp, ym), ivec2(xm, yp), ivec2(xp, yp));
        int e[9];
        bool sky[9];
        for (int i = 0; i < 9; ++i) {
            e[i] = int(imageLoad(edges, q[i] - origin).r);
            sky[i] = isinf(imageLoad(z0, q[i]).r);
        }
        const int C = 0, L = 1, R = 2, T = 3, B = 4, TL = 5, TR = 6, BL = 7, BR = 8;
        const int SL = 0, SR = 1, ST = 2, SB = 3;
        precise float eL = edgeOf(e[C], SL) * edgeOf(e[L], SR), eR = edgeOf(e[C], SR) * edgeOf(e[R], SL);
        precise float eT = edgeOf(e[C], ST) * edgeOf(e[T], SB), eB = edgeOf(e[C], SB) * edgeOf(e[B], ST);
        precise float total = ((eL + eR) + eT) + eB;
        precise float leak = crDiv(clamp(1.5 - total, 0.0, 1.0), 1.5) * 0.5;
        precise float l0 = eL + leak, l1 = eR + leak, l2 = eT + leak, l3 = eB + leak;
        eL = clamp(l0, 0.0, 1.0), eR = clamp(l1, 0.0, 1.0), eT = clamp(l2, 0.0, 1.0), eB = clamp(l3, 0.0, 1.0);
        float w[9];
        w[C] = mode == 2 ? gt.betaLast : gt.betaMiddle;
        w[L] = eL, w[R] = eR, w[T] = eT, w[B] = eB;
        precise float wTL = 0.425 * (eL * edgeOf(e[L], ST) + eT * edgeOf(e[T], SL));
        precise float wTR = 0.425 * (eT * edgeOf(e[T], SR) + eR * edgeOf(e[R], ST));
        precise float wBL = 0.425 * (eB * edgeOf(e[B], SL) + eL * edgeOf(e[L], SB));
        precise float wBR = 0.425 * (eR * edgeOf(e[R], SB) + eB * edgeOf(e[B], SR));
        w[TL] = wTL, w[TR] = wTR, w[BL] = wBL, w[BR] = wBR;
        precise float sum = 0.0, wsum = 0.0;
        for (int i = 0; i < 9; ++i) {
            if (sky[i]) continue;
            sum += w[i] * imageLoad(aIn, q[i] - origin).r;
            wsum += w[i];
        }
        result = crDiv(sum, wsum);
        if (mode == 2)
            result = clamp(result, 0.0, 1.0);
        else if (gt.xegtaoStorage != 0)
            result = gtaoStore(result);
    }
    const bool intoWork = mode == 1;
    imageStore(aOut, intoWork ? at - origin : p, vec4(result));
}
