#version 450
// ddaa2: directional diffusion combined with a clean edge search (Klein, DDAA, sections
// 2.3-2.5; spec ppaa.md "ddaa2"; the CPU's src/aa/ddaa2.cpp). The search walks half a pixel
// towards the steeper side, one pixel per step, 3 reads per round from one coordinate plus
// integer texel offsets ("batched sampling", section 2.5).
#define SSFX_TILE
#include "ppaa.glsl"
#include "ddaa.glsl"

const int kBatch = 3;  // samples per round: EDGE_STEP_LIST = [3, 3, 3, 3, 3]

// The luma of the search read at c moved `move` (texture units) along the edge, plus texel
// offset k along it, minus localAverage. With spec_pairReads (aa_pass.cpp: the CPU's
// searchReadsArePairReads holds for this size) that read is the pair read of the texels
// `along` pixels from (x, y) along the edge, across at rows/columns +a0 and +a0 + 1: the
// same value from two fetches and no coordinate arithmetic (in the hardware mode, which takes
// it on CPU devices, the mean of the device's two texels: its filter's value up to rounding).
float searchDelta(int x, int y, int a0, int along, bool horizontal, float cu, float cv, float move, int k,
                  float localAverage) {
    if (spec_pairReads != 0) {
        const ivec2 p = horizontal ? ivec2(x + along, y + a0) : ivec2(x + a0, y + along);
        EXACT float d = edgeLuma(pairRead(p, p + (horizontal ? ivec2(0, 1) : ivec2(1, 0)))) - localAverage;
        return d;
    }
    // One read, its coordinates chosen by value: a branch with a read on each side would
    // cost both reads on drivers that run shaders as masked SIMD code (lavapipe).
    EXACT float movedU = cu + move;
    EXACT float movedV = cv + move;
    const float su = horizontal ? movedU : cu, sv = horizontal ? cv : movedV;
    const int ox = horizontal ? k : 0, oy = horizontal ? 0 : k;
    const vec3 c = spec_sampling != 0 ? sampleAt(su, sv, ox, oy) : sampleModel(axisU(su), axisV(sv), ox, oy);
    EXACT float delta = edgeLuma(c) - localAverage;
    return delta;
}

