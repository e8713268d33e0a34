// Shared by every anti-aliasing pass: bindings, the GPU sampling model of spec ppaa.md
// section 1 (the CPU's ssfx::Texture, Filtering::Gpu), luma, and exact float helpers.
//
// Exactness. The `model` sampling mode must give the CPU's bytes on any device. Vulkan
// rounds float add, subtract and multiply correctly, but lets a compiler fuse a * b + c
// into one fma and does not require division or square root to be correctly rounded. So:
//  - every float computation is `precise` (SPIR-V NoContraction: no fusing, the written
//    order);
//  - division and square root go through crDiv and crSqrt, which correct the device's
//    result to the correctly rounded one with an exact residual (Dekker's product);
//  - filtered values come from the CPU's own table of k / 4080 (no division at all);
//  - the final byte is computed exactly from the float's bits (toUnorm8), not by the
//    device's float-to-unorm conversion.
#extension GL_GOOGLE_include_directive : require
#include "aa_constants.h"

layout(local_size_x = SSFX_AA_GROUP, local_size_y = SSFX_AA_GROUP) in;


layout(set = 0, binding = SSFX_AA_BINDING_INPUT) uniform sampler2D src;
layout(set = 0, binding = SSFX_AA_BINDING_OUTPUT, rgba8) uniform writeonly image2D dst;
layout(set = 0, binding = SSFX_AA_BINDING_TABLES, std430) readonly buffer Tables {
    float sixteenth[SSFX_AA_SIXTEENTH_COUNT];
    float unorm8[SSFX_AA_UNORM_COUNT];
    float mitchell4[SSFX_AA_MITCHELL4_COUNT];
} tables;
layout(push_constant, std430) uniform Push {
    AaConstants pc;
};

// ---- exact float helpers ------------------------------------------------------------------

// a * b == p + e exactly (Dekker 1971, with Veltkamp's split; needs only correctly rounded
// multiply and add, which Vulkan guarantees).
void twoProduct(float a, float b, out float p, out float e) {
    precise float pp = a * b;
    precise float ca = 4097.0 * a;
    precise float ah = ca - (ca - a);
    precise float al = a - ah;
    precise float cb = 4097.0 * b;
    precise float bh = cb - (cb - b);
    precise float bl = b - bh;
    precise float ee = ((ah * bh - pp) + ah * bl + al * bh) + al * bl;
    p = pp;
    e = ee;
}

// The next float from q towards +inf (dir > 0) or -inf; q finite and non-zero.
float nextFloat(float q, float dir) {
    const uint bits = floatBitsToUint(q);
    return uintBitsToFloat((q > 0.0) == (dir > 0.0) ? bits + 1u : bits - 1u);
}

// |a - q b| (division a / b) or |a - q q| (square root of a; b unused), to compare
// candidate results: exact up to the last subtraction's rounding, far below the difference
// between neighbouring candidates.
float residual(bool root, float a, float b, float q) {
    float p, e;
    twoProduct(q, root ? q : b, p, e);
    precise float r = (a - p) - e;
    return abs(r);
}

// The smaller of the gaps between q and its two neighbouring floats (q finite, non-zero).
float minGap(float q) {
    precise float up = nextFloat(q, 1.0) - q;
    precise float down = q - nextFloat(q, -1.0);
    return min(abs(up), abs(down));
}

// The device's result q of a / b or sqrt(a), correctly rounded: kept when its residual r
// shows it is (the usual case: one exact product), else moved to a neighbour while that
// one has the smaller residual, at most `steps` times.
float correctlyRounded(bool root, float a, float b, float q, float r, int steps) {
    for (int i = 0; i < steps; ++i) {
        const float up = nextFloat(q, 1.0), down = nextFloat(q, -1.0);
        const float ru = residual(root, a, b, up), rd = residual(root, a, b, down);
        if (ru < r && ru <= rd) {
            q = up;
            r = ru;
        } else if (rd < r) {
            q = down;
            r = rd;
        } else {
            break;
        }
    }
    return q;
}

