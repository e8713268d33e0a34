#version 450
// The device's decode of every 8-bit value, for gpu::AaPass's probes (aa_pass.cpp:
// unormDecodeIsExact, srgbBytesRecovered): texel i of a 256 x 1 image, fetched as the passes
// fetch (a texel fetch through a combined image sampler), its R, G and B written as floats,
// then the 8-bit sRGB levels the passes recover from them (srgb.glsl), as floats.
#extension GL_GOOGLE_include_directive : require
#include "srgb.glsl"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D src;
layout(set = 0, binding = 1, std430) writeonly buffer Out {
    float decoded[];  // 3 per texel, then 3 recovered levels per texel
};

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    if (i >= 256) return;
    const vec4 t = texelFetch(src, ivec2(i, 0), 0);
    const uvec3 level = srgbLevelsDevice(t.rgb);
    for (int k = 0; k < 3; ++k) {
        decoded[3 * i + k] = t[k];
        decoded[768 + 3 * i + k] = float(level[k]);
    }
}
