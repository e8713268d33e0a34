// The vector GTAO main pass (gtao-inl.h): what it needs, flattened into plain arrays.
#pragma once

#include <cstdint>

namespace ssfx::ao::detail {

struct GtaoSimdInput {
    const float* chain;               //!< the depth chain's levels, one after the other (t = -z)
    const std::int32_t* levelOffset;  //!< [5] start of each level in `chain`
    const std::int32_t* levelWidth;   //!< [5]
    //! [5 width] and [5 height]: level m's texel of buffer column / row p (GtaoSetup).
    const std::int32_t* texelX;
    const std::int32_t* texelY;
    int width, height, guard;
    float ax, bx, ay, by;  //!< positions (z (ax + bx x), z (ay + by y), z) (PositionTables)
    const float* normals;  //!< work region, x y z interleaved, row-major; (0, 0, 0): none
    int workX0, workY0, workWidth;
    const float* noiseS;  //!< [64 x 64] the slice noise of (x mod 64, y mod 64)
    const float* noiseT;  //!< [64 x 64] the step noise
    float rNum, re, fRe, mipOffset, toc1, thickness, finalPower;
    int slices, steps;
    bool lift, nearFade, fastAcos, discard, minusOne;
};

//! A before the denoiser of pixels [x0, x1) of buffer row y into out[0 ..) (sampleDistribution
//! power 2 only), whole vectors; returns the first x it left to the scalar loop.
int gtaoRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, float* out);

}  // namespace ssfx::ao::detail