// a / b correctly rounded (IEEE), from the device's quotient (Vulkan allows 2.5 ulp, and
// compilers may turn it into a multiplication by the reciprocal). q is the correctly
// rounded quotient when |a - q b| < |b| gap / 2 (gap: the smaller distance to q's
// neighbours; tested against 0.49, a little under half).
float crDiv(float a, float b) {
    precise float q = a / b;
    if (isinf(q) || isnan(q) || q == 0.0) return q;
    const float r = residual(false, a, b, q);
    precise float bound = 0.49 * abs(b) * minGap(q);
    return r < bound ? q : correctlyRounded(false, a, b, q, r, 3);
}

// sqrt(x) correctly rounded, from the device's (Vulkan: "inherited from 1 / inversesqrt").
// s is correctly rounded when |x - s^2| < s gap, as (s +- gap / 2)^2 = s^2 +- s gap +
// gap^2 / 4 (tested against 0.98 s gap).
float crSqrt(float x) {
    precise float s = sqrt(x);
    if (!(x > 0.0) || isinf(x)) return s;
    const float r = residual(true, x, 0.0, s);
    precise float bound = 0.98 * s * minGap(s);
    return r < bound ? s : correctlyRounded(true, x, 0.0, s, r, 2);
}

// ssfx::toUnorm8: v in [0, 1] (NaN: 0) to round-half-up(v * 255), with the product exact:
// v = M 2^-s with a 24-bit M, so v * 255 = (255 M) 2^-s and 255 M fits in 32 bits.
uint toUnorm8(float v) {
    if (!(v > 0.0)) return 0u;
    if (v >= 1.0) return 255u;
    int e;
    const float f = frexp(v, e);  // v = f 2^e, f in [0.5, 1)
    const uint m = uint(ldexp(f, 24));
    const int s = 24 - e;  // v = m 2^-s, s >= 24 (e <= 0)
    if (s >= 33) return 0u;  // v * 255 < 2^32 2^-33 = 0.5
    const uint q = m * 255u;
    // floor(q 2^-s + 0.5) = (q >> s) + bit s - 1 of q
    return (s == 32 ? 0u : q >> uint(s)) + ((q >> uint(s - 1)) & 1u);
}

// ---- the texture ---------------------------------------------------------------------------

// k / 4080 and v / 255 rounded to float32, from the CPU's own tables. (Not a division in the
// shader: even lavapipe turns a division by a constant into a multiplication by its
// reciprocal, which is one rounding too many.)
float sixteenthLevel(uint k) { return tables.sixteenth[k]; }
float unormLevel(uint v) { return tables.unorm8[v]; }

// The 8-bit texel (x, y), clamped to the image (clamp-to-edge addressing).
uvec3 texel8(int x, int y) {
    const vec4 t = texelFetch(src, ivec2(clamp(x, 0, pc.width - 1), clamp(y, 0, pc.height - 1)), 0);
    return uvec3(round(t.rgb * 255.0));
}
vec3 fetchValue(int x, int y) {
    const uvec3 t = texel8(x, y);
    return vec3(unormLevel(t.r), unormLevel(t.g), unormLevel(t.b));
}

// Texture coordinate of pixel x's centre: (x + 0.5) / W in float32.
float centreU(int x) {
    precise float c = float(x) + 0.5;
    return crDiv(c, pc.fw);
}
float centreV(int y) {
    precise float c = float(y) + 0.5;
    return crDiv(c, pc.fh);
}

// A coordinate split into texel index and 8-bit sub-texel weight (ssfx::Texture::axis).
struct AxisPos {
    int index;  // floor(coord * size - 0.5), clamped to [-4, size + 4]
    int w;      // the fraction rounded half up to 1/256: 0..256
};
AxisPos axisPos(float coord, float size, int n) {
    precise float t = coord * size - 0.5;
    precise float fl = floor(t);
    const float lim = float(n) + 4.0;
    const float flc = fl >= -4.0 ? (fl < lim ? fl : lim) : -4.0;
    precise float frac = t - fl;
    precise float scaled = frac * 256.0 + 0.5;
    return AxisPos(int(flc), frac >= 0.0 ? int(scaled) : 0);
}
AxisPos axisU(float u) { return axisPos(u, pc.fw, pc.width); }
AxisPos axisV(float v) { return axisPos(v, pc.fh, pc.height); }

