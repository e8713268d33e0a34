#version 450
// The device's unorm decode of every 8-bit value, for gpu::AaPass's probe (aa_pass.cpp:
// unormDecodeIsExact): texel i of a 256 x 1 image, fetched as the passes fetch (a texel
// fetch through a combined image sampler), its R, G and B written as floats.
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D src;
layout(set = 0, binding = 1, std430) writeonly buffer Out {
    float decoded[];  // 3 per texel
};

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    if (i >= 256) return;
    const vec4 t = texelFetch(src, ivec2(i, 0), 0);
    decoded[3 * i] = t.r;
    decoded[3 * i + 1] = t.g;
    decoded[3 * i + 2] = t.b;
}
