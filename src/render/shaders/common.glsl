// Declarations shared by the fragment stages.
layout(set = 0, binding = 0) uniform Frame {
    mat4 view;
    vec4 ambient;
    vec4 params;  // x: derivative scale, y: light count
    vec4 eye;     // camera position, world space
} frame;

struct MaterialData { vec4 diffuse; ivec4 layer; };
layout(std430, set = 0, binding = 1) readonly buffer Materials { MaterialData materials[]; };
struct LightData { vec4 vector; vec4 color; };  // vector.w: 0 directional (direction of travel), 1 point (position)
layout(std430, set = 0, binding = 2) readonly buffer Lights { LightData lights[]; };
layout(set = 0, binding = 3) uniform sampler2DArray textures;

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;
layout(location = 3) flat in uint material;

// Surfaces are two-sided: the vertex normal is turned to the side of the triangle that the
// camera sees. That side comes from the geometric normal (screen-space derivatives of the
// position), not from the winding, which imported models do not keep consistent.
vec3 facingNormal() {
    vec3 n = normalize(worldNormal);
    vec3 ng = cross(dFdx(worldPosition), dFdy(worldPosition));
    if (dot(ng, frame.eye.xyz - worldPosition) < 0.0) ng = -ng;
    return dot(n, ng) < 0.0 ? -n : n;
}
