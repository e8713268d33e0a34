#version 450
// GTAO pass 2a: the edges and the normals from depth of the work region (spec gtao.md
// sections 5.1 and 6; the CPU's gtaoEdges, quantiseEdges and gtaoNormalFromDepth in
// src/ao/gtao_pixel.hpp). Edges L, R, T, B from level-0 t with the slope through the centre
// taken out, stored as XeGTAO packs them (roundEven(2.9 e) in 0..3 each, L + 4 R + 16 T +
// 64 B, as a float); the normal from the four neighbours' positions weighted by the
// unquantised edges. Sky: edges 0, normal (0, 0, 0). Neighbours beyond the buffer read the
// edge texel's t at their own position.
#define SSFX_GTAO_TABLES_BINDING 3
#include "gtao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D z0;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D edgesOut;    // work region
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D normalsOut;  // work region

float tAt(int x, int y) { return -imageLoad(z0, clamp(ivec2(x, y), ivec2(0), ivec2(pc.width, pc.height) - 1)).r; }

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const int x = pc.regionX + p.x, y = pc.regionY + p.y;
    const float tc = tAt(x, y);
    float e[4] = float[4](0.0, 0.0, 0.0, 0.0);
    vec3 n = vec3(0.0);
    if (!isinf(tc)) {
        const ivec2 nb[4] = ivec2[4](ivec2(x - 1, y), ivec2(x + 1, y), ivec2(x, y - 1), ivec2(x, y + 1));
        float tn[4], dt[4];
        bool sky[4];
        for (int i = 0; i < 4; ++i) {
            tn[i] = tAt(nb[i].x, nb[i].y);
            sky[i] = isinf(tn[i]);
            precise float d = tn[i] - tc;
            dt[i] = sky[i] ? 0.0 : d;
        }
        precise float sLR = (dt[1] - dt[0]) * 0.5, sTB = (dt[3] - dt[2]) * 0.5;
        precise float adj[4] = float[4](dt[0] + sLR, dt[1] - sLR, dt[2] + sTB, dt[3] - sTB);
        precise float scale = tc * 0.011;
        for (int i = 0; i < 4; ++i) {
            if (sky[i]) continue;
            const float m = sky[i ^ 1] ? abs(dt[i]) : min(abs(dt[i]), abs(adj[i]));
            precise float v = 1.25 - crDiv(m, scale);
            e[i] = clamp(v, 0.0, 1.0);
        }
        // Section 6: right-handed camera space, the reverse of XeGTAO's order.
        const vec3 c = gtaoPosition(x, y, -tc);
        vec3 u[4];
        for (int i = 0; i < 4; ++i) {
            precise vec3 d = gtaoPosition(nb[i].x, nb[i].y, -tn[i]) - c;
            u[i] = sky[i] ? vec3(0.0) : gtaoUnitOrZero(d);
        }
        const int L = 0, R = 1, T = 2, B = 3;
        float a[4];  // LT, TR, RB, BL
        const ivec2 pairs[4] = ivec2[4](ivec2(L, T), ivec2(T, R), ivec2(R, B), ivec2(B, L));
        for (int k = 0; k < 4; ++k) {
            const int i = pairs[k].x, j = pairs[k].y;
            precise float w = e[i] * e[j] + 0.01;
            a[k] = sky[i] || sky[j] ? 0.0 : clamp(w, 0.0, 1.0);
        }
        const vec3 cLT = gtaoCross(u[T], u[L]), cTR = gtaoCross(u[R], u[T]), cRB = gtaoCross(u[B], u[R]),
                   cBL = gtaoCross(u[L], u[B]);
        precise vec3 s = ((a[0] * cLT + a[1] * cTR) + a[2] * cRB) + a[3] * cBL;
        n = gtaoUnitOrZero(s);
    }
    int packed = 0;
    for (int i = 0; i < 4; ++i) {
        precise float q = 2.9 * e[i];
        packed |= int(roundEven(q)) << (2 * i);
    }
    imageStore(edgesOut, p, vec4(float(packed)));
    imageStore(normalsOut, p, vec4(n, 0.0));
}
