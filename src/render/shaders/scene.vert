// Shared vertex stage of every scene pass. The vertex's clip position uses one float
// matrix composed in double on the host (SAO paper section 2.1).
#version 450

layout(push_constant) uniform Push { mat4 viewProjection; } pc;
layout(set = 0, binding = 0) uniform Frame {
    mat4 view;          // world -> camera (for camera-space normals)
    vec4 ambient;       // rgb
    vec4 params;        // x: texture-coordinate derivative scale (m), y: light count
    vec4 eye;           // camera position, world space
} frame;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in uint inMaterial;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 uv;
layout(location = 3) flat out uint material;

void main() {
    gl_Position = pc.viewProjection * vec4(inPosition, 1.0);
    worldPosition = inPosition;
    worldNormal = inNormal;
    uv = inUv;
    material = inMaterial;
}
