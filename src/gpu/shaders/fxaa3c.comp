#version 450
// fxaa3c: FXAA 3.11 "console" (T. Lottes, NVIDIA 2011): direction from the four diagonal
// lumas, two short and two long taps along it, no edge search (spec ppaa.md "fxaa3c"; the
// CPU's src/aa/fxaa3c.cpp). Diagonals at +-diagonalOffset pixels (the DDAA paper: 1).
#define SSFX_TILE
#include "ppaa.glsl"

float diagonal(int x, int y, int sx, int sy) {
    if (spec_diagonalsAtCentres != 0) return lumaAt(x + sx, y + sy);  // at pixel centres: the pixels
    const float u = centreU(x), v = centreV(y);
    precise float du = u + float(sx) * pc.diagonalU;
    precise float dv = v + float(sy) * pc.diagonalV;
    return edgeLuma(sampleUV(du, dv));
}

// clamp(q, -2, 2) with NaN giving -2, as the CPU's fmin(fmax(q, -2), 2).
float clampTwo(float q) { return isnan(q) ? -2.0 : clamp(q, -2.0, 2.0); }

// The colour of an edge pixel: two short and two long taps along the direction (FXAA
// 3.11 console); `unchanged` where the direction is 0.
vec3 edgeColour(int x, int y, float lumaNW, float lumaSW, float lumaSE, float lumaNE, float lumaMin, float lumaMax,
                vec3 unchanged) {
    precise float swMinusNe = lumaSW - lumaNE;
    precise float seMinusNw = lumaSE - lumaNW;
    precise float dirX = swMinusNe + seMinusNw;
    precise float dirY = swMinusNe - seMinusNw;
    precise float len2 = dirX * dirX + dirY * dirY;
    const float len = crSqrt(len2);
    // No direction at all (exact float ties only): leave the pixel, as the CPU does.
    if (!(len > 0.0)) return unchanged;
    const float u = centreU(x), v = centreV(y);
    const float d1x = crDiv(dirX, len), d1y = crDiv(dirY, len);
    const float hs = 0.5;  // first pair of taps at +-0.5 px along the edge
    precise float n1u = u - d1x * hs * pc.invW;
    precise float n1v = v - d1y * hs * pc.invH;
    precise float p1u = u + d1x * hs * pc.invW;
    precise float p1v = v + d1y * hs * pc.invH;
    const vec3 n1 = sampleUV(n1u, n1v), p1 = sampleUV(p1u, p1v);
    precise float minAbs = minf(abs(d1x), abs(d1y)) * pc.edgeSharpness;
    const float d2x = clampTwo(crDiv(d1x, minAbs)), d2y = clampTwo(crDiv(d1y, minAbs));
    precise float n2u = u - d2x * 2.0 * pc.invW;
    precise float n2v = v - d2y * 2.0 * pc.invH;
    precise float p2u = u + d2x * 2.0 * pc.invW;
    precise float p2v = v + d2y * 2.0 * pc.invH;
    const vec3 n2 = sampleUV(n2u, n2v), p2 = sampleUV(p2u, p2v);
    precise vec3 A = n1 + p1;
    precise vec3 B = (n2 + p2) * 0.25 + A * 0.25;
    const float lumaB = edgeLuma(B);
    precise vec3 halfA = A * 0.5;
    return (lumaB < lumaMin || lumaB > lumaMax) ? halfA : B;
}

void main() {
    loadTile();
    ivec2 p;
    if (!outputPixel(p)) return;
    const int x = p.x, y = p.y;
    const float lumaNW = diagonal(x, y, -1, -1), lumaSW = diagonal(x, y, -1, +1);
    const float lumaSE = diagonal(x, y, +1, +1);
    precise float lumaNE = diagonal(x, y, +1, -1) + 1.0 / 384.0;  // FXAA: keeps dir from being 0
    const float lumaM = lumaAt(x, y);
    const float lumaMax = maxf(maxf(lumaNE, lumaSE), maxf(lumaNW, lumaSW));
    const float lumaMin = minf(minf(lumaNE, lumaSE), minf(lumaNW, lumaSW));
    precise float contrast = maxf(lumaMax, lumaM) - minf(lumaMin, lumaM);
    precise float relative = lumaMax * pc.edgeThreshold;
    // The input pixel unless the contrast says edge (spec section 1's early exit).
    vec3 colour = texelValue(x, y);
    if (!(contrast < maxf(pc.edgeThresholdMin, relative)))
        colour = edgeColour(x, y, lumaNW, lumaSW, lumaSE, lumaNE, lumaMin, lumaMax, colour);
    store(p, colour, alphaAt(x, y));
}
