#version 450
// How a device lays out subgroups in a 16 x 16 work group, for gpu::AaPass's probe
// (aa_pass.cpp: subgroupsAreConsecutive): each invocation writes its subgroup invocation id
// and the subgroup size at its local invocation index. blur's segments (blur.comp) take the
// rows above and below from the neighbouring lanes where lanes are consecutive invocations.
#extension GL_KHR_shader_subgroup_basic : require

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0, std430) writeonly buffer Out {
    uint lanes[];  // 2 per invocation: gl_SubgroupInvocationID, gl_SubgroupSize
};

void main() {
    const uint i = gl_LocalInvocationIndex;
    lanes[2u * i] = gl_SubgroupInvocationID;
    lanes[2u * i + 1u] = gl_SubgroupSize;
}
