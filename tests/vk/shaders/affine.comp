#version 450
// The vk module's test shader: out[i] = a * in[i] + i for i < count, one invocation per item.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Input { float values[]; } src;
layout(std430, binding = 1) writeonly buffer Output { float values[]; } dst;
layout(push_constant) uniform Push { float a; uint count; } push;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;  // the last group covers past the end
    dst.values[i] = push.a * src.values[i] + float(i);
}
