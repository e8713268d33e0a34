#version 450
// The frame's encode pass (docs/frame.md): the shading's linear RGB (R32G32B32A32_SFLOAT) to
// the 8-bit image the anti-aliasing reads, as deferred::toRgba8 does on the CPU:
// byte = floor(clamp(c, 0, 1) * 255 + 0.5), alpha 255. `precise` keeps the multiply and the
// add two roundings (no fused multiply-add), as in the CPU's float code.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform readonly image2D src;
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D dst;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(dst)))) return;
    precise vec3 scaled = clamp(imageLoad(src, p).rgb, 0.0, 1.0) * 255.0;
    precise vec3 rounded = scaled + 0.5;
    // A byte b stored as b / 255 converts back to b exactly (the AA passes store so too).
    imageStore(dst, p, vec4(floor(rounded), 255.0) / 255.0);
}
