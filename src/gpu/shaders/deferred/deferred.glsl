// Shared by the adaptive-shading passes (spec adaptive_ss.md; the CPU's src/deferred/): the
// setup block, the G-buffer bindings and the shading of one sample (SampleShader::shade).
//
// Arithmetic. The shading is the CPU's formula in the device's float arithmetic (its
// division, square root, pow and log2 are the device's), so the image is the CPU's within
// the bound tests/gpu/test_gpu_deferred.cpp states, not its bits. The camera-space depth of
// the depth metric is the CPU's double formula rounded once, in float pairs (exact.glsl), so
// that k rarely differs: only where a metric lies within float error of a rounding boundary
// or FXAA's threshold (the documented ties, docs/gpu.md).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

// 8 x 8 pixels per work group: the tile of the tiled variant (the CPU's kTile).
layout(local_size_x = 8, local_size_y = 8) in;

// What the host fills once per run (deferred_pass.cpp: DeferredSetup; std430, 4-byte scalars).
layout(set = 0, binding = 0, std430) readonly buffer Setup {
    int width, height, m, n;           // final image, m x m samples per pixel, n = m^2
    int sampleW, sampleH, lightCount, maxAnisotropy;
    int stall, textureSize, levelCount, useAo;  // useAo: gAo multiplies the ambient term
    float cDepth, cNormal, cShading, tMin;
    float tEdge, specular, shininess, p00;
    float p11, c0Hi, c0Lo, c1Hi;
    float c1Lo, c2Hi, c2Lo, pad0;
    vec4 ambient, background;
    ivec4 order[16];  // xy: the window position of dither index i
    ivec4 level[16];  // x: first texel (uint) of the level in `texels`, y: its size
} setup;

struct Light { vec4 vector; vec4 color; };  // vector.w: 1 point (position), 0 directional (towards it)
layout(set = 0, binding = 1, std430) readonly buffer Lights { Light lights[]; };
struct Material { vec4 diffuse; ivec4 layer; };
layout(set = 0, binding = 2, std430) readonly buffer Materials { Material materials[]; };
// The texture array's bytes for the CPU's sampler model: level l of layer k at
// setup.level[l].x + k size_l^2, RGBA8 packed in one uint per texel.
layout(set = 0, binding = 3, std430) readonly buffer Texels { uint texels[]; };
// The same texture array for the device's sampler (linear, repeat, anisotropic).
layout(set = 0, binding = 4) uniform sampler2DArray textures;
// The G-buffer (the renderer's formats or the run() upload's; texelFetch'ed).
layout(set = 0, binding = 5) uniform sampler2D gDepth;   // hardware depth d in [0, 1]
layout(set = 0, binding = 6) uniform sampler2D gNormal;  // camera space (xyz)
layout(set = 0, binding = 7) uniform sampler2D gUv;
layout(set = 0, binding = 8) uniform sampler2D gUvGrad;   // du/dx, dv/dx, du/dy, dv/dy per final pixel
layout(set = 0, binding = 9) uniform usampler2D gIds;     // material, texture layer (0xFFFF: none)
// The final pixels' ambient occlusion (GBuffer::ambientOcclusion; a 1x1 stand-in when unused).
layout(set = 0, binding = 19) uniform sampler2D gAo;

// Passes' images and counters.
layout(set = 0, binding = 10, rgba32f) uniform image2D firstImage;  // S: colour, luma in w
layout(set = 0, binding = 11, r32ui) uniform uimage2D kImage;       // samples per pixel
layout(set = 0, binding = 12, rgba32f) uniform image2D metrics;     // k_d, k_n, k_s
layout(set = 0, binding = 13, rgba32f) uniform writeonly image2D outImage;
// [0] samples shaded by the rest pass (= the busy lane-iterations), [1] lane-iterations
// issued (per subgroup: its lanes x its busiest lane's samples), [2] the subgroup size seen,
// [3] the sample list's length (the sample-list schedule).
layout(set = 0, binding = 14, std430) buffer Counters { uint counters[4]; };
// The sample-list schedule (deferred_list.comp): per entry its pixel (y width + x) and its
// colour; per pixel the first entry of its range; the shade stage's indirect group counts.
layout(set = 0, binding = 15, std430) buffer Entries { uint entries[]; };
layout(set = 0, binding = 16, std430) buffer Colours { vec4 colours[]; };
layout(set = 0, binding = 17, std430) buffer Bases { uint bases[]; };
layout(set = 0, binding = 18, std430) buffer Args { uint args[3]; };

