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
// The `hardware` mode is the same source compiled with SSFX_DEVICE_ARITHMETIC (a second
// SPIR-V module, CMake's VARIANT): the device's sampler and the device's own arithmetic,
// the fast path an engine would enable. EXACT is then no qualifier (the compiler may fuse
// and reorder), division and square root are the device's (divide, squareRoot), texels are
// the device's unorm decode and the output its float-to-unorm conversion. Its promise is
// the device's precision, not the CPU's bytes (docs/gpu.md gives the measured agreement).
#extension GL_GOOGLE_include_directive : require
#ifdef SSFX_AA_SEGMENTS_MODULE
// The edge methods' segments stage (edge_list.glsl) spreads a subgroup's edge pixels over its
// lanes; aa_pass.cpp takes its modules only where the device has these in compute shaders.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_shuffle : require
#endif
#include "aa_constants.h"

#ifdef SSFX_DEVICE_ARITHMETIC
#define EXACT
#else
#define EXACT precise
#endif

// The work-group size is specialized (aa_constants.h: groupX, groupY).
layout(local_size_x_id = 4, local_size_y_id = 5) in;

layout(set = 0, binding = SSFX_AA_BINDING_INPUT) uniform sampler2D src;
layout(set = 0, binding = SSFX_AA_BINDING_OUTPUT, rgba8) uniform writeonly image2D dst;
layout(set = 0, binding = SSFX_AA_BINDING_TABLES, std430) readonly buffer Tables {
    float mitchell4[SSFX_AA_MITCHELL4_COUNT];
    float srgbLevels[SSFX_AA_SRGB_LEVELS];          // texture=srgb: the CPU's kSrgb8
    int srgbPacked[SSFX_AA_SRGB_BUCKETS];           // texture=srgb: encodeSrgb8's buckets, packed
    float srgbDeviceLevels[SSFX_AA_SRGB_BUCKETS];   // texture=srgb, model: the device's decode to levels
}
tables;
layout(push_constant, std430) uniform Push { AaConstants pc; };

#include "../common/exact.glsl"  // shared by every family of passes
#include "srgb.glsl"

// a / b and sqrt(x): correctly rounded in the model (exact.glsl), the device's own in the
// hardware mode (Vulkan: 2.5 ulp for division, square root as 1 / inversesqrt).
float divide(float a, float b) {
#ifdef SSFX_DEVICE_ARITHMETIC
    return a / b;
#else
    return crDiv(a, b);
#endif
}
float squareRoot(float x) {
#ifdef SSFX_DEVICE_ARITHMETIC
    return sqrt(x);
#else
    return crSqrt(x);
#endif
}

// ---- the texture ---------------------------------------------------------------------------

// k / 4080 and v / 255 rounded to float32, as the CPU's tables (exact.glsl's levelOver4080).
float sixteenthLevel(uint k) { return levelOver4080(k); }
float unormLevel(uint v) { return levelOver4080(16u * v); }

