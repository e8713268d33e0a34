#version 450
// blur: 3x3 truncated Gaussian (DDAA paper section 3.1; spec ppaa.md "blur"; the CPU's
// src/aa/blur_kernel.hpp). Weights from gpu::aaConstants (the CPU's blurWeights). Texel
// reads only, so both sampling modes give the CPU's bytes. No workgroup tile (its loads cost
// more than the fetches on lavapipe, and blur has no luma to share).
#include "ppaa.glsl"

// One output pixel from its 3x3 neighbourhood: the centre c, the row above (a: left, mid,
// right), the pixel's own row's left and right, the row below (b). Sum order: centre, the
// direct neighbours W, E, S, N, then the corners (the CPU's).
vec3 blurred(vec3 c, vec3 w, vec3 e, vec3 aw, vec3 a, vec3 ae, vec3 bw, vec3 b, vec3 be) {
    EXACT vec3 direct = ((w + e) + (a + b)) * pc.blurW1;
    EXACT vec3 corner = ((aw + ae) + (bw + be)) * pc.blurW2;
    EXACT vec3 result = ((c + direct) + corner) * pc.blurNorm;
    return result;
}

#ifdef SSFX_AA_SEGMENTS_MODULE
// The segments path (gpu::EdgePath::Segments, CPU devices; ppaa.glsl's segmentLane): each lane
// fetches and decodes the 10 texels of its own row around its pixels and of one more row, and
// takes the rows above and below from its neighbouring lanes (subgroupShuffle): 2 (S + 2)
// fetches for S pixels (2.5 a pixel; 9 one pixel an invocation), the same values in the same
// sums: the same bytes. Every invocation reaches the shuffles.
void main() {
    const SegmentLane s = segmentLane();
    const int xs = s.xs, y = s.y;
    const uint lane = gl_SubgroupInvocationID;
    // Columns xs - 1 .. xs + S of the rows above (a), the pixel's (m) and below (b).
    vec3 a[SSFX_AA_SEGMENT + 2], m[SSFX_AA_SEGMENT + 2], b[SSFX_AA_SEGMENT + 2];
    float alpha[SSFX_AA_SEGMENT];
    for (int i = 0; i < SSFX_AA_SEGMENT + 2; ++i) {
        const vec4 r = texelRaw(xs - 1 + i, y);
        m[i] = texelDecoded(r);
        if (i >= 1 && i <= SSFX_AA_SEGMENT) alpha[i - 1] = r.a;
        const vec3 extra = texelValue(xs - 1 + i, s.extraY);
        const vec3 above = subgroupShuffle(m[i], lane - 1u), below = subgroupShuffle(m[i], lane + 1u);
        a[i] = s.haveAbove ? above : extra;
        b[i] = s.haveBelow ? below : extra;
    }
    if (xs >= pc.outWidth || y >= pc.outHeight) return;
    for (int i = 0; i < SSFX_AA_SEGMENT; ++i)
        if (xs + i < pc.outWidth)
            store(ivec2(xs + i, y), blurred(m[i + 1], m[i], m[i + 2], a[i], a[i + 1], a[i + 2], b[i], b[i + 1], b[i + 2]),
                  uint(round(alpha[i] * 255.0)));
}
#else
void main() {
    ivec2 p;
    if (!outputPixel(p)) return;
    const int x = p.x, y = p.y;
    // S = (0, -1) is the row above, N = (0, +1) the row below (ppaa.glsl's names).
    const vec3 c = texelValue(x, y), w = texelValue(x - 1, y), e = texelValue(x + 1, y);
    const vec3 s = texelValue(x, y - 1), n = texelValue(x, y + 1);
    const vec3 sw = texelValue(x - 1, y - 1), se = texelValue(x + 1, y - 1);
    const vec3 nw = texelValue(x - 1, y + 1), ne = texelValue(x + 1, y + 1);
    store(p, blurred(c, w, e, sw, s, se, nw, n, ne), alphaAt(x, y));
}
#endif
