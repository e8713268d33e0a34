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
// offset k along it, minus localAverage.
float searchDelta(bool horizontal, float cu, float cv, float move, int k, float localAverage) {
    vec3 c;
    if (pc.sampling != 0) {
        c = horizontal ? sampleAt(cu + move, cv, k, 0) : sampleAt(cu, cv + move, 0, k);
    } else if (horizontal) {
        precise float along = cu + move;
        c = sampleModel(axisU(along), axisV(cv), k, 0);
    } else {
        precise float along = cv + move;
        c = sampleModel(axisU(cu), axisV(along), 0, k);
    }
    precise float delta = edgeLuma(c) - localAverage;
    return delta;
}

// One side of the search: the distance to the end of the edge (maxDistance + 1 when not
// found) and the delta there (or at the last read).
void searchSide(int sign, float first, bool horizontal, float cu, float cv, float invAlong, float gradientScaled,
                float localAverage, out float distance, out float delta) {
    // Round 0: the free position 1, then reads at texel offsets 2 and 3 from c.
    delta = first;
    if (abs(delta) >= gradientScaled) {
        distance = 1.0;
        return;
    }
    for (int k = 2; k <= kBatch; ++k) {
        delta = searchDelta(horizontal, cu, cv, 0.0, sign * k, localAverage);
        if (abs(delta) >= gradientScaled) {
            distance = float(k);
            return;
        }
    }
    // Later rounds: c moved offset + 2 pixels, texel offsets -1, 0, +1, nearest first.
    for (int r = 1; r < pc.searchRounds; ++r) {
        const int offset = kBatch * r;
        precise float move = float(sign) * (float(offset + 2) * invAlong);
        for (int k = -1; k <= 1; ++k) {
            delta = searchDelta(horizontal, cu, cv, move, sign * k, localAverage);
            if (abs(delta) >= gradientScaled) {
                distance = float(offset + 2 + k);
                return;
            }
        }
    }
    distance = float(kBatch * pc.searchRounds + 1);
}

// Offset across the edge, in pixels, signed towards the steep side.
float edgeSearchOffset(int x, int y, Luma3x3 n, EdgeSides s) {
    const bool steep2 = abs(s.g2) > abs(s.g1);  // ties go to side 1
    const float lumaSteep = steep2 ? s.luma2 : s.luma1;
    precise float gradientScaled = 0.25 * maxf(abs(s.g1), abs(s.g2));
    precise float localAverage = (lumaSteep + n.C) * 0.5;
    const int across = steep2 ? 1 : -1;

    // First positions, free: the neighbours along the edge and their diagonals on the steep side.
    precise float first1, first2;
    if (s.horizontal) {
        first1 = (n.W + (steep2 ? n.NW : n.SW)) * 0.5;
        first2 = (n.E + (steep2 ? n.NE : n.SE)) * 0.5;
    } else {
        first1 = (n.S + (steep2 ? n.SE : n.SW)) * 0.5;
        first2 = (n.N + (steep2 ? n.NE : n.NW)) * 0.5;
    }
    // c: the centre moved half a pixel across, towards the steep side.
    precise float cu = centreU(x);
    precise float cv = centreV(y);
    if (s.horizontal)
        cv += float(across) * 0.5 * pc.invH;
    else
        cu += float(across) * 0.5 * pc.invW;
    const float invAlong = s.horizontal ? pc.invW : pc.invH;

    float d1, delta1, d2, delta2;
    precise float f1 = first1 - localAverage;
    precise float f2 = first2 - localAverage;
    searchSide(-1, f1, s.horizontal, cu, cv, invAlong, gradientScaled, localAverage, d1, delta1);
    searchSide(+1, f2, s.horizontal, cu, cv, invAlong, gradientScaled, localAverage, d2, delta2);

    precise float sum = d1 + d2;
    precise float pixelOffset = 0.5 - crDiv(minf(d1, d2), sum);
    const float deltaNear = d1 < d2 ? delta1 : delta2;  // ties: side 2
    // "Correct variation": the luma at the nearer end lies on the other side of the local
    // average than the centre, so the edge really ends there.
    const bool correct = (deltaNear < 0.0) != (n.C < localAverage);
    precise float signedOffset = pixelOffset * float(across);
    return correct ? signedOffset : 0.0;
}

void main() {
    loadTile();
    ivec2 p;
    if (!outputPixel(p)) return;
    const Luma3x3 n = neighbourhood(p.x, p.y);
    float range;
    if (belowEdgeThreshold(n, range)) {
        storeInput(p);
        return;
    }
    const EdgeSides s = edgeSides(n);
    Diffusion d = diffusion(n, s);
    const float offset = edgeSearchOffset(p.x, p.y, n, s);
    // Combination (section 2.3): the search offset moves both diffusion reads, and a large
    // offset (near an edge's end) weakens the diffusion.
    precise float edgeStrength = minf(1.0, 2.0 * abs(offset));
    precise float st = d.strength * (1.0 - edgeStrength);
    d.strength = st;
    precise float offU = s.horizontal ? 0.0 : offset * pc.invW;
    precise float offV = s.horizontal ? offset * pc.invH : 0.0;
    store(p, diffuse(p.x, p.y, d, offU, offV), alphaAt(p.x, p.y));
}