// Texel (x, y) as fetched, clamped to the image (clamp-to-edge addressing). (Every fetch
// goes through here, so a compiler can merge two fetches of one texel.)
vec4 texelRaw(int x, int y) { return texelFetch(src, ivec2(clamp(x, 0, pc.width - 1), clamp(y, 0, pc.height - 1)), 0); }
// texture=srgb's exact encode (the CPU's encodeSrgb8, by its packed table: color.hpp's
// SrgbEncodeTable): the first level of v's bucket, plus one where v's offset in the bucket is
// at or above its threshold's; 0 below 2^-14 (and for NaN), 255 from 1. One load.
uint encodeSrgbExact(float v) {
    if (!(v >= uintBitsToFloat(SSFX_AA_SRGB_LOW_BITS))) return 0u;
    if (v >= 1.0) return 255u;
    const uint offset = floatBitsToUint(v) - SSFX_AA_SRGB_LOW_BITS;
    const uint e = uint(tables.srgbPacked[offset >> SSFX_AA_SRGB_SHIFT]);
    return (e >> 16u) + ((offset & SSFX_AA_SRGB_OFFSET_MASK) >= (e & 0xFFFFu) ? 1u : 0u);
}
// A fetched texel's 8-bit values: from the unorm value, or, through an sRGB view
// (spec_srgb), recovered from the device's decode (srgb.glsl; the pass checked that this
// gives every byte back on this device). (The exact encode's table gives them back too, but
// its three loads took longer than the three pows on lavapipe: ddaa2 texture=srgb 3.9-4.5x
// its unorm time against 3.2-3.6x, alternated runs on the photograph.)
uvec3 texelBytes(vec4 raw) {
    if (spec_srgb != 0) return srgbLevelsDevice(raw.rgb);
    return uvec3(round(raw.rgb * 255.0));
}
// The 8-bit texel (x, y).
uvec3 texel8(int x, int y) { return texelBytes(texelRaw(x, y)); }
// texture=srgb: the decoded level of an 8-bit value, the CPU's kSrgb8 (IEC 61966-2-1 in
// double, rounded to float).
vec3 srgbDecoded(uvec3 t) { return vec3(tables.srgbLevels[t.r], tables.srgbLevels[t.g], tables.srgbLevels[t.b]); }
// texture=srgb, model (spec_srgbDecodeTable): the level of a texel channel from the device's
// decoded value d, by the pass's table of the device's decode (aa_pass.cpp: each byte's d in a
// bucket of its own; below 2^-14 only byte 0's, from 1 only byte 255's).
float srgbLevelOfDecoded(float d) {
    if (!(d >= uintBitsToFloat(SSFX_AA_SRGB_LOW_BITS))) return 0.0;
    if (d >= 1.0) return 1.0;
    return tables.srgbDeviceLevels[(floatBitsToUint(d) - SSFX_AA_SRGB_LOW_BITS) >> SSFX_AA_SRGB_SHIFT];
}
// A fetched texel's value: v / 255 rounded to float32 (the CPU's table), or with
// texture=srgb its decoded level (the CPU's kSrgb8). The device's decode in the hardware
// mode; in the model too where the pass found it to be exactly that for all 256 values of the
// input's format (spec_deviceDecode, aa_pass.cpp's probes: a function of 256 inputs, checked
// on every one); else computed from the byte (lavapipe's unorm decode is one ulp off for
// 254, and devices' sRGB decodes are approximations).
vec3 texelDecoded(vec4 raw) {
#ifdef SSFX_DEVICE_ARITHMETIC
    return raw.rgb;
#else
    if (spec_deviceDecode != 0) return raw.rgb;
    if (spec_srgb != 0) {
        if (spec_srgbDecodeTable != 0)
            return vec3(srgbLevelOfDecoded(raw.r), srgbLevelOfDecoded(raw.g), srgbLevelOfDecoded(raw.b));
        return srgbDecoded(texelBytes(raw));
    }
    const uvec3 t = uvec3(round(raw.rgb * 255.0));
    return vec3(unormLevel(t.r), unormLevel(t.g), unormLevel(t.b));
#endif
}
vec3 fetchValue(int x, int y) { return texelDecoded(texelRaw(x, y)); }

// Texture coordinate of pixel x's centre: (x + 0.5) / W in float32.
float centreU(int x) {
    EXACT float c = float(x) + 0.5;
    return divide(c, pc.fw);
}
float centreV(int y) {
    EXACT float c = float(y) + 0.5;
    return divide(c, pc.fh);
}

// A coordinate split into texel index and 8-bit sub-texel weight (ssfx::Texture::axis).
struct AxisPos {
    int index;  // floor(coord * size - 0.5), clamped to [-4, size + 4]
    int w;      // the fraction rounded half up to 1/256: 0..256
};
AxisPos axisPos(float coord, float size, int n) {
    EXACT float t = coord * size - 0.5;
    EXACT float fl = floor(t);
    const float lim = float(n) + 4.0;
    const float flc = fl >= -4.0 ? (fl < lim ? fl : lim) : -4.0;
    EXACT float frac = t - fl;
    EXACT float scaled = frac * 256.0 + 0.5;
    return AxisPos(int(flc), frac >= 0.0 ? int(scaled) : 0);
}
AxisPos axisU(float u) { return axisPos(u, pc.fw, pc.width); }
AxisPos axisV(float v) { return axisPos(v, pc.fh, pc.height); }

