#version 450
// fxaa3c: FXAA 3.11 "console" (T. Lottes, NVIDIA 2011): direction from the four diagonal
// lumas, two short and two long taps along it, no edge search (spec ppaa.md "fxaa3c"; the
// CPU's src/aa/fxaa3c.cpp). Diagonals at +-diagonalOffset pixels (the DDAA paper: 1).
#define SSFX_TILE
#include "ppaa.glsl"

// `atCentre`: the luma of pixel (x + sx, y + sy), used when the diagonals are at pixel centres.
float diagonal(int x, int y, int sx, int sy, float atCentre) {
    if (spec_diagonalsAtCentres != 0) return atCentre;
    const float u = centreU(x), v = centreV(y);
    EXACT float du = u + float(sx) * pc.diagonalU;
    EXACT float dv = v + float(sy) * pc.diagonalV;
    return edgeLuma(sampleUV(du, dv));
}

// clamp(q, -2, 2) with NaN giving -2, as the CPU's fmin(fmax(q, -2), 2).
float clampTwo(float q) { return isnan(q) ? -2.0 : clamp(q, -2.0, 2.0); }

// The diagonal lumas and the early-exit test (FXAA 3.11 console).
struct Lumas {
    float NW, SW, SE, NE;
    float lumaMin, lumaMax;
    bool edge;
};
// FXAA names y up: its NW is (x - 1, y - 1), Luma3x3's SW.
Lumas lumas(int x, int y, Luma3x3 n) {
    Lumas l;
    l.NW = diagonal(x, y, -1, -1, n.SW);
    l.SW = diagonal(x, y, -1, +1, n.NW);
    l.SE = diagonal(x, y, +1, +1, n.NE);
    EXACT float ne = diagonal(x, y, +1, -1, n.SE) + 1.0 / 384.0;  // FXAA: keeps dir from being 0
    l.NE = ne;
    const float lumaM = n.C;
    l.lumaMax = maxf(maxf(l.NE, l.SE), maxf(l.NW, l.SW));
    l.lumaMin = minf(minf(l.NE, l.SE), minf(l.NW, l.SW));
    EXACT float contrast = maxf(l.lumaMax, lumaM) - minf(l.lumaMin, lumaM);
    EXACT float relative = l.lumaMax * pc.edgeThreshold;
    l.edge = !(contrast < maxf(pc.edgeThresholdMin, relative));
    return l;
}

bool edgeAt(int x, int y, Luma3x3 n) { return lumas(x, y, n).edge; }

// The colour of an edge pixel: two short and two long taps along the direction.
vec3 edgeColour(int x, int y, Luma3x3 n) {
    const Lumas l = lumas(x, y, n);
    EXACT float swMinusNe = l.SW - l.NE;
    EXACT float seMinusNw = l.SE - l.NW;
    EXACT float dirX = swMinusNe + seMinusNw;
    EXACT float dirY = swMinusNe - seMinusNw;
    EXACT float len2 = dirX * dirX + dirY * dirY;
    const float len = squareRoot(len2);
    // No direction at all (exact float ties only): leave the pixel, as the CPU does.
    if (!(len > 0.0)) return texelValue(x, y);
    const float u = centreU(x), v = centreV(y);
    const float d1x = divide(dirX, len), d1y = divide(dirY, len);
    const float hs = 0.5;  // first pair of taps at +-0.5 px along the edge
    EXACT float n1u = u - d1x * hs * pc.invW;
    EXACT float n1v = v - d1y * hs * pc.invH;
    EXACT float p1u = u + d1x * hs * pc.invW;
    EXACT float p1v = v + d1y * hs * pc.invH;
    const vec3 n1 = sampleUV(n1u, n1v), p1 = sampleUV(p1u, p1v);
    EXACT float minAbs = minf(abs(d1x), abs(d1y)) * pc.edgeSharpness;
    const float d2x = clampTwo(divide(d1x, minAbs)), d2y = clampTwo(divide(d1y, minAbs));
    EXACT float n2u = u - d2x * 2.0 * pc.invW;
    EXACT float n2v = v - d2y * 2.0 * pc.invH;
    EXACT float p2u = u + d2x * 2.0 * pc.invW;
    EXACT float p2v = v + d2y * 2.0 * pc.invH;
    const vec3 n2 = sampleUV(n2u, n2v), p2 = sampleUV(p2u, p2v);
    EXACT vec3 A = n1 + p1;
    EXACT vec3 B = (n2 + p2) * 0.25 + A * 0.25;
    const float lumaB = edgeLuma(B);
    EXACT vec3 halfA = A * 0.5;
    return (lumaB < l.lumaMin || lumaB > l.lumaMax) ? halfA : B;
}

#include "edge_list.glsl"
