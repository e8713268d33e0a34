// Forward shading for the anti-aliasing evaluation: diffuse (texture x colour) times
// (ambient + Lambert over all lights). No anti-aliasing; linear values written as is.
#version 450
#include "common.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    const MaterialData m = materials[material];
    vec3 albedo = m.diffuse.rgb;
    if (m.layer.x >= 0) albedo *= texture(textures, vec3(uv, float(m.layer.x))).rgb;
    const vec3 n = facingNormal();
    vec3 light = frame.ambient.rgb;
    const int count = int(frame.params.y);
    for (int i = 0; i < count; ++i) {
        const LightData l = lights[i];
        if (l.vector.w == 0.0) {
            light += l.color.rgb * max(dot(n, -l.vector.xyz), 0.0);
        } else {
            const vec3 d = l.vector.xyz - worldPosition;
            const float d2 = max(dot(d, d), 1e-4);
            light += l.color.rgb * max(dot(n, d * inversesqrt(d2)), 0.0) / d2;
        }
    }
    outColor = vec4(clamp(albedo * light, 0.0, 1.0), 1.0);
}
