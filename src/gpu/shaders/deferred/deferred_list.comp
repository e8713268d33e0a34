#version 450
// Adaptive shading, pass 3 as a sample list (a GPU schedule of ours, beside the paper's
// per-pixel loop and its tiled future work): the rest pass's samples shaded one per
// invocation, so that no lane waits for the loop of a pixel with a larger k.
//  stage 0 enqueue (per pixel): reserves the pixel's samples beyond S (the first one again
//          where reshadesFirst, then dither indices 1 .. k-1) as one range of the list;
//  stage 1 args (one invocation): the shade stage's group counts for the indirect dispatch;
//  stage 2 shade (per entry): one sample with footprint 1/sqrt(k), into the entry's colour;
//  stage 3 resolve (per pixel): S or nothing, plus the range's colours in dither order, over
//          k: the rest pass's sum step for step, so the image is the per-pixel one bit for bit.
// The list's order follows the atomics (it varies from run to run); every entry's colour and
// every pixel's sum do not.
#extension GL_KHR_shader_subgroup_ballot : require
#include "deferred.glsl"

layout(constant_id = 1) const int kStage = 0;
const uint kGroupSize = 64u;        // 8 x 8 invocations, flattened in the shade stage
const uint kMaxGroupsX = 65535u;    // Vulkan's guaranteed maxComputeWorkGroupCount[0]

uint samplesBeyondFirst(ivec2 p, out int k, out bool reshade) {
    k = int(imageLoad(kImage, p).x);
    reshade = reshadesFirst(p, k);
    return uint(k - 1) + (reshade ? 1u : 0u);
}

void enqueue() {
    ivec2 p;
    const bool inside = pixelOf(p);
    int k = 1;
    bool reshade = false;
    const uint count = inside ? samplesBeyondFirst(p, k, reshade) : 0u;
    // One atomic per subgroup; its lanes' ranges follow each other.
    const uint offset = subgroupExclusiveAdd(count), total = subgroupAdd(count);
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(counters[3], total);
    base = subgroupBroadcastFirst(base) + offset;
    if (!inside) return;
    const uint pixel = uint(p.y * setup.width + p.x);
    bases[pixel] = base;
    for (uint j = 0u; j < count; ++j) entries[base + j] = pixel;
}

void groupCounts() {
    if (gl_LocalInvocationIndex != 0u) return;
    const uint groups = (counters[3] + kGroupSize - 1u) / kGroupSize;
    args[0] = min(groups, kMaxGroupsX);
    args[1] = (groups + kMaxGroupsX - 1u) / kMaxGroupsX;
    args[2] = 1u;
}

void shade() {
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    const uint i = group * kGroupSize + gl_LocalInvocationIndex;
    const bool valid = i < counters[3];
    if (valid) {
        const uint pixel = entries[i];
        const ivec2 p = ivec2(int(pixel % uint(setup.width)), int(pixel / uint(setup.width)));
        int k;
        bool reshade;
        samplesBeyondFirst(p, k, reshade);
        const int s = (reshade ? 0 : 1) + int(i - bases[pixel]);
        colours[i] = vec4(shadeSample(windowSample(p, s), 1.0 / sqrt(float(k))), 0.0);
    }
    // The lanes as the rest pass counts them: every lane of a subgroup with work is issued.
    const uint work = valid ? 1u : 0u;
    const uint busy = subgroupAdd(work), widest = subgroupMax(work);
    if (subgroupElect()) {
        atomicAdd(counters[0], busy);
        atomicAdd(counters[1], widest * gl_SubgroupSize);
        atomicMax(counters[2], gl_SubgroupSize);
    }
}

void resolve() {
    ivec2 p;
    if (!pixelOf(p)) return;
    int k;
    bool reshade;
    const uint count = samplesBeyondFirst(p, k, reshade);
    const uint base = bases[uint(p.y * setup.width + p.x)];
    vec3 sum = reshade ? vec3(0.0) : imageLoad(firstImage, p).rgb;
    for (uint j = 0u; j < count; ++j) sum += colours[base + j].rgb;
    imageStore(outImage, p, vec4(sum / float(k), 1.0));
}

void main() {
    if (kStage == 0) enqueue();
    else if (kStage == 1) groupCounts();
    else if (kStage == 2) shade();
    else resolve();
}