// The GPU-model bilinear read at split coordinates plus integer texel offsets: exact
// integer weights in 1/65536, the sum rounded half up to 1/16 of a level (spec section 1).
vec3 sampleModel(AxisPos ax, AxisPos ay, int ox, int oy) {
    const int x0 = ax.index + ox, y0 = ay.index + oy;
    const uvec3 t00 = texel8(x0, y0), t10 = texel8(x0 + 1, y0);
    const uvec3 t01 = texel8(x0, y0 + 1), t11 = texel8(x0 + 1, y0 + 1);
    const uint w00 = uint((256 - ax.w) * (256 - ay.w)), w10 = uint(ax.w * (256 - ay.w));
    const uint w01 = uint((256 - ax.w) * ay.w), w11 = uint(ax.w * ay.w);
    const uvec3 sum = w00 * t00 + w10 * t10 + w01 * t01 + w11 * t11;
    const uvec3 k = (sum + 2048u) >> 12u;
    return vec3(sixteenthLevel(k.r), sixteenthLevel(k.g), sixteenthLevel(k.b));
}

// A bilinear read at texture coordinate (u, v) plus an integer texel offset: the model, or
// the device's sampler (the offset added in texture units: not exact, the fast path).
vec3 sampleAt(float u, float v, int ox, int oy) {
    if (pc.sampling != 0) {
        precise float su = u + float(ox) * pc.invW;
        precise float sv = v + float(oy) * pc.invH;
        return textureLod(src, vec2(su, sv), 0.0).rgb;
    }
    return sampleModel(axisU(u), axisV(v), ox, oy);
}
vec3 sampleUV(float u, float v) { return sampleAt(u, v, 0, 0); }

// ---- luma and output -----------------------------------------------------------------------

// sqrt(0.299 r + 0.587 g + 0.114 b), summed left to right (spec section 1).
float luma(vec3 c) {
    precise float l = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
    return crSqrt(l);
}
// ssfx::edgeLuma: luma plus chromaWeight times max - min of R, G, B.
float edgeLuma(vec3 c) {
    const float l = luma(c);
    if (pc.chromaWeight == 0.0) return l;
    const float hi = c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
    const float lo = c.r < c.g ? (c.r < c.b ? c.r : c.b) : (c.g < c.b ? c.g : c.b);
    precise float e = l + pc.chromaWeight * (hi - lo);
    return e;
}
// ---- the work group's tile: the texels of its pixels and a one-pixel border, decoded, with
// their luma (the CPU's luma plane), in workgroup memory. Shaders that read the 3x3
// neighbourhood define SSFX_TILE and call loadTile() first, in uniform control flow.
#ifdef SSFX_TILE
const int kTile = SSFX_AA_GROUP + 2;
shared vec3 tileRgb[kTile * kTile];
#ifndef SSFX_TILE_NO_LUMA
shared float tileLuma[kTile * kTile];
#endif
ivec2 tileOrigin() { return ivec2(gl_WorkGroupID.xy) * SSFX_AA_GROUP - 1; }
void loadTile() {
    const ivec2 origin = tileOrigin();
    for (int i = int(gl_LocalInvocationIndex); i < kTile * kTile; i += SSFX_AA_GROUP * SSFX_AA_GROUP) {
        const vec3 c = fetchValue(origin.x + i % kTile, origin.y + i / kTile);
        tileRgb[i] = c;
#ifndef SSFX_TILE_NO_LUMA
        tileLuma[i] = edgeLuma(c);
#endif
    }
    barrier();
}
// Texel (x, y) of the group's pixels or their border, clamped to the image like a fetch
// (the tile's border texels were fetched clamped).
int tileIndex(int x, int y) {
    const ivec2 q = ivec2(x, y) - tileOrigin();
    return q.y * kTile + q.x;
}
vec3 texelValue(int x, int y) { return tileRgb[tileIndex(x, y)]; }
#ifndef SSFX_TILE_NO_LUMA
float lumaAt(int x, int y) { return tileLuma[tileIndex(x, y)]; }
#else
float lumaAt(int x, int y) { return edgeLuma(texelValue(x, y)); }  // (unused: no luma)
#endif
#else
vec3 texelValue(int x, int y) { return fetchValue(x, y); }
float lumaAt(int x, int y) { return edgeLuma(fetchValue(x, y)); }
#endif

