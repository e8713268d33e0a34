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
// The segments path (gpu::EdgePath::Segments, CPU devices): one invocation per SSFX_AA_SEGMENT
// pixels of a row, each texel of the three rows fetched and decoded once (3 (S + 2) fetches
// for S pixels against 9 S), three columns live at a time. The same values in the same sums,
// so the same bytes.
void main() {
    const int xs = int(gl_GlobalInvocationID.x) * SSFX_AA_SEGMENT, y = int(gl_GlobalInvocationID.y);
    if (xs >= pc.outWidth || y >= pc.outHeight) return;
    // Columns x - 1, x, x + 1 of the rows above (a), the pixel's (m) and below (b).
    vec3 a0 = texelValue(xs - 1, y - 1), m0 = texelValue(xs - 1, y), b0 = texelValue(xs - 1, y + 1);
    vec3 a1 = texelValue(xs, y - 1), b1 = texelValue(xs, y + 1);
    vec4 r1 = texelRaw(xs, y);
    vec3 m1 = texelDecoded(r1);
    for (int i = 0; i < SSFX_AA_SEGMENT; ++i) {
        const int x = xs + i;
        const vec3 a2 = texelValue(x + 1, y - 1), b2 = texelValue(x + 1, y + 1);
        const vec4 r2 = texelRaw(x + 1, y);
        const vec3 m2 = texelDecoded(r2);
        if (x < pc.outWidth) store(ivec2(x, y), blurred(m1, m0, m2, a0, a1, a2, b0, b1, b2), uint(round(r1.a * 255.0)));
        a0 = a1, m0 = m1, b0 = b1;
        a1 = a2, m1 = m2, b1 = b2, r1 = r2;
    }
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