// The GPU-model bilinear read at split coordinates plus integer texel offsets: exact
// integer weights in 1/65536, the sum rounded half up to 1/16 of a level (spec section 1).
// texture=srgb: the same weights on the decoded texels, summed in float32 in the CPU's
// order (ssfx::Texture::sampleGpuDecoded; no 1/16-level grid).
vec3 sampleModel(AxisPos ax, AxisPos ay, int ox, int oy) {
    const int x0 = ax.index + ox, y0 = ay.index + oy;
    const uint w00 = uint((256 - ax.w) * (256 - ay.w)), w10 = uint(ax.w * (256 - ay.w));
    const uint w01 = uint((256 - ax.w) * ay.w), w11 = uint(ax.w * ay.w);
    if (spec_srgb != 0) {
        const float unit = 1.0 / 65536.0;  // the weights are exact multiples of it
        EXACT vec3 sum = ((fetchValue(x0, y0) * (float(w00) * unit) + fetchValue(x0 + 1, y0) * (float(w10) * unit)) +
                          fetchValue(x0, y0 + 1) * (float(w01) * unit)) +
                         fetchValue(x0 + 1, y0 + 1) * (float(w11) * unit);
        return sum;
    }
    const uvec3 t00 = texel8(x0, y0), t10 = texel8(x0 + 1, y0);
    const uvec3 t01 = texel8(x0, y0 + 1), t11 = texel8(x0 + 1, y0 + 1);
    const uvec3 sum = w00 * t00 + w10 * t10 + w01 * t01 + w11 * t11;
    const uvec3 k = (sum + 2048u) >> 12u;
    return vec3(sixteenthLevel(k.r), sixteenthLevel(k.g), sixteenthLevel(k.b));
}

// The GPU-model read half-way between texels a and b (weights 128 and 0 or 256): the sum
// of sampleModel is 32768 (a + b), so k = 8 (a + b). Texels clamped like every fetch. The
// CPU's pair planes hold these values (src/aa/luma_planes.hpp).
// texture=srgb: 0.5 a + 0.5 b of the decoded texels (sampleModel's sum, whose other two
// products are zero).
vec3 pairRead(ivec2 a, ivec2 b) {
#ifdef SSFX_DEVICE_ARITHMETIC
    // The hardware mode (aa_pass.cpp takes this on CPU devices): the mean of the device's
    // decoded texels, what its bilinear filter returns there (weight exactly 1/2) up to its
    // own rounding. (With texture=srgb the decode is the sRGB view's, in linear light, as the
    // filter's.)
    return (fetchValue(a.x, a.y) + fetchValue(b.x, b.y)) * 0.5;
#else
    if (spec_srgb != 0) {
        EXACT vec3 half_ = fetchValue(a.x, a.y) * 0.5 + fetchValue(b.x, b.y) * 0.5;
        return half_;
    }
    const uvec3 k = 8u * (texel8(a.x, a.y) + texel8(b.x, b.y));
    return vec3(sixteenthLevel(k.r), sixteenthLevel(k.g), sixteenthLevel(k.b));
#endif
}

// A bilinear read at texture coordinate (u, v) plus an integer texel offset: the model, or
// the device's sampler (the offset added in texture units: not exact, the fast path).
vec3 sampleAt(float u, float v, int ox, int oy) {
    if (spec_sampling != 0) {
        EXACT float su = u + float(ox) * pc.invW;
        EXACT float sv = v + float(oy) * pc.invH;
        return textureLod(src, vec2(su, sv), 0.0).rgb;
    }
    return sampleModel(axisU(u), axisV(v), ox, oy);
}
vec3 sampleUV(float u, float v) { return sampleAt(u, v, 0, 0); }

// ---- luma and output -----------------------------------------------------------------------

