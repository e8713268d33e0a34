// The three dispatches of the methods with an edge test (aa_constants.h: SSFX_AA_STAGE_*),
// shared. Included last by a method's shader (with SSFX_TILE defined), which defines
//   bool edgeAt(int x, int y, Luma3x3 n): the early-exit test says edge (spec ppaa.md
//     section 1), n the pixel's 3x3 lumas, and
//   vec3 edgeColour(int x, int y, Luma3x3 n): the method's colour for an edge pixel, n its
//     3x3 lumas.
// LUMA writes the luma plane (each texel's edgeLuma once, four per plane texel: ppaa.glsl's
// lumaAt reads it) and copies every pixel to the output unchanged; CLASSIFY lists the edge
// pixels; EDGES (an indirect dispatch of 64 x 1 groups, each over a run of the list) computes
// the listed pixels over their copies. LUMA and CLASSIFY run one invocation per plane texel
// (four pixels of a row) in 16 x 16 groups: a CPU driver pays per invocation, and CLASSIFY
// reads the 3x3 lumas of four pixels from 5 to 9 plane loads, not 20 to 36 (lavapipe at
// 1920x1080: the two dispatches took 80 ms with one pixel per invocation and an r32f plane,
// 37 ms like this).
// Why a list: a driver that runs shaders as masked SIMD code (lavapipe) runs the whole edge
// computation, search loops included, for every group of lanes that holds one edge pixel,
// and about 40 % of 8-pixel runs hold one; from the list every lane is an edge pixel. The
// list's order depends on the atomics, the output does not: each pixel is computed on its
// own. Stage 0 is the same method in one pass, its lumas in the work group's tile, for images
// with more pixels than a storage buffer's list can hold (the device's maxStorageBufferRange).
// The segments stage is the method in one dispatch without a list or a plane, for CPU
// devices (below; modules of their own).
layout(set = 0, binding = SSFX_AA_BINDING_EDGES, std430) buffer EdgeList {
    uint groupsX, groupsY, groupsZ;  // the edge pass's VkDispatchIndirectCommand
    uint count;                      // edge pixels listed
    uint pixels[];                   // x | y << 16
}
edges;

// Stage 0's list of the work group's edge pixels (x | y << 16) and their count.
shared uint groupEdges[SSFX_AA_GROUP * SSFX_AA_GROUP];
shared uint groupEdgeCount;

// Appends the edge pixels among `n` candidates (`edge[i]`: pixel (x0 + i, y)) with one
// atomic: their slots are consecutive. groupsX = min(ceil(count / SSFX_AA_EDGE_GROUP), most)
// as the list grows, most = spec_edgeGroups or more where the device's loop budget needs
// more (pc.edgeGroupsMin), at most SSFX_AA_EDGE_MAX_GROUPS.
void appendEdges(int x0, int y, bool edge[SSFX_AA_LUMA_PACK]) {
    uint n = 0u;
    for (int i = 0; i < SSFX_AA_LUMA_PACK; ++i) n += edge[i] ? 1u : 0u;
    if (n == 0u) return;
    uint slot = atomicAdd(edges.count, n);
    const uint group = uint(SSFX_AA_EDGE_GROUP);
    const uint most = min(max(uint(spec_edgeGroups), uint(pc.edgeGroupsMin)), uint(SSFX_AA_EDGE_MAX_GROUPS));
    const uint before = min((slot + group - 1u) / group, most), after = min((slot + n + group - 1u) / group, most);
    if (after > before) atomicAdd(edges.groupsX, after - before);
    for (int i = 0; i < SSFX_AA_LUMA_PACK; ++i)
        if (edge[i]) edges.pixels[slot++] = uint(x0 + i) | (uint(y) << 16u);
}

// The luma plane's texel and its neighbours' lumas in one row: `l[0]` the pixel left of the
// texel, `l[1..4]` its four, `l[5]` the pixel right of it, clamped to the image (the plane's
// padding past the last column already holds the last column's luma).
struct LumaRow {
    float l[SSFX_AA_LUMA_PACK + 2];
};
LumaRow lumaRow(int q, int y) {
    const vec4 mid = lumaTexel(q, y);
    const float left = q > 0 ? lumaTexel(q - 1, y).w : mid.x;
    const float right = (q + 1) * SSFX_AA_LUMA_PACK < pc.width ? lumaTexel(q + 1, y).x : mid.w;
    return LumaRow(float[SSFX_AA_LUMA_PACK + 2](left, mid.x, mid.y, mid.z, mid.w, right));
}

