// The three dispatches of the methods with an edge test (aa_constants.h: SSFX_AA_STAGE_*),
// shared. Included last by a method's shader (with SSFX_TILE defined), which defines
//   bool edgeAt(int x, int y): the early-exit test says edge (spec ppaa.md section 1), and
//   vec3 edgeColour(int x, int y): the method's colour for an edge pixel.
// LUMA writes the luma plane (each texel's edgeLuma once, ppaa.glsl's lumaAt reads it);
// CLASSIFY (16 x 16 groups) writes every pixel below the edge threshold unchanged and lists
// the edge pixels; EDGES (an indirect dispatch of 64 x 1 groups) computes the listed pixels.
// Why: a driver that runs shaders as masked SIMD code (lavapipe) runs the whole edge
// computation, search loops included, for every group of lanes that holds one edge pixel,
// and about 40 % of 8-pixel runs hold one; from the list every lane is an edge pixel. The
// list's order depends on the atomics, the output does not: each pixel is computed on its
// own. Stage 0 is the same method in one pass, its lumas in the work group's tile, for images
// with more pixels than a storage buffer's list can hold (the device's maxStorageBufferRange).
layout(set = 0, binding = SSFX_AA_BINDING_EDGES, std430) buffer EdgeList {
    uint groupsX, groupsY, groupsZ;  // the edge pass's VkDispatchIndirectCommand
    uint count;                      // edge pixels listed
    uint pixels[];                   // x | y << 16
} edges;

void appendEdge(ivec2 p) {
    const uint slot = atomicAdd(edges.count, 1u);
    edges.pixels[slot] = uint(p.x) | (uint(p.y) << 16u);
    // groupsX = min(ceil(count / SSFX_AA_EDGE_GROUP), spec_edgeGroups) as the list grows.
    const uint group = uint(SSFX_AA_EDGE_GROUP);
    if (slot % group == 0u && slot / group < uint(spec_edgeGroups)) atomicAdd(edges.groupsX, 1u);
}

void main() {
    if (spec_stage == SSFX_AA_STAGE_EDGES) {
        const uint stride = edges.groupsX * uint(SSFX_AA_EDGE_GROUP);
        for (uint i = gl_GlobalInvocationID.x; i < edges.count; i += stride) {
            const uint e = edges.pixels[i];
            const ivec2 p = ivec2(e & 0xffffu, e >> 16u);
            store(p, edgeColour(p.x, p.y), alphaAt(p.x, p.y));
        }
        return;
    }
    if (spec_stage == SSFX_AA_STAGE_LUMA) {
        ivec2 p;
        if (outputPixel(p)) imageStore(lumaPlane, p, vec4(edgeLuma(fetchValue(p.x, p.y))));
        return;
    }
    if (spec_stage == 0) loadTile();
    ivec2 p;
    if (!outputPixel(p)) return;
    if (spec_stage == SSFX_AA_STAGE_CLASSIFY) {
        if (edgeAt(p.x, p.y))
            appendEdge(p);
        else
            storeInput(p);  // the texel as fetched, as noaa stores it
        return;
    }
    // Stage 0: one pass, for an image whose list would not fit in a storage buffer.
    store(p, edgeAt(p.x, p.y) ? edgeColour(p.x, p.y) : texelValue(p.x, p.y), alphaAt(p.x, p.y));
}