layout(constant_id = 0) const int kLookupHardware = 0;  // 1: the device's sampler (textureGrad)

#include "../common/exact.glsl"

const uint kNoMaterial = 0xFFFFu;

// ---- the CPU's sampler model (src/deferred/sampler.cpp) ---------------------------------

vec4 texel(int layer, int lvl, int x, int y) {
    const int size = setup.level[lvl].y;
    const uint word = texels[uint(setup.level[lvl].x) + uint((layer * size + y) * size + x)];
    return vec4(uvec4(word, word >> 8, word >> 16, word >> 24) & 255u) * (1.0 / 255.0);
}
vec4 textureBilinearModel(int layer, int lvl, vec2 uv) {
    const int size = setup.level[lvl].y;
    const float x = uv.x * float(size) - 0.5, y = uv.y * float(size) - 0.5;
    const float fx = floor(x), fy = floor(y);
    const float ax = x - fx, ay = y - fy;
    // Repeat addressing: size is a power of two, so the mask wraps negative indices too.
    const int x0 = int(fx) & (size - 1), y0 = int(fy) & (size - 1);
    const int x1 = (x0 + 1) & (size - 1), y1 = (y0 + 1) & (size - 1);
    const vec4 top = texel(layer, lvl, x0, y0) * (1.0 - ax) + texel(layer, lvl, x1, y0) * ax;
    const vec4 bottom = texel(layer, lvl, x0, y1) * (1.0 - ax) + texel(layer, lvl, x1, y1) * ax;
    return top * (1.0 - ay) + bottom * ay;
}
vec4 textureLodModel(int layer, vec2 uv, float lod) {
    const float maxLevel = float(setup.levelCount - 1);
    lod = clamp(isinf(lod) || isnan(lod) ? maxLevel : lod, 0.0, maxLevel);
    const int l0 = int(floor(lod));
    const float f = lod - float(l0);
    const vec4 a = textureBilinearModel(layer, l0, uv);
    if (f == 0.0) return a;
    return a * (1.0 - f) + textureBilinearModel(layer, l0 + 1, uv) * f;
}
// EXT_texture_filter_anisotropic's formulation, as the CPU's textureGrad.
vec4 textureGradModel(int layer, vec2 uv, vec2 dx, vec2 dy) {
    const float size = float(setup.textureSize);
    const float px = length(dx) * size, py = length(dy) * size;
    const float pMax = max(px, py), pMin = min(px, py);
    if (!(pMax > 0.0)) return textureLodModel(layer, uv, 0.0);
    const int count = clamp(int(ceil(pMax / max(pMin, 1e-20))), 1, setup.maxAnisotropy);
    const float lod = log2(pMax / float(count));
    if (count == 1) return textureLodModel(layer, uv, lod);
    const vec2 major = px >= py ? dx : dy;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < count; ++i)
        sum += textureLodModel(layer, uv + major * ((float(i) + 0.5) / float(count) - 0.5), lod);
    return sum / float(count);
}

// ---- one sample -------------------------------------------------------------------------

// The CPU's SampleShader::linearDepth's -z: -c0 / (d c1 + c2) from the host's doubles, in
// float pairs and rounded once. +infinity for background. linearDepthOf: from the sample's
// material id and hardware depth d, already read.
float linearDepthOf(uint id, float d) {
    if (id == kNoMaterial) return 1.0 / 0.0;
    const vec2 den = pairAdd(pairMul(vec2(d, 0.0), vec2(setup.c1Hi, setup.c1Lo)), vec2(setup.c2Hi, setup.c2Lo));
    return -pairDivToFloat(vec2(setup.c0Hi, setup.c0Lo), den);
}
float linearDepth(ivec2 s) { return linearDepthOf(texelFetch(gIds, s, 0).x, texelFetch(gDepth, s, 0).r); }

// An artificial cost per sample (ShadingParams::stall): xorshift steps the compiler must
// keep; a state of 0, which xorshift never reaches from an odd seed, would change the colour.
// Sixteen steps a loop iteration: lavapipe ends an invocation's loops after 65535 iterations
// in all (vkx::Context::maxShaderLoopIterations; deferred_pass.cpp checks a run fits).
uint xorshift(uint s) {
    s ^= s << 13;
    s ^= s >> 17;
    return s ^ (s << 5);
}
uint xorshift4(uint s) { return xorshift(xorshift(xorshift(xorshift(s)))); }
vec3 stallFor(uint index, vec3 colour) {
    uint s = index | 1u;
    for (int k = 0; k < setup.stall / 16; ++k) s = xorshift4(xorshift4(xorshift4(xorshift4(s))));
    for (int k = 0; k < setup.stall % 16; ++k) s = xorshift(s);
    return s == 0u ? colour + 1.0 : colour;
}