#ifdef SSFX_AA_SEGMENTS_MODULE
// The segments stage (gpu::EdgePath::Segments; the modules compiled with
// SSFX_AA_SEGMENTS_MODULE): one invocation per SSFX_AA_SEGMENT pixels of a row, the method
// whole in one dispatch. Each invocation fetches the three rows around its
// pixels once (3 (S + 2) fetches for S pixels, where a pixel of the list path costs a plane
// store, a classify and 9 plane loads), tests its pixels, copies the unchanged ones, and the
// subgroup then computes its edge pixels spread over its lanes: in round j lane l takes the
// subgroup's edge pixel j * size + l, in the lanes' order (an exclusive prefix sum of their
// counts says whose it is). On a driver that runs shaders as masked SIMD code (lavapipe) the
// edge computation then runs ceil(edges / lanes) times per subgroup, about as often as the
// list's, without the luma plane, the classify dispatch or the list's scattered visits. Each
// pixel is computed on its own, so the bytes are the other paths'. Every invocation, inside
// the image or not, reaches the subgroup operations.
void segments() {
    // Lumas of columns xs - 1 .. xs + S of rows y - 1 (above), y and y + 1 (below), fetched
    // clamped as the plane's; the row's own texels kept for the copies. Each lane computes its
    // own row's and one more, and takes the rows above and below from its neighbouring lanes
    // (ppaa.glsl's segmentLane): 2 (S + 2) lumas for S pixels (2.5 a pixel, where each lane
    // computing its three rows took 3.75).
    const SegmentLane s = segmentLane();
    const int xs = s.xs, y = s.y;
    const bool inside = xs < pc.width && y < pc.height;
    const uint lane = gl_SubgroupInvocationID;
    float above[SSFX_AA_SEGMENT + 2], row[SSFX_AA_SEGMENT + 2], below[SSFX_AA_SEGMENT + 2];
    vec4 raw[SSFX_AA_SEGMENT];
    for (int i = 0; i < SSFX_AA_SEGMENT + 2; ++i) {
        const int x = xs - 1 + i;
        const vec4 r = texelRaw(x, y);
        if (i >= 1 && i <= SSFX_AA_SEGMENT) raw[i - 1] = r;
        row[i] = edgeLuma(texelDecoded(r));
        const float extra = edgeLuma(fetchValue(x, s.extraY));
        const float up = subgroupShuffle(row[i], lane - 1u), down = subgroupShuffle(row[i], lane + 1u);
        above[i] = s.haveAbove ? up : extra;
        below[i] = s.haveBelow ? down : extra;
    }
    uint edge = 0u;  // bit i: pixel xs + i is an edge pixel
    for (int i = 0; i < SSFX_AA_SEGMENT; ++i) {
        if (!inside || xs + i >= pc.width) continue;
        // Luma3x3 names: S is the row above, N the row below.
        const Luma3x3 n = Luma3x3(row[i + 1], row[i], row[i + 2], above[i + 1], below[i + 1], above[i], below[i],
                                  above[i + 2], below[i + 2]);
        if (edgeAt(xs + i, y, n))
            edge |= 1u << uint(i);
        else
            copyTexel(ivec2(xs + i, y), raw[i]);
    }
    const uint count = uint(bitCount(edge));
    const uint first = subgroupExclusiveAdd(count), total = subgroupAdd(count);
    const uint origin = uint(min(xs, 0xffff)) | (uint(min(y, 0xffff)) << 16u);
    for (uint j = 0u; j < total; j += gl_SubgroupSize) {
        const uint k = j + gl_SubgroupInvocationID;  // this lane's edge pixel of the subgroup's
        // Its owner: the last lane whose first pixel is at most k (a lane with none has the
        // next lane's first, so the last such lane has one).
        uint owner = 0u;
        for (uint l = 1u; l < gl_SubgroupSize; ++l)
            if (subgroupShuffle(first, l) <= k) owner = l;
        uint bits = subgroupShuffle(edge, owner);
        const uint at = subgroupShuffle(origin, owner), rank = k - subgroupShuffle(first, owner);
        for (uint r = 0u; r < rank; ++r) bits &= bits - 1u;  // drop the owner's earlier pixels
        const int bit = findLSB(bits);
        // The pixel's 3 x 3 lumas, from the owner's rows (columns bit .. bit + 2 of them).
        float a[3], m[3], b[3];
        for (int i = 0; i < SSFX_AA_SEGMENT + 2; ++i) {
            const float ai = subgroupShuffle(above[i], owner), mi = subgroupShuffle(row[i], owner),
                        bi = subgroupShuffle(below[i], owner);
            for (int c = 0; c < 3; ++c) {
                if (i == bit + c) {
                    a[c] = ai;
                    m[c] = mi;
                    b[c] = bi;
                }
            }
        }
        if (k < total) {
            const ivec2 p = ivec2(int(at & 0xffffu) + bit, int(at >> 16u));
            const Luma3x3 n = Luma3x3(m[1], m[0], m[2], a[1], b[1], a[0], b[0], a[2], b[2]);
            store(p, edgeColour(p.x, p.y, n), alphaAt(p.x, p.y));
        }
    }
}

