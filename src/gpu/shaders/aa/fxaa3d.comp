#version 450
// fxaa3d: FXAA 3.11 "desktop"/quality with a 12-iteration edge search (T. Lottes, NVIDIA
// 2011), as in the DDAA paper's comparison (spec ppaa.md "fxaa3d"; the CPU's
// src/aa/fxaa3d.cpp). paperSearchQuirk (default on): side 2 steps back one pixel after its
// first read, as the paper's shader does.
#define SSFX_TILE
#include "ppaa.glsl"

// Step after each unsuccessful read, in pixels: 1 for the first five, then skipping (the
// skipping gives FXAA its stipple artifacts, DDAA paper Fig. 7; kept: it is the baseline).
const float kSteps[12] = float[12](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

float walkLuma(bool horizontal, float wu, float wv, float localAverage) {
    const vec3 c = sampleUV(wu, wv);
    EXACT float d = edgeLuma(c) - localAverage;
    return d;
}

// The colour of an edge pixel: the edge search along it, then one read moved across it by
// the larger of the search's offset and the sub-pixel term.
bool edgeAt(int x, int y, Luma3x3 n) { return edgeAt3x3(n); }
vec3 edgeColour(int x, int y, Luma3x3 n) {
    float range;
    belowEdgeThreshold(n, range);
    const EdgeSides s = edgeSides(n);
    const bool pair1 = abs(s.g1) >= abs(s.g2);  // steeper side; ties go to side 1
    const float lumaSteep = pair1 ? s.luma1 : s.luma2;
    EXACT float gradientScaled = 0.25 * maxf(abs(s.g1), abs(s.g2));
    EXACT float localAverage = (lumaSteep + n.C) * 0.5;
    float lengthSign = s.horizontal ? pc.invH : pc.invW;
    if (pair1) lengthSign = -lengthSign;

    const float u = centreU(x), v = centreV(y);
    // posB: half a pixel across, towards the steep side; off: one pixel along the edge.
    EXACT float bu = u, bv = v;
    if (s.horizontal)
        bv += lengthSign * 0.5;
    else
        bu += lengthSign * 0.5;
    const float offU = s.horizontal ? pc.invW : 0.0;
    const float offV = s.horizontal ? 0.0 : pc.invH;

    EXACT float nU = bu - offU * kSteps[0], nV = bv - offV * kSteps[0];
    EXACT float pU = bu + offU * kSteps[0], pV = bv + offV * kSteps[0];
    EXACT float endN = walkLuma(s.horizontal, nU, nV, localAverage);
    EXACT float endP = walkLuma(s.horizontal, pU, pV, localAverage);
    bool doneN = abs(endN) >= gradientScaled;
    bool doneP = abs(endP) >= gradientScaled;
    if (spec_sideSearch != 0) {
        // One side a step (a CPU device's choice, aa_pass.cpp): each iteration moves and reads
        // side N while it searches, then side P. The sides are independent (each its own
        // positions, reads and end), so each gets the same operations as in the loop below,
        // but a SIMD lane group runs as many reads as its longest pixel's two sides together,
        // not twice its longest side (a simulation of the walk on the photograph: 25 % fewer
        // reads; docs/gpu.md).
        int iN = 1, iP = 1;  // each side's next step
        bool searchN = !doneN, searchP = !doneP;
        while (searchN || searchP) {
            const bool sideN = searchN;
            const int i = sideN ? iN : iP;  // 1 .. 10: the steps with a read
            const float step = i < 5 ? 1.0 : (i == 5 ? 1.5 : (i < 10 ? 2.0 : 4.0));  // kSteps[i]
            const bool back = sideN || (i == 1 && pc.paperSearchQuirk != 0);
            EXACT float moveU = offU * step;
            EXACT float moveV = offV * step;
            const float fromU = sideN ? nU : pU, fromV = sideN ? nV : pV;
            EXACT float atU = back ? fromU - moveU : fromU + moveU;
            EXACT float atV = back ? fromV - moveV : fromV + moveV;
            EXACT float end = walkLuma(s.horizontal, atU, atV, localAverage);
            const bool done = abs(end) >= gradientScaled;
            if (sideN) {
                nU = atU;
                nV = atV;
                endN = end;
                doneN = done;
                iN = i + 1;
                searchN = !done && iN < 11;
            } else {
                pU = atU;
                pV = atV;
                endP = end;
                doneP = done;
                iP = i + 1;
                searchP = !done && iP < 11;
            }
        }
        // A side that found no end takes the last step, without a read.
        if (!doneN) {
            nU -= offU * kSteps[11];
            nV -= offV * kSteps[11];
        }
        if (!doneP) {
            pU += offU * kSteps[11];
            pV += offV * kSteps[11];
        }
    } else {
        // Both sides a step, as the paper's shader (a GPU's choice).
        for (int i = 1; i < 12; ++i) {
            if (!doneN) {
                nU -= offU * kSteps[i];
                nV -= offV * kSteps[i];
            }
            if (!doneP) {
                if (i == 1 && pc.paperSearchQuirk != 0) {
                    pU -= offU * kSteps[i];
                    pV -= offV * kSteps[i];
                } else {
                    pU += offU * kSteps[i];
                    pV += offV * kSteps[i];
                }
            }
            if ((doneN && doneP) || i == 11) break;  // after the last step there is no read
            if (!doneN) endN = walkLuma(s.horizontal, nU, nV, localAverage);
            if (!doneP) endP = walkLuma(s.horizontal, pU, pV, localAverage);
            doneN = doneN || abs(endN) >= gradientScaled;
            doneP = doneP || abs(endP) >= gradientScaled;
        }
    }

    EXACT float dstN = s.horizontal ? u - nU : v - nV;
    EXACT float dstP = s.horizontal ? pU - u : pV - v;
    EXACT float centreOff = n.C - localAverage;
    const bool centreBelow = centreOff < 0.0;
    const bool goodSpanN = (endN < 0.0) != centreBelow;
    const bool goodSpanP = (endP < 0.0) != centreBelow;
    const bool directionN = dstN < dstP;
    EXACT float spanSum = dstN + dstP;
    EXACT float pixelOffset = 0.5 - divide(minf(dstN, dstP), spanSum);
    const bool goodSpan = directionN ? goodSpanN : goodSpanP;

    // Sub-pixel aliasing term (FXAA 3.11 subpix, spec step 6).
    EXACT float avg = (1.0 / 12.0) * (2.0 * ((n.S + n.N) + (n.W + n.E)) + (n.SW + n.NW) + (n.SE + n.NE));
    EXACT float dev = abs(avg - n.C);
    EXACT float sp = range > 0.0 ? minf(maxf(divide(dev, range), 0.0), 1.0) : 0.0;
    sp = (-2.0 * sp + 3.0) * sp * sp;
    EXACT float sub = sp * sp * pc.subpix;

    const float offset = maxf(goodSpan ? pixelOffset : 0.0, sub);
    EXACT float shift = offset * lengthSign;
    EXACT float ru = u + shift;
    EXACT float rv = v + shift;
    return sampleUV(s.horizontal ? u : ru, s.horizontal ? rv : v);  // one read (see ddaa2's searchDelta)
}

#include "edge_list.glsl"
