// The vector AO sample pass (sao-inl.h): what it needs, flattened into plain arrays.
#pragma once

#include <cstdint>

namespace ssfx::ao::detail {

struct SimdSampleInput {
    const float* levels;              //!< all pyramid levels, one after the other (level 0 first)
    const std::int32_t* levelOffset;  //!< [maxLevel + 1] start of each level in `levels`
    const std::int32_t* levelW;       //!< [maxLevel + 1] sizes
    const std::int32_t* levelH;
    int maxLevel;       //!< highest level a tap may read
    int width, height;  //!< level 0
    const float* fx;    //!< position tables (ao_sampling.hpp PositionTables)
    const float* fy;
    float ax, bx, ay, by;  //!< fx(x) = ax + bx * x, fy(y) = ay + by * y (PositionTables)
    float pixelsPerMeter, radius;
    int numSamples, logQ;
    const float *alpha, *dirX, *dirY;  //!< the spiral, [numSamples]
    int estimator;                     //!< 0: SAO's falloff, 1: AlchemyAO (eq. 1)
    float r2, bias, beta, epsilon, scale;
    float scale2;  //!< A = max(0, 1 - (sum * scale) * scale2) (1: one factor)
    //! [numSamples] alpha_k float(tau turnAngle) when each tap's angle is summed with the hash
    //! angle in float (SaoParams::spinInFloat); null: the spiral rotated per pixel.
    const float* tapAngle;
};

//! z = c0 / (d c1 + c2) for one row (depth-inl.h); false, with `z` unspecified, when some
//! d is outside [0, 1] or NaN (the caller's per-pixel loop then reports it).
bool depthToZRowSimd(const float* d, float* z, int n, double c0, double c1, double c2);

//! One output row of a bilateral blur pass (bilateral-inl.h): tap t of pixel i reads
//! zTap[t][i] and aTap[t][i] (row pointers already moved by the tap's offset).
struct BilateralRowInput {
    static constexpr int kMaxTaps = 17;  //!< 2 blurRadius + 1, blurRadius <= 8
    int taps;
    const float* zCentre;
    const float* zTap[kMaxTaps];
    const float* aTap[kMaxTaps];
    float gauss[kMaxTaps];  //!< spatial weight of each tap
    float edgeSharpness;    //!< k of max(0, 1 - k |dz|)
    float epsilon;          //!< out = sum / (weights + epsilon)
};

//! out[i] for i in [lo, hi) of one bilateral row; 1 where zCentre[i] is infinite.
void bilateralRowSimd(const BilateralRowInput& in, int lo, int hi, float* out);

//! Pixels [x0, x1) of buffer row y into out[0 ..); A before the intensity exponent.
//! Returns the first x it left to the scalar loop.
int sampleRowSimd(const SimdSampleInput& in, int y, int x0, int x1, float* out);

}  // namespace ssfx::ao::detail