// The output pixel: the colour quantised exactly (model) or by the device (hardware), alpha
// from `alpha` (an 8-bit value).
void store(ivec2 p, vec3 c, uint alpha) {
    if (pc.sampling != 0) {
        imageStore(dst, p, vec4(clamp(c, 0.0, 1.0), float(alpha) / 255.0));
        return;
    }
    const uvec3 b = uvec3(toUnorm8(c.r), toUnorm8(c.g), toUnorm8(c.b));
    imageStore(dst, p, vec4(vec3(b), float(alpha)) / 255.0);
}
// The input pixel unchanged.
void storeInput(ivec2 p) {
    imageStore(dst, p, texelFetch(src, p, 0));
}
uint alphaAt(int x, int y) {
    return uint(round(texelFetch(src, ivec2(x, y), 0).a * 255.0));
}

// ---- the 3x3 luma neighbourhood, early exit, edge sides (src/aa/ppaa_common.hpp) -----------

// Names as in the reference shader: S = (0, -1) is the row above, N = (0, +1) the row below.
struct Luma3x3 {
    float C, W, E, S, N, SW, NW, SE, NE;
};
Luma3x3 neighbourhood(int x, int y) {
    Luma3x3 n;
    n.C = lumaAt(x, y);
    n.W = lumaAt(x - 1, y);
    n.E = lumaAt(x + 1, y);
    n.S = lumaAt(x, y - 1);
    n.N = lumaAt(x, y + 1);
    n.SW = lumaAt(x - 1, y - 1);
    n.NW = lumaAt(x - 1, y + 1);
    n.SE = lumaAt(x + 1, y - 1);
    n.NE = lumaAt(x + 1, y + 1);
    return n;
}
float maxf(float a, float b) { return a < b ? b : a; }
float minf(float a, float b) { return b < a ? b : a; }

// True when the pixel stays unchanged; `range` = lumaMax - lumaMin over the centre and its
// four direct neighbours.
bool belowEdgeThreshold(Luma3x3 n, out float range) {
    const float lumaMax = maxf(maxf(maxf(n.S, n.N), maxf(n.W, n.E)), n.C);
    const float lumaMin = minf(minf(minf(n.S, n.N), minf(n.W, n.E)), n.C);
    precise float r = lumaMax - lumaMin;
    precise float t = lumaMax * pc.edgeThreshold;
    range = r;
    return r < maxf(pc.edgeThresholdMin, t);
}

struct EdgeSides {
    bool horizontal;  // the edge runs along x; "across" is y
    float luma1, luma2;
    float g1, g2;  // luma1 - C, luma2 - C
};
EdgeSides edgeSides(Luma3x3 n) {
    precise float edgeH = abs(-2.0 * n.W + (n.SW + n.NW)) + abs(-2.0 * n.C + (n.S + n.N)) * 2.0 +
                          abs(-2.0 * n.E + (n.SE + n.NE));
    precise float edgeV = abs(-2.0 * n.N + (n.NE + n.NW)) + abs(-2.0 * n.C + (n.W + n.E)) * 2.0 +
                          abs(-2.0 * n.S + (n.SW + n.SE));
    EdgeSides s;
    s.horizontal = edgeH >= edgeV;
    s.luma1 = s.horizontal ? n.S : n.W;
    s.luma2 = s.horizontal ? n.N : n.E;
    precise float g1 = s.luma1 - n.C;
    precise float g2 = s.luma2 - n.C;
    s.g1 = g1;
    s.g2 = g2;
    return s;
}

// The invocation's pixel, or false when it lies outside the output.
bool outputPixel(out ivec2 p) {
    p = ivec2(gl_GlobalInvocationID.xy);
    return p.x < pc.outWidth && p.y < pc.outHeight;
}
