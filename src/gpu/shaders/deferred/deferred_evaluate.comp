#version 450
// Adaptive shading, pass 2 (adaptive_ss.md, Evaluate; paper section 3.1): k per pixel from
// the depth variance and the normal cone of its window and the luminance range of S over the
// pixel and its 4 neighbours (clamped at the border), k = max of the three rounded half away
// from zero and clamped to [1, m^2]. The CPU's adaptiveSupersampling, Evaluate step.
//
// The pipeline is made per m (kM): every loop has a constant trip count and every fetch a
// constant offset, so a compiler can unroll the loops and keep depths[] in registers. With
// every sample's id, depth and normal read unconditionally, that took the pass to about 0.9
// of its time on lavapipe, near that machine's noise; either change alone did not
// (docs/gpu.md).
#include "deferred.glsl"

layout(constant_id = 1) const int kM = 4;  // the G-buffer's m (1 .. 4)
const int kN = kM * kM;

const float kBackgroundDepth = 1000.0;  // deferred::kBackgroundDepth

float lumaAt(ivec2 p) { return imageLoad(firstImage, clamp(p, ivec2(0), ivec2(setup.width, setup.height) - 1)).w; }

void main() {
    ivec2 p;
    if (!pixelOf(p)) return;
    // Depth metric: c times the variance of the window's depths (background counts as
    // kBackgroundDepth). The CPU sums in double; here the mean first, then the squared
    // deviations (float error far below the metric's rounding but at ties).
    float depths[kN];
    vec3 mean = vec3(0.0);
    int geometry = 0;
    float sum = 0.0;
    for (int j = 0; j < kM; ++j)
        for (int i = 0; i < kM; ++i) {
            const ivec2 s = kM * p + ivec2(i, j);
            const uint id = texelFetch(gIds, s, 0).x;
            const float d = texelFetch(gDepth, s, 0).r;
            const vec3 normal = texelFetch(gNormal, s, 0).xyz;
            const float z = linearDepthOf(id, d);
            depths[j * kM + i] = isinf(z) ? kBackgroundDepth : z;
            sum += depths[j * kM + i];
            if (!isinf(z)) {
                mean += normal;
                ++geometry;
            }
        }
    const float average = sum / float(kN);
    float variance = 0.0;
    for (int i = 0; i < kN; ++i) variance += (depths[i] - average) * (depths[i] - average);
    const float kd = setup.cDepth * (variance / float(kN));
    // Normal metric over the geometry samples: c sqrt(1 - min |mean . n_ij|); normals that
    // cancel out are a maximal cone.
    float kn = 0.0;
    if (geometry > 0) {
        const float len = length(mean);
        if (!(len > 0.0)) {
            kn = setup.cNormal;
        } else {
            mean /= len;
            float minDot = 1.0;
            for (int j = 0; j < kM; ++j)
                for (int i = 0; i < kM; ++i) {
                    const ivec2 s = kM * p + ivec2(i, j);
                    if (texelFetch(gIds, s, 0).x != kNoMaterial)
                        minDot = min(minDot, abs(dot(mean, texelFetch(gNormal, s, 0).xyz)));
                }
            kn = setup.cNormal * sqrt(max(0.0, 1.0 - minDot));
        }
    }
    // Shading metric: FXAA's early exit on S's lumas (ppaa.md section 1).
    const float c = lumaAt(p), north = lumaAt(p + ivec2(0, -1)), south = lumaAt(p + ivec2(0, 1)),
                west = lumaAt(p + ivec2(-1, 0)), east = lumaAt(p + ivec2(1, 0));
    const float lMax = max(max(max(c, north), max(south, west)), east);
    const float lMin = min(min(min(c, north), min(south, west)), east);
    const float r = lMax - lMin;
    const float ks = r < max(setup.tMin, lMax * setup.tEdge) ? 0.0 : setup.cShading * r;
    imageStore(metrics, p, vec4(kd, kn, ks, 0.0));
    // std::lround: half away from zero (k >= 0 here), exactly: the fraction is exact.
    const float k = min(max(max(kd, kn), ks), 1e6);
    const float whole = floor(k);
    const int rounded = int(whole) + (k - whole >= 0.5 ? 1 : 0);
    imageStore(kImage, p, uvec4(uint(clamp(rounded, 1, kN))));
}
