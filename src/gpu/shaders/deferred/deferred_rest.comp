#version 450
// Adaptive shading, pass 3 (adaptive_ss.md, ShadeRestAdaptively), and brute force: per pixel
// the samples in dither order, each standing for 1/sqrt(k) of the pixel (1/m for brute
// force), averaged with the first (re-shaded when textured: its albedo depends on the
// footprint, so k = m^2 equals brute force). The CPU's shadePixel and bruteForceSupersampling.
//
// Variants (specialization constant kVariant):
//  0 per pixel: invocation i of the 8 x 8 group shades pixel i of its tile;
//  1 tiled (the paper's future work): the tile's pixels ranked by k (then by position, a
//    stable counting sort as the CPU's), invocation i shades the pixel of rank i, so that a
//    subgroup's lanes hold pixels of similar k and idle less;
//  2 brute force: every sample of every pixel.
// Counters: the samples shaded, and per subgroup its lanes times its busiest lane's samples
// against the samples its lanes shaded (the idle-lane share, counted in the shader).
#include "deferred.glsl"

layout(constant_id = 1) const int kVariant = 0;

shared uint tileK[64];

// Shades pixel p (in the image) and returns the samples it shaded beyond S.
uint shadePixel(ivec2 p) {
    if (kVariant == 2) {
        const float footprint = 1.0 / float(setup.m);
        vec3 sum = vec3(0.0);
        for (int s = 0; s < setup.n; ++s) sum += shadeSample(windowSample(p, s), footprint);
        imageStore(outImage, p, vec4(sum / float(setup.n), 1.0));
        return uint(setup.n);
    }
    const int k = int(imageLoad(kImage, p).x);
    // One loop for the re-shaded first sample and the others (not a branch before a loop):
    // lanes that start at 0 and lanes that start at 1 run the same iterations together, and
    // a pixel with k = 1 runs none (its image is S). 0 + x and x / 1 are exact: the CPU's sums.
    const bool reshade = reshadesFirst(p, k);
    const float footprint = 1.0 / sqrt(float(k));
    vec3 sum = reshade ? vec3(0.0) : imageLoad(firstImage, p).rgb;
    for (int s = reshade ? 0 : 1; s < k; ++s) sum += shadeSample(windowSample(p, s), footprint);
    imageStore(outImage, p, vec4(sum / float(k), 1.0));
    return uint(k - 1) + (reshade ? 1u : 0u);
}

void main() {
    const ivec2 tile = ivec2(gl_WorkGroupID.xy) * 8;
    const int local = int(gl_LocalInvocationIndex);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    bool inside = p.x < setup.width && p.y < setup.height;
    if (kVariant == 1) {
        // Rank the tile's pixels by (k, index); pixels outside the image rank last.
        tileK[local] = inside ? imageLoad(kImage, p).x : 0xFFFFu;
        barrier();
        const uint mine = tileK[local];
        int rank = 0;
        for (int j = 0; j < 64; ++j) {
            const uint other = tileK[j];
            rank += other < mine || (other == mine && j < local) ? 1 : 0;
        }
        // Rank r shades the r-th pixel: find it (the inverse permutation) through shared memory.
        barrier();
        tileK[rank] = uint(local);
        barrier();
        const int pick = int(tileK[local]);
        p = tile + ivec2(pick % 8, pick / 8);
        inside = p.x < setup.width && p.y < setup.height;
    }
    uint work = 0u;
    if (inside) work = shadePixel(p);
    // Every lane takes part, those outside the image too (they idle).
    const uint busy = subgroupAdd(work), widest = subgroupMax(work);
    if (subgroupElect()) {
        atomicAdd(counters[0], busy);
        atomicAdd(counters[1], widest * gl_SubgroupSize);
        atomicMax(counters[2], gl_SubgroupSize);
    }
}
