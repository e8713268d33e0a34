// Shared by the ambient-obscurance passes (SAO and AlchemyAO; spec sao.md): the push
// constants, the work-group layout and the arithmetic that must match the CPU's.
//
// Exactness. As in the anti-aliasing passes (aa/ppaa.glsl): every float computation is
// `precise` (no fused multiply-add, the written order, as the CPU's build: contraction off),
// and division and square root are correctly rounded (common/exact.glsl). So depth -> z's
// float arithmetic, the pyramid, the 2x2 quad pass, the packing and the bilateral passes
// give the CPU's float bits from the same inputs. What stays the device's own is the sample
// pass's sine and cosine (and pow for an intensity exponent other than 1), which Vulkan
// leaves to the implementation: their parity with the CPU is a stated bound
// (tests/gpu/test_gpu_ao.cpp).
#extension GL_GOOGLE_include_directive : require
#include "ao_constants.h"

layout(local_size_x = SSFX_AO_GROUP, local_size_y = SSFX_AO_GROUP) in;
layout(push_constant, std430) uniform Push { AoConstants pc; };

// The tables buffer, in the shaders that define SSFX_AO_TABLES_BINDING before including.
#ifdef SSFX_AO_TABLES_BINDING
layout(set = 0, binding = SSFX_AO_TABLES_BINDING, std430) readonly buffer Tables { SSFX_AO_TABLES_BLOCK } tables;
#endif

#include "../common/exact.glsl"

// The invocation's pixel of the dispatch region, relative to the region; false beyond it.
bool regionPixel(out ivec2 p) {
    p = ivec2(gl_GlobalInvocationID.xy);
    return p.x < pc.regionW && p.y < pc.regionH;
}

// ssfx::ao::packAo: A in 8 bits, round(clamp(A, 0, 1) 255) / 255 (nearbyint: ties to even).
float packAo(float a) {
    precise float scaled = clamp(a, 0.0, 1.0) * 255.0;
    return crDiv(roundEven(scaled), 255.0);
}