// The position (pixels from c along the edge) of read k (0, 1, 2) of round r, and its
// coordinate move and texel offset: round 0 reads positions 2 and 3 (position 1 is free),
// round r > 0 moves c by 3 r + 2 pixels and reads offsets -1, 0, +1 around it.
int roundPosition(int r, int k) { return r == 0 ? k + 2 : kBatch * r + 2 + (k - 1); }
// Offset across the edge, in pixels, signed towards the steep side; centre: the pixel's centre
// (centreU, centreV).
float edgeSearchOffset(int x, int y, vec2 centre, Luma3x3 n, EdgeSides s) {
    const bool steep2 = abs(s.g2) > abs(s.g1);  // ties go to side 1
    const float lumaSteep = steep2 ? s.luma2 : s.luma1;
    EXACT float gradientScaled = 0.25 * maxf(abs(s.g1), abs(s.g2));
    EXACT float localAverage = (lumaSteep + n.C) * 0.5;
    const int across = steep2 ? 1 : -1;
    const int a0 = steep2 ? 0 : -1;  // the search reads between rows/columns +a0 and +a0 + 1

    // First positions, free: the neighbours along the edge and their diagonals on the steep side.
    EXACT float first1, first2;
    if (s.horizontal) {
        first1 = (n.W + (steep2 ? n.NW : n.SW)) * 0.5;
        first2 = (n.E + (steep2 ? n.NE : n.SE)) * 0.5;
    } else {
        first1 = (n.S + (steep2 ? n.SE : n.SW)) * 0.5;
        first2 = (n.N + (steep2 ? n.NE : n.NW)) * 0.5;
    }
    // c: the centre moved half a pixel across, towards the steep side.
    EXACT float cu = centre.x;
    EXACT float cv = centre.y;
    if (s.horizontal)
        cv += float(across) * 0.5 * pc.invH;
    else
        cu += float(across) * 0.5 * pc.invW;
    const float invAlong = s.horizontal ? pc.invW : pc.invH;

    // Both sides in step, round by round: the reads of each side, and so its result, are the
    // CPU's; in step, the invocations of a SIMD lane group wait for the slower side once per
    // round instead of once per side. With spec_batchedSearch a round's reads are batched
    // (the paper's section 2.5): every read of a side that had not found its end when the
    // round began is issued before any of them is tested, and reads past the end found in
    // the round are ignored (the CPU stops there: they change nothing). Batched on a CPU
    // device (lavapipe: edge dispatch 41-42 ms against 46.5-46.7 ms, paired runs), one read
    // at a time on a GPU (the H200: 45-51 us batched 55-61 us; docs/gpu.md).
    EXACT float delta1 = first1 - localAverage;
    EXACT float delta2 = first2 - localAverage;
    bool done1 = abs(delta1) >= gradientScaled, done2 = abs(delta2) >= gradientScaled;
    float d1 = 1.0, d2 = 1.0;
    if (spec_sideSearch != 0) {
        // One read a step, one side at a time (a CPU device's choice, aa_pass.cpp): each
        // iteration reads side 1 while it searches, then side 2. Read j of a side is at
        // position j + 2, the rounds' positions in order (round 0: 2, 3; round r: 3 r + 1 ..
        // 3 r + 3), with its round's coordinate move and texel offset, so each side's reads,
        // tests and end are the loop's below; but a SIMD lane group runs as many reads as its
        // longest pixel's two sides together, where the rounds of both sides in step run six
        // a round until its longest side ends (a simulation of the search over 8 consecutive
        // edge pixels: the photograph 14.6 -> 7.7 reads, the atrium 23.7 -> 16.4; docs/gpu.md).
        const int reads = pc.searchRounds > 0 ? 2 + kBatch * (pc.searchRounds - 1) : 0;  // a side's
        int j1 = 0, j2 = 0;  // each side's next read
        bool search1 = !done1 && reads > 0, search2 = !done2 && reads > 0;
        while (search1 || search2) {
            const bool side1 = search1;
            const int j = side1 ? j1 : j2;
            const int position = j + 2;
            const int r = (position - 1) / kBatch;  // its round
            const int moved = r == 0 ? 0 : kBatch * r + 2;  // pixels
            const int offset = position - moved;             // texel offset from the round's coordinate
            EXACT float move = float(moved) * invAlong;
            EXACT float signedMove = side1 ? -move : move;
            const float delta = searchDelta(x, y, a0, side1 ? -position : position, s.horizontal, cu, cv, signedMove,
                                            side1 ? -offset : offset, localAverage);
            const bool done = abs(delta) >= gradientScaled;
            if (side1) {
                delta1 = delta;
                done1 = done;
                d1 = done ? float(position) : d1;
                j1 = j + 1;
                search1 = !done && j1 < reads;
            } else {
                delta2 = delta;
                done2 = done;
                d2 = done ? float(position) : d2;
                j2 = j + 1;
                search2 = !done && j2 < reads;
            }
        }
    } else {
        for (int r = 0; r < pc.searchRounds && !(done1 && done2); ++r) {
            const int moved = r == 0 ? 0 : kBatch * r + 2;  // pixels
            EXACT float move = float(moved) * invAlong;
            // Fixed trip counts (read 0 of round 0 is skipped inside), so the arrays stay in registers.
            float read1[kBatch], read2[kBatch];
            for (int k = 0; k < kBatch && spec_batchedSearch != 0; ++k) {
                const int offset = r == 0 ? k + 1 : k - 1;
                const bool read = r > 0 || k > 0;
                read1[k] = read && !done1 ? searchDelta(x, y, a0, -(moved + offset), s.horizontal, cu, cv, -move, -offset,
                                                        localAverage)
                                          : 0.0;
                read2[k] = read && !done2
                               ? searchDelta(x, y, a0, moved + offset, s.horizontal, cu, cv, move, offset, localAverage)
                               : 0.0;
            }
            for (int k = 0; k < kBatch; ++k) {
                if (r == 0 && k == 0) continue;
                const int offset = r == 0 ? k + 1 : k - 1;  // texel offset from the round's coordinate
                const float position = float(roundPosition(r, r == 0 ? k - 1 : k));
                if (!done1) {
                    delta1 = spec_batchedSearch != 0 ? read1[k]
                                                     : searchDelta(x, y, a0, -(moved + offset), s.horizontal, cu, cv,
                                                                   -move, -offset, localAverage);
                    done1 = abs(delta1) >= gradientScaled;
                    d1 = done1 ? position : d1;
                }
                if (!done2) {
                    delta2 = spec_batchedSearch != 0
                                 ? read2[k]
                                 : searchDelta(x, y, a0, moved + offset, s.horizontal, cu, cv, move, offset, localAverage);
                    done2 = abs(delta2) >= gradientScaled;
                    d2 = done2 ? position : d2;
                }
            }
        }
    }
    const float notFound = float(kBatch * pc.searchRounds + 1);
    if (!done1) d1 = notFound;
    if (!done2) d2 = notFound;

    EXACT float sum = d1 + d2;
    EXACT float pixelOffset = 0.5 - divide(minf(d1, d2), sum);
    const float deltaNear = d1 < d2 ? delta1 : delta2;  // ties: side 2
    // "Correct variation": the luma at the nearer end lies on the other side of the local
    // average than the centre, so the edge really ends there.
    const bool correct = (deltaNear < 0.0) != (n.C < localAverage);
    EXACT float signedOffset = pixelOffset * float(across);
    return correct ? signedOffset : 0.0;
}

// The colour of an edge pixel: the diffusion, moved by the edge search's offset.
bool edgeAt(int x, int y, Luma3x3 n) { return edgeAt3x3(n); }
vec3 edgeColour(int x, int y, Luma3x3 n) {
    const EdgeSides s = edgeSides(n);
    Diffusion d = diffusion(n, s);
    const vec2 centre = vec2(centreU(x), centreV(y));
    const float offset = edgeSearchOffset(x, y, centre, n, s);
    // Combination (section 2.3): the search offset moves both diffusion reads, and a large
    // offset (near an edge's end) weakens the diffusion.
    EXACT float edgeStrength = minf(1.0, 2.0 * abs(offset));
    EXACT float st = d.strength * (1.0 - edgeStrength);
    d.strength = st;
    EXACT float offU = s.horizontal ? 0.0 : offset * pc.invW;
    EXACT float offV = s.horizontal ? offset * pc.invH : 0.0;
    return diffuse(centre, d, offU, offV);
}

#include "edge_list.glsl"
