// G-buffer pass (adaptive_ss.md step 1): per sample the camera-space normal, texture
// coordinates, their derivatives per final-image pixel, material and texture layer.
// Depth comes from the depth attachment. The albedo is not looked up here.
#version 450
#include "common.glsl"

layout(location = 0) out vec4 outNormal;   // R16G16B16A16_SNORM
layout(location = 1) out vec2 outUv;       // R32G32_SFLOAT
layout(location = 2) out vec4 outUvGrad;   // R32G32B32A32_SFLOAT: du/dx, dv/dx, du/dy, dv/dy
layout(location = 3) out uvec2 outIds;     // R16G16_UINT: material, texture layer (0xFFFF = none)

void main() {
    outNormal = vec4(normalize(mat3(frame.view) * facingNormal()), 0.0);
    outUv = uv;
    // dFdx is per G-buffer sample; one final-image pixel is m samples wide.
    outUvGrad = vec4(dFdx(uv), dFdy(uv)) * frame.params.x;
    const int layer = materials[material].layer.x;
    outIds = uvec2(material, layer < 0 ? 0xFFFFu : uint(layer));
}