void main() { segments(); }
#else
void main() {
    if (spec_stage == SSFX_AA_STAGE_EDGES) {
        // Each group walks a contiguous run of the list (its lanes consecutive entries), not
        // every groupsX-th block of it: the classify groups append in about the image's
        // order (a band of rows at a time), so a group's reads and writes stay in a band of
        // rows that the caches hold (lavapipe, 256 groups: the edge dispatch took a median
        // 0.85 of the strided walk's time, 80 paired runs over every method, both modes and
        // three images; docs/gpu.md). Iterations per invocation are the same either way (the
        // loop budget's count). With one pixel per invocation (a GPU) both walks are the same.
        const uint lanes = uint(SSFX_AA_EDGE_GROUP);
        const uint per = (edges.count + edges.groupsX * lanes - 1u) / (edges.groupsX * lanes) * lanes;
        const uint begin = gl_WorkGroupID.x * per, end = min(begin + per, edges.count);
        for (uint i = begin + gl_LocalInvocationID.x; i < end; i += lanes) {
            const uint e = edges.pixels[i];
            const ivec2 p = ivec2(e & 0xffffu, e >> 16u);
            store(p, edgeColour(p.x, p.y, neighbourhood(p.x, p.y)), alphaAt(p.x, p.y));
        }
        return;
    }
    // The luma and classify dispatches: one invocation per luma-plane texel (q, y), pixels
    // x0 .. x0 + 3 of row y.
    const int q = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
    const int x0 = q * SSFX_AA_LUMA_PACK;
    if (spec_stage == SSFX_AA_STAGE_LUMA || spec_stage == SSFX_AA_STAGE_CLASSIFY)
        if (q >= lumaPlaneWidth() || y >= pc.height) return;
    if (spec_stage == SSFX_AA_STAGE_LUMA) {
        // The lumas, and the pixels copied to the output unchanged (the texel as fetched, as
        // noaa stores it): the edge dispatch overwrites the edge pixels.
        float l[SSFX_AA_LUMA_PACK];
        for (int i = 0; i < SSFX_AA_LUMA_PACK; ++i) {
            const int x = min(x0 + i, pc.width - 1);  // past the last column: the padding
            const vec4 raw = texelRaw(x, y);
            l[i] = edgeLuma(texelDecoded(raw));
            if (x0 + i < pc.width) copyTexel(ivec2(x, y), raw);
        }
        imageStore(lumaPlane, ivec2(q, y), vec4(l[0], l[1], l[2], l[3]));
        return;
    }
    if (spec_stage == SSFX_AA_STAGE_CLASSIFY) {
        const LumaRow above = lumaRow(q, y - 1), row = lumaRow(q, y), below = lumaRow(q, y + 1);
        bool edge[SSFX_AA_LUMA_PACK];
        for (int i = 0; i < SSFX_AA_LUMA_PACK; ++i) {
            // Luma3x3 names: S is the row above, N the row below.
            const Luma3x3 n = Luma3x3(row.l[i + 1], row.l[i], row.l[i + 2], above.l[i + 1], below.l[i + 1], above.l[i],
                                      below.l[i], above.l[i + 2], below.l[i + 2]);
            edge[i] = x0 + i < pc.width && edgeAt(x0 + i, y, n);
        }
        appendEdges(x0, y, edge);
        return;
    }
    // Stage 0, one pass (gpu::EdgePath::OnePass: a GPU's path, and every device's for an
    // image whose list would not fit in a storage buffer). The work group's edge pixels are
    // compacted into a list in workgroup memory, then computed by the group's first
    // invocations, one listed pixel each: on a GPU the edge computation then runs in as few
    // subgroups as the group has edge pixels, all their lanes busy, instead of in every
    // subgroup that holds one edge pixel (about 20 % of a photograph's pixels are edges, and
    // nearly every 32-pixel subgroup holds one). Every invocation reaches the barriers.
    if (gl_LocalInvocationIndex == 0u) groupEdgeCount = 0u;
    loadTile();  // its barrier also publishes the count's reset
    ivec2 p;
    if (outputPixel(p)) {
        if (edgeAt(p.x, p.y, neighbourhood(p.x, p.y)))
            groupEdges[atomicAdd(groupEdgeCount, 1u)] = uint(p.x) | (uint(p.y) << 16u);
        else
            copyTexel(p, texelRaw(p.x, p.y));
    }
    barrier();
    const uint listed = groupEdgeCount, size = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    for (uint i = gl_LocalInvocationIndex; i < listed; i += size) {
        const uint e = groupEdges[i];
        const ivec2 q = ivec2(e & 0xffffu, e >> 16u);
        store(q, edgeColour(q.x, q.y, neighbourhood(q.x, q.y)), alphaAt(q.x, q.y));
    }
}
#endif