// sqrt(0.299 r + 0.587 g + 0.114 b), summed left to right (spec section 1).
float luma(vec3 c) {
    EXACT float l = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
    return squareRoot(l);
}
// ssfx::edgeLuma: luma plus chromaWeight times max - min of R, G, B.
float edgeLuma(vec3 c) {
    const float l = luma(c);
    if (spec_chroma == 0) return l;
    const float hi = c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
    const float lo = c.r < c.g ? (c.r < c.b ? c.r : c.b) : (c.g < c.b ? c.g : c.b);
    EXACT float e = l + pc.chromaWeight * (hi - lo);
    return e;
}
// ---- the lumas of the 3x3 neighbourhoods (the CPU's luma plane): shaders that read them
// define SSFX_TILE. The two-pass dispatches (edge_list.glsl) read the luma plane that their
// LUMA dispatch wrote; stage 0 loads the work group's tile, the lumas of its pixels and a
// one-pixel border, in workgroup memory (loadTile(), first, in uniform control flow). Either
// way each texel's luma is computed once. Colours are fetched where they are used.
vec3 texelValue(int x, int y) { return fetchValue(x, y); }
#ifdef SSFX_TILE
const int kTile = SSFX_AA_GROUP + 2;
shared float tileLuma[kTile * kTile];
ivec2 tileOrigin() { return ivec2(gl_WorkGroupID.xy) * SSFX_AA_GROUP - 1; }
void loadTile() {
    const ivec2 origin = tileOrigin();
    for (int i = int(gl_LocalInvocationIndex); i < kTile * kTile; i += SSFX_AA_GROUP * SSFX_AA_GROUP)
        tileLuma[i] = edgeLuma(fetchValue(origin.x + i % kTile, origin.y + i / kTile));
    barrier();
}
// The luma plane (rgba32f): texel (q, y) holds the lumas of pixels 4q .. 4q + 3 of row y,
// those past the last column holding the last column's (aa_constants.h: SSFX_AA_LUMA_PACK).
// Packed because each load is a gather on lavapipe: the classify dispatch reads a pixel's
// five neighbours from 1.25 loads instead of 5 (edge_list.glsl).
#if SSFX_AA_LUMA_PACK != 4
#error "the luma plane is rgba32f: four lumas per texel"
#endif
layout(set = 0, binding = SSFX_AA_BINDING_LUMA, rgba32f) uniform image2D lumaPlane;
int lumaPlaneWidth() { return (pc.width + SSFX_AA_LUMA_PACK - 1) / SSFX_AA_LUMA_PACK; }
// Texel q of row y of the plane, both clamped to it.
vec4 lumaTexel(int q, int y) {
    return imageLoad(lumaPlane, ivec2(clamp(q, 0, lumaPlaneWidth() - 1), clamp(y, 0, pc.height - 1)));
}
// The luma of texel (x, y), clamped to the image like a fetch: from the luma plane (the
// classify and edge dispatches), from the texel (the segments stage: an edge pixel's own
// neighbourhood, the same value as the plane's) or from the tile (stage 0: the group's
// pixels or their border, whose texels were fetched clamped).
float lumaAt(int x, int y) {
#ifdef SSFX_AA_SEGMENTS_MODULE
    return edgeLuma(fetchValue(x, y));
#else
    if (spec_stage == SSFX_AA_STAGE_EDGES || spec_stage == SSFX_AA_STAGE_CLASSIFY) {
        const int cx = clamp(x, 0, pc.width - 1);
        return lumaTexel(cx / SSFX_AA_LUMA_PACK, y)[cx % SSFX_AA_LUMA_PACK];
    }
    const ivec2 q = ivec2(x, y) - tileOrigin();
    return tileLuma[q.y * kTile + q.x];
#endif
}
#else
float lumaAt(int x, int y) { return edgeLuma(fetchValue(x, y)); }
#endif

#ifdef SSFX_AA_SEGMENTS_MODULE
// The segments' layout (blur.comp, edge_list.glsl): one invocation per SSFX_AA_SEGMENT pixels
// of a row, the work group transposed (local x is the row, local y the segment) so that a
// subgroup's lanes lie on consecutive rows of one column of segments (aa_pass.cpp makes the
// segments only where its probe found a subgroup's lanes to be consecutive invocations of the
// group). A lane takes the rows above and below from its neighbouring lanes where they hold
// them, and fetches one more row itself: the row above for the first lane of a run, else the
// row below, which only the last lane uses (every lane lacks one of them at most: the probe).
struct SegmentLane {
    int xs, y;                   // the segment's first pixel
    bool haveAbove, haveBelow;   // the neighbouring lanes hold rows y - 1 and y + 1 of these segments
    int extraY;                  // the row this lane fetches besides its own
};
SegmentLane segmentLane() {
    SegmentLane s;
    s.xs = int(gl_WorkGroupID.x * SSFX_AA_GROUP + gl_LocalInvocationID.y) * SSFX_AA_SEGMENT;
    s.y = int(gl_WorkGroupID.y * SSFX_AA_GROUP + gl_LocalInvocationID.x);
    const uint lane = gl_SubgroupInvocationID;
    s.haveAbove = lane > 0u && gl_LocalInvocationID.x > 0u;
    s.haveBelow = lane + 1u < gl_SubgroupSize && gl_LocalInvocationID.x + 1u < SSFX_AA_GROUP;
    s.extraY = s.haveAbove ? s.y + 1 : s.y - 1;
    return s;
}
#endif

