#version 450
// The exact float helpers (src/gpu/shaders/common/exact.glsl) on the device, for
// GpuShaders.ExactHelpersMatchIeee: per input pair (a, b), the device's own a / b and
// sqrt(a), crDiv(a, b), crSqrt(a), toUnorm8(a), the corrections from deliberately wrong
// starting values (the corrected a / b 2 ulp up and 2 ulp down, the corrected sqrt(a) 1 ulp
// (even pairs) or 7 ulp (odd pairs) up and down: counted from the correct result, not from
// the device's, which may itself be off), which exercise the corrections on a device whose
// own results are already exact, and a * b (for b = 1: whether the device flushes a
// subnormal a to zero, which Vulkan allows without the float-controls execution modes); and
// levelOver4080(k) for k = 0..4080 (invocation k).
#extension GL_GOOGLE_include_directive : require
#include "../../../src/gpu/shaders/common/exact.glsl"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) readonly buffer In { vec2 pairs[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Out { uint results[]; };  // 10 per pair
layout(set = 0, binding = 2, std430) writeonly buffer Levels { uint levels[4081]; };
layout(push_constant) uniform Push { uint count; };

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i <= 4080u) levels[i] = floatBitsToUint(levelOver4080(i));
    if (i >= count) return;
    const float a = pairs[i].x, b = pairs[i].y;
    precise float q = a / b;
    precise float s = sqrt(a);
    const uint o = 10 * i;
    const float cq = crDiv(a, b), cs = crSqrt(a);
    results[o] = floatBitsToUint(q);
    results[o + 1] = floatBitsToUint(s);
    results[o + 2] = floatBitsToUint(cq);
    results[o + 3] = floatBitsToUint(cs);
    results[o + 4] = toUnorm8(a);
    precise float product = a * b;
    results[o + 9] = floatBitsToUint(product);
    q = cq;
    s = cs;
    const bool finite = !isinf(q) && !isnan(q) && q != 0.0 && s > 0.0 && !isinf(s);
    const float qUp = finite ? nextFloat(nextFloat(q, 1.0), 1.0) : q;
    const float qDown = finite ? nextFloat(nextFloat(q, -1.0), -1.0) : q;
    const uint ulps = (i & 1u) != 0u ? 7u : 1u;
    const float sUp = finite ? uintBitsToFloat(floatBitsToUint(s) + ulps) : s;
    const float sDown = finite ? uintBitsToFloat(floatBitsToUint(s) - ulps) : s;
    results[o + 5] = floatBitsToUint(crDivFrom(a, b, qUp));
    results[o + 6] = floatBitsToUint(crDivFrom(a, b, qDown));
    results[o + 7] = floatBitsToUint(crSqrtFrom(a, sUp));
    results[o + 8] = floatBitsToUint(crSqrtFrom(a, sDown));
}
