// The vector GTAO main pass (gtao-inl.h): what it needs, flattened into plain arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "ssfx/ao/gtao.hpp"

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
    // Set after the fields above (gtao.cpp):
    //! Each level's start in `chain`, width and height, padded to 16 entries: a register
    //! table where a vector holds 8 or more lanes.
    std::int32_t levelStart16[16] = {}, levelWidth16[16] = {}, levelHeight16[16] = {};
    //! The texel of column / row p is computed, floor((2 p + 1) W_m / 2 W), rather than read
    //! from texelX / texelY: (2 W + 1) W and (2 H + 1) H fit an int32 with room (gtao.cpp).
    bool arithmeticTexels = false;
    //! Cheaper still where the setup found it exact for every column, row and level (it
    //! checks them all against texelX / texelY): the texel is trunc((2 p + 1) * scale_m)
    //! with scale_m = float(W_m / 2W) (resp. H), one product.
    bool floatTexels = false;
    float texelScaleX16[16] = {}, texelScaleY16[16] = {};
    //! With floatTexels, where the chain holds fewer than 2^23 texels: the sample's index in
    //! `chain` as one float multiply-add (exact) from the level's start and width as floats.
    bool floatIndex = false;
    float levelStartF16[16] = {}, levelWidthF16[16] = {};
    //! 2^(2 - 2 mipOffset): level m is round(log2 |s| - mipOffset) clamped to [0, 4], read
    //! from the exponent of |s|^2 lodScale (gtao-inl.h) without a logarithm.
    float lodScale = 0.0f;
    //! GtaoNoisePlanes::values where the setup made them (else null: the pass derives the
    //! same quantities from noiseS and noiseT with Highway's cosine and sine).
    const float* noisePlanes = nullptr;
    //! Clamp every sample (test hook gtaoClampEverywhereForTest), else only where a vector's
    //! samples could leave the buffer.
    bool clampEverywhere = false;
};

//! What the main pass derives from the noise alone, per noise cell (x mod 64, y mod 64), in
//! the scalar oracle's own operations (GtaoMain::pixel: libm's cosine and sine, an IEEE
//! division), so the same bits: for slice k, cos phi_k (plane 2 k) and sin phi_k (plane
//! 2 k + 1); for slice k and step j, the step's spacing ((j + xj) / J)^2 (plane 2 S + k J + j).
//! A plane is 64 rows of kStride floats; entries 64 .. kStride - 1 of a row repeat entries
//! 0 .. 15, so that up to 16 lanes load a row's cells from any column without wrapping.
struct GtaoNoisePlanes {
    static constexpr int kStride = 80;
    static constexpr int kPlaneFloats = 64 * kStride;
    //! Planes beyond this many (S (J + 2) > 512: 10 MiB) are not made.
    static constexpr int kMaxPlanes = 512;
    int slices = 0, steps = 0;
    float power = 0.0f;  //!< sampleDistributionPower
    std::vector<float> values;
};
//! Makes `planes` for p's slices, steps and sampleDistributionPower (kept while those stay);
//! false, and none made, past kMaxPlanes.
bool gtaoNoisePlanes(const GtaoParams& p, GtaoNoisePlanes& planes);

//! How the vector pass finds each sample's texel (GtaoSimdInput): the one product where the
//! setup found it exact (its index in floats where the chain is small enough, else in
//! integers), else the corrected arithmetic where it fits an int32, else the setup's tables.
//! Tests force each path (all give the same texels, so the same bytes).
enum class GtaoTexelPath { Auto, Product, ProductIntegerIndex, Arithmetic, Tables };
GtaoTexelPath& gtaoTexelPathForTest();
//! Whether the vector pass may use noise planes (GtaoNoisePlanes; true): tests turn them off
//! to run the arithmetic that replaces them.
bool& gtaoNoisePlanesForTest();
//! Whether the vector pass clamps every sample to the buffer (false): tests set it to compare
//! the lanes known to stay inside with the clamped code.
bool& gtaoClampEverywhereForTest();
//! Test hook: how many p in [0, n) get a computed texel (the arithmetic path) other than
//! floor((2 p + 1) wm / 2 n), on the SIMD target this machine dispatches to.
std::int64_t gtaoTexelMismatches(int n, int wm);

//! A before the denoiser of pixels [x0, x1) of buffer row y into out[0 ..) (sampleDistribution
//! power 2 only), whole vectors; returns the first x it left to the scalar loop.
int gtaoRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, float* out);

//! The edges (packed as quantiseEdges) and normals from depth (x y z interleaved) of pixels
//! [x0, x1) of buffer row y, 1 <= x0, x1 <= width - 1, written from edges[0] and
//! normals[0]; whole vectors, the same bits as gtaoEdges and gtaoNormalFromDepth (sky:
//! (0, 0, 0)); returns the first x it left to the scalar loop. Reads chain level 0,
//! width, height, ax, bx, ay, by.
//! What the vector denoiser reads (GtaoDenoise without bent normals).
struct GtaoDenoiseInput {
    const float* t0;            //!< chain level 0 (t = -z; +infinity: sky), `width` per row
    int width;                  //!< of the buffer
    const std::uint8_t* edges;  //!< work region, row-major (quantiseEdges)
    const float* a;             //!< the pass's input, work region, row-major
    int workX0, workY0, workWidth, workHeight;
    float beta;
};

//! GtaoDenoise::pixel for pixels [x0, x1) of buffer row y (workX0 + 1 <= x0, x1 <= workX0 +
//! workWidth - 1) into out[0 ..), whole vectors, the same bits; returns the first x it left
//! to the scalar loop.
int gtaoDenoiseRowSimd(const GtaoDenoiseInput& in, int y, int x0, int x1, float* out);

int gtaoEdgesNormalsRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, std::uint8_t* edges, float* normals);

}  // namespace ssfx::ao::detail