// The output pixel: the colour quantised exactly (model) or by the device (hardware), alpha
// from `alpha` (an 8-bit value). texture=srgb: encoded back to sRGB levels (the output is a
// unorm image holding the sRGB bytes, as the CPU's output).
void store(ivec2 p, vec3 c, uint alpha) {
    if (spec_srgb != 0) {
        uvec3 b;
        if (spec_sampling != 0) {
            b = srgbLevelsDevice(c);
        } else {
            b = uvec3(encodeSrgbExact(c.r), encodeSrgbExact(c.g), encodeSrgbExact(c.b));
        }
        imageStore(dst, p, vec4(vec3(b), float(alpha)) / 255.0);
        return;
    }
    if (spec_sampling != 0) {
        imageStore(dst, p, vec4(clamp(c, 0.0, 1.0), float(alpha) / 255.0));
        return;
    }
    const uvec3 b = uvec3(toUnorm8(c.r), toUnorm8(c.g), toUnorm8(c.b));
    imageStore(dst, p, vec4(vec3(b), float(alpha)) / 255.0);
}
// A fetched texel stored at p unchanged: its bytes (an sRGB view's recovered, srgb.glsl).
void copyTexel(ivec2 p, vec4 raw) {
    if (spec_srgb != 0) {
        imageStore(dst, p, vec4(vec3(texelBytes(raw)), round(raw.a * 255.0)) / 255.0);
        return;
    }
    imageStore(dst, p, raw);
}
// The input pixel unchanged.
void storeInput(ivec2 p) { copyTexel(p, texelFetch(src, p, 0)); }
uint alphaAt(int x, int y) { return uint(round(texelRaw(x, y).a * 255.0)); }

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
    EXACT float r = lumaMax - lumaMin;
    EXACT float t = lumaMax * pc.edgeThreshold;
    range = r;
    return r < maxf(pc.edgeThresholdMin, t);
}

// The early-exit test of the methods on the 3x3 neighbourhood: true for an edge pixel.
bool edgeAt3x3(Luma3x3 n) {
    float range;
    return !belowEdgeThreshold(n, range);
}

struct EdgeSides {
    bool horizontal;  // the edge runs along x; "across" is y
    float luma1, luma2;
    float g1, g2;  // luma1 - C, luma2 - C
};
EdgeSides edgeSides(Luma3x3 n) {
    EXACT float edgeH =
        abs(-2.0 * n.W + (n.SW + n.NW)) + abs(-2.0 * n.C + (n.S + n.N)) * 2.0 + abs(-2.0 * n.E + (n.SE + n.NE));
    EXACT float edgeV =
        abs(-2.0 * n.N + (n.NE + n.NW)) + abs(-2.0 * n.C + (n.W + n.E)) * 2.0 + abs(-2.0 * n.S + (n.SW + n.SE));
    EdgeSides s;
    s.horizontal = edgeH >= edgeV;
    s.luma1 = s.horizontal ? n.S : n.W;
    s.luma2 = s.horizontal ? n.N : n.E;
    EXACT float g1 = s.luma1 - n.C;
    EXACT float g2 = s.luma2 - n.C;
    s.g1 = g1;
    s.g2 = g2;
    return s;
}

// The invocation's pixel, or false when it lies outside the output.
bool outputPixel(out ivec2 p) {
    p = ivec2(gl_GlobalInvocationID.xy);
    return p.x < pc.outWidth && p.y < pc.outHeight;
}