// The colour of sample s for a footprint (the fraction of a final pixel's width the sample
// stands for); SampleShader::shade step for step.
vec3 shadeSample(ivec2 s, float footprint) {
    const uvec2 ids = texelFetch(gIds, s, 0).xy;
    vec3 colour;
    if (ids.x == kNoMaterial) {
        colour = setup.background.rgb;
    } else {
        vec3 albedo = materials[ids.x].diffuse.rgb;
        if (ids.y != kNoMaterial) {
            const int layer = int(ids.y);
            // A material or layer change in the sample's 2x2 quad: the derivatives are meaningless.
            const ivec2 q = s & ~1;
            bool boundary = false;
            for (int y = q.y; y < min(q.y + 2, setup.sampleH); ++y)
                for (int x = q.x; x < min(q.x + 2, setup.sampleW); ++x)
                    boundary = boundary || texelFetch(gIds, ivec2(x, y), 0).xy != ids;
            const vec2 uv = texelFetch(gUv, s, 0).xy;
            const vec4 grad = texelFetch(gUvGrad, s, 0) * footprint;
            vec4 tex;
            if (kLookupHardware != 0)
                tex = boundary ? textureLod(textures, vec3(uv, float(layer)), 0.0)
                               : textureGrad(textures, vec3(uv, float(layer)), grad.xy, grad.zw);
            else
                tex = boundary ? textureBilinearModel(layer, 0, uv) : textureGradModel(layer, uv, grad.xy, grad.zw);
            albedo *= tex.rgb;
        }
        const float z = -linearDepth(s);
        // ao::reconstructPosition at the sample's centre.
        const vec2 p = vec2(s) + 0.5;
        const vec3 pos = vec3(z / setup.p00 * (1.0 - 2.0 * p.x / float(setup.sampleW)),
                              z / setup.p11 * (2.0 * p.y / float(setup.sampleH) - 1.0), z);
        const vec3 n = normalize(texelFetch(gNormal, s, 0).xyz);
        const vec3 toEye = normalize(-pos);
        vec3 diffuse = setup.ambient.rgb, specular = vec3(0.0);
        if (setup.useAo != 0) diffuse *= texelFetch(gAo, s / setup.m, 0).r;
        for (int i = 0; i < setup.lightCount; ++i) {
            vec3 dir = lights[i].vector.xyz, irradiance = lights[i].color.rgb;
            if (lights[i].vector.w != 0.0) {
                const vec3 d = lights[i].vector.xyz - pos;
                const float d2 = max(dot(d, d), 1e-4);
                dir = d / sqrt(d2);
                irradiance /= d2;
            }
            const float nl = dot(n, dir);
            if (nl <= 0.0) continue;
            diffuse += irradiance * nl;
            // Blinn-Phong times n.l, fading with the diffuse term at the terminator.
            const float nh = max(dot(n, normalize(dir + toEye)), 0.0);
            specular += irradiance * (setup.specular * pow(nh, setup.shininess) * nl);
        }
        colour = albedo * diffuse + specular;
    }
    if (setup.stall > 0) colour = stallFor(uint(s.y * setup.sampleW + s.x), colour);
    return colour;
}

// The window sample of pixel p with dither index i.
ivec2 windowSample(ivec2 p, int i) { return setup.m * p + setup.order[i].xy; }

// The PPAA luma of a colour clamped to [0, 1] (core/color.hpp).
float lumaOf(vec3 c) {
    const vec3 v = clamp(c, 0.0, 1.0);
    return sqrt(0.299 * v.r + 0.587 * v.g + 0.114 * v.b);
}

// This invocation's pixel; false outside the image.
// Whether the rest of pixel p (k samples) shades its first sample again: where k > 1 and it
// is textured (its albedo depends on the footprint, so that k = m^2 equals brute force).
bool reshadesFirst(ivec2 p, int k) { return k > 1 && texelFetch(gIds, windowSample(p, 0), 0).y != kNoMaterial; }

bool pixelOf(out ivec2 p) {
    p = ivec2(gl_GlobalInvocationID.xy);
    return p.x < setup.width && p.y < setup.height;
}
