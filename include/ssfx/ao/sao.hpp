// Scalable Ambient Obscurance (McGuire, Mara, Luebke, HPG 2012; spec sao.md), on the CPU.
//
// Pipeline: depth -> camera-space z (depth.hpp) -> z pyramid -> AO sample pass (spiral
// taps with a per-pixel hash rotation, a pyramid level per tap, the paper's updated
// falloff, 2x2 quad bilateral) -> two separable bilateral passes. The depth buffer may be
// larger than the output by a guard band of g pixels on each side (section 2.5): the
// guard band's geometry occludes, only the inner region is computed and returned.
// Output: ambient visibility A in [0, 1] (1 = unoccluded; sky stays 1).
//
// Every pass is a separate function so that the experiments and tests can look at each;
// sao() runs them all. Float32 arithmetic as a shader would do; rows in parallel, the
// same bytes for any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"

namespace ssfx::ao {

//! Where the sample pass and blur run: the inner region of the buffer.
struct Region {
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

//! The separable bilateral reconstruction (section 2.4); shared with the baseline.
struct BilateralParams {
    int blurRadius = 3;      //!< taps on each side (the paper's 7-tap filter)
    int blurStride = 3;      //!< px between taps (the 2x2 pass already averaged)
    float blurSigma = 2.0f;  //!< Gaussian sigma in taps (the paper gives none; our choice)
    //! 1/m: a tap's weight is multiplied by max(0, 1 - edgeSharpness * |z_tap - z|).
    //! The paper's 2^11 on its key z / (-200 m) is 2048 / 200 = 10.24 per metre.
    float edgeSharpness = 10.24f;
    //! The released blur's spatial weights (AmbientOcclusion_blur.pix, June 2012): tap t != 0
    //! weighs 0.3 + gaussian[|t|], the centre gaussian[0], summed centre first, from its table
    //! gaussian = {0.153170, 0.144893, 0.122649, 0.092902, 0.062970} (sigma 2 taps);
    //! blurSigma is then unused and blurRadius must be <= 4. Default off: exp(-t^2 / 2 sigma^2).
    bool blurReleasedWeights = false;
    //! Taps beyond the blurred region weigh 0 (the released passes read the cleared buffer
    //! there) instead of reading the region's edge pixel (clamped). Default off.
    bool blurZeroOutside = false;
    //! A = sum / (sum of weights + blurEpsilon); the released blur adds 1e-4. Default 0.
    float blurEpsilon = 0.0f;
};

//! The region SAO's sample pass and 2x2 quad pass cover: the output region grown to whole
//! 2x2 quads of the buffer grid (clamped to the buffer), so that every output pixel's quad
//! partner has a sample-pass value.
inline Region quadAligned(Region r, int w, int h) {
    const int x0 = r.x0 & ~1, y0 = r.y0 & ~1;
    const int x1 = std::min(w, (r.x0 + r.width + 1) & ~1), y1 = std::min(h, (r.y0 + r.height + 1) & ~1);
    return {x0, y0, x1 - x0, y1 - y0};
}

//! The bilateral rows of a table, for an Owner (SaoParams, AlchemyParams) whose member
//! `Blur` is a BilateralParams; names as in BilateralParams.
template <auto Blur>
constexpr std::array<ParamInfo, 7> bilateralRows() {
    return {{
        integer<Blur, &BilateralParams::blurRadius>(
            "blurRadius", "taps", 0, 8, "taps on each side of the bilateral blur (the paper: 7 taps, stride 3)"),
        integer<Blur, &BilateralParams::blurStride>("blurStride", "px", 1, 8, "pixels between the blur's taps"),
        real<Blur, &BilateralParams::blurSigma>(
            "blurSigma", "taps", 1e-3, 16, "Gaussian sigma of the blur's weights (the paper gives none; our choice)"),
        real<Blur, &BilateralParams::edgeSharpness>(
            "edgeSharpness", "1/m", 0, 1e6,
            "depth edge: a tap weighs max(0, 1 - edgeSharpness |z_tap - z|) (the paper: 2^11 on the key z / -200 m)"),
        boolean<Blur, &BilateralParams::blurReleasedWeights>(
            "blurReleasedWeights", "the released blur's spatial weights 0.3 + gaussian[|t|] (blurRadius <= 4)"),
        boolean<Blur, &BilateralParams::blurZeroOutside>("blurZeroOutside",
                                                         "taps beyond the region weigh 0 (the released passes)"),
        real<Blur, &BilateralParams::blurEpsilon>("blurEpsilon", "", 0, 1,
                                                  "A = sum / (sum of weights + blurEpsilon); released: 1e-4"),
    }};
}

struct SaoParams {
    float radius = 1.0f;     //!< m: world-space sample radius r
    float bias = 0.01f;      //!< m: beta, ignores tiny occluders from depth precision
    float epsilon = 0.01f;   //!< m^2: keeps the falloff finite as v.v -> 0
    float intensity = 1.0f;  //!< A is raised to this power
    int numSamples = 9;      //!< s (paper: 9)
    int numSpiralTurns = 7;  //!< tau (paper: 7 for s = 9; see spiralTurnsFor())
    int logQ = 3;            //!< log2 q', the mip-level switch distance (2^3..2^5 equivalent)
    int maxMip = 5;          //!< MAX_MIP, pyramid levels above 0
    bool usePyramid = true;  //!< false: every tap reads level 0 ("SAO without pyramid", Fig. 5)
    PyramidFilter pyramidFilter = PyramidFilter::RotatedGrid;
    float quadThreshold = 0.02f;  //!< m: 2x2 bilateral averages where |dz| is below this
    BilateralParams blur;
    int guardBand = 0;  //!< px on each side of the depth buffer not output
    //! The paper's bandwidth option (section 2.3, "pack A and z"): the blur reads A as 8 bits
    //! and z as a 16-bit key, key = z / packZMin in [0, 1] stored as its integer and fraction
    //! parts of key * 256 (two 8-bit channels). Default off: the blur reads float A and z.
    bool packBlurInput = false;
    float packZMin = -200.0f;  //!< m: z_min of the key (the paper's -200 m)
    //! With packBlurInput: the buffer as the released shaders store it between the passes
    //! (RGB8: A in R, the key in G and B), key = clamp(z * (1 / packZMin), 0, 1) packed as
    //! (floor(256 key) / 256, 256 key - floor(256 key)) and read back as
    //! G * 256 / 257 + B / 257; A is stored in 8 bits before *each* blur pass, and the edge
    //! weight max(0, 1 - edgeSharpness |key_tap - key|) is taken on the key itself, so
    //! edgeSharpness is per key unit (the released 2000; packZMin: their FAR_PLANE_Z, -300 m).
    bool releasedPacking = false;
    //! rad: the angle of one spiral turn, 2 pi; the released tapLocation() uses 6.28.
    double spiralTurnAngle = 2.0 * 3.14159265358979323846;
    //! The released tapLocation(): tap k's angle alpha_k (tau spiralTurnAngle) + phi is summed
    //! in float (phi is not reduced first, so the sum rounds to half an ulp of phi: the taps
    //! of pixels with large hash angles turn) before cos/sin, with alpha_k = (k + 0.5) *
    //! float(1 / s); cos/sin of that float are exact. Default off: the
    //! spiral's angles in double, rotated by phi per pixel (eq. 8 as a rotation).
    bool spinInFloat = false;
    //! The released estimator's intensity: A = max(0, 1 - ((sum * (intensity / r^6)) * (5 / s)))
    //! (a linear factor) instead of the default A = max(0, 1 - 5 / (r^6 s) sum)^intensity.
    bool linearIntensity = false;
};

//! SaoParams' table (core/params.hpp): ranges and docs; the defaults are the initialisers.
inline constexpr auto kSaoParams = concat(
    std::array{
        real<&SaoParams::radius>("radius", "m", 1e-6, 100, "world-space sample radius r"),
        real<&SaoParams::bias>("bias", "m", 0, 1, "beta: ignores tiny occluders from depth precision"),
        real<&SaoParams::epsilon>("epsilon", "m^2", 1e-9, 1, "keeps the falloff finite as v.v -> 0"),
        real<&SaoParams::intensity>("intensity", "", 0, 10, "A is raised to this power (linearIntensity: a factor)"),
        integer<&SaoParams::numSamples>("numSamples", "", 1, 64, "s, taps per pixel"),
        integer<&SaoParams::numSpiralTurns>(
            "numSpiralTurns", "", 1, 64,
            "tau, turns of the tap spiral (spiralTurnsFor(s) gives the discrepancy-minimising table)"),
        integer<&SaoParams::logQ>("logQ", "", 0, 8, "log2 q': the distance at which a tap moves up a pyramid level"),
        integer<&SaoParams::maxMip>("maxMip", "", 0, 16, "MAX_MIP: pyramid levels above 0"),
        boolean<&SaoParams::usePyramid>("usePyramid", "0: every tap reads level 0 (SAO without the pyramid)"),
        choice<&SaoParams::pyramidFilter>("pyramidFilter", kPyramidFilterNames,
                                          "z pyramid filter (rotated-grid: the paper's; others: Table 1)"),
        real<&SaoParams::quadThreshold>("quadThreshold", "m", 0, 10,
                                        "the 2x2 quad bilateral averages where |dz| is below this (released code)"),
    },
    concat(
        bilateralRows<&SaoParams::blur>(),
        std::array{
            integer<&SaoParams::guardBand>("guardBand", "px", 0, 4096, "guard band on each side, not output"),
            boolean<&SaoParams::packBlurInput>("packBlurInput", "the blur reads A as 8 bits and z as a 16-bit key"),
            real<&SaoParams::packZMin>("packZMin", "m", -1e5, -1e-3, "z_min of the packed key"),
            boolean<&SaoParams::releasedPacking>("releasedPacking",
                                                 "with packBlurInput: the released shaders' RGB8 storage"),
            real<&SaoParams::spiralTurnAngle>("spiralTurnAngle", "rad", 6, 6.5,
                                              "angle of one spiral turn (2 pi; released: 6.28)"),
            boolean<&SaoParams::spinInFloat>("spinInFloat", "the released tapLocation(): tap angles summed in float"),
            boolean<&SaoParams::linearIntensity>("linearIntensity",
                                                 "the released estimator: intensity as a linear factor"),
        }));

//! Named configurations of SaoParams (the same mechanism as `ssfx aa --preset`):
//!   "paper"    the defaults: the paper's text (s = 9, tau = 7, r = 1 m, beta = 0.01 m,
//!              intensity 1 as an exponent, the 7-tap stride-3 Gaussian blur on float z);
//!   "released" the authors' released shaders and host code (G3D 9, June 2012): s = 11,
//!              tau = 7, spiralTurnAngle 6.28, spinInFloat, linearIntensity, r = 0.7 m,
//!              bias 0.012 m, intensity 0.7, the 9-tap stride-2 blur (blurRadius 4,
//!              blurStride 2, blurReleasedWeights, blurEpsilon 1e-4, blurZeroOutside), RGB8
//!              storage between the passes (packBlurInput, releasedPacking, packZMin -300 m,
//!              edgeSharpness 2000 per key unit).
//! Throws ssfx::Error listing the names for an unknown one.
SaoParams saoPreset(const std::string& name);
//! The preset names, "paper" first.
std::vector<std::string> saoPresetNames();

//! The packing of SaoParams::packBlurInput, for tests: A -> 8-bit, and z -> the z the blur
//! sees after the 16-bit key round trip (sky stays -infinity).
float packAo(float a);
float packZ(float z, float zMin);
//! With releasedPacking: the key the released blur reads back for z (see releasedPacking;
//! sky stays -infinity, which weighs 0 as a tap and passes A = 1 through as a centre).
float releasedKey(float z, float zMin);

//! The discrepancy-minimising number of spiral turns for s samples (s = 1..30; spec sao.md);
//! the paper's default pairs s = 9 with tau = 7 instead.
int spiralTurnsFor(int numSamples);

//! With spinInFloat: tap k's angle as the released tapLocation() forms it, in float and
//! without FMA: alpha_k * float(tau * turnAngle) + phi, alpha_k = (k + 0.5) * float(1 / s).
float releasedTapAngle(int k, int numSamples, int numSpiralTurns, double spiralTurnAngle, float phi);

//! AlchemyAO's per-pixel rotation angle (paper eq. 8, the released code's form):
//! phi = 10 * float((3 x) ^ (y + x y)) radians, with C operator precedence.
float hashAngle(int x, int y);

//! Throws ssfx::Error naming the first out-of-range field.
void validate(const SaoParams& p);

//! Sets a field by its name in kSaoParams (blur fields by their own names), checked
//! (core/params.hpp setParam); throws ssfx::Error listing the names for an unknown one.
void setParam(SaoParams& p, const std::string& name, double value);

//! The raw AO sample pass over `region` of the z buffer (the pyramid's level 0): A per
//! pixel of the region, before any filtering. Pixels whose normal cannot be formed (a
//! sky neighbour in their quad) and sky pixels get A = 1.
ImageF saoSamplePass(const std::vector<ImageF>& pyramid, const Projection& proj, Region region, const SaoParams& p,
                     const Exec& exec = {});
//! The same on a pyramid already in one buffer (no copy: what sao() itself runs).
ImageF saoSamplePass(const ZPyramid& pyramid, const Projection& proj, Region region, const SaoParams& p,
                     const Exec& exec = {});

//! The face normals the sample pass uses (paper eq. 4, quad-pair differences), for every
//! pixel of the z buffer; (0, 0, 0) where none can be formed. Row-major.
std::vector<Vec3> faceNormals(ImageView<const float> z, const Projection& proj, const Exec& exec = {});

//! The 2x2 quad bilateral (end of section 2.3): within each 2x2 quad of the *buffer* grid,
//! where |dz| < threshold, A is averaged over the pair in x, then in y. In place; `a` covers
//! the region, `z` the buffer.
void quadBilateral(ImageF& a, ImageView<const float> z, Region region, float threshold, const Exec& exec = {});

//! One separable bilateral pass (horizontal or vertical) over the region; taps are clamped
//! to the region, sky pixels stay 1 and do not contribute.
ImageF bilateralPass(const ImageF& a, ImageView<const float> z, Region region, const BilateralParams& p,
                     bool horizontal, const Exec& exec = {});
//! Into `out` (reallocated only when its size differs from the region's).
void bilateralPass(const ImageF& a, ImageView<const float> z, Region region, const BilateralParams& p, bool horizontal,
                   ImageF& out, const Exec& exec = {});

//! The whole pipeline: `depth` (hardware depth in [0, 1], guard band included), the camera
//! of the whole buffer. Returns A for the inner region (size minus 2 * guardBand).
ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& params = {}, const Exec& exec = {});

//! The scalar oracle: the same pipeline with the sample pass's scalar loop only, one thread.
//! The vector kernel matches it within the tolerance stated in tests/ao/test_sao.cpp.
ImageF saoReference(ImageView<const float> depth, const Camera& camera, const SaoParams& params = {});

//! What the passes compute once per call, as the CPU's floats. The GPU passes
//! (ssfx/gpu/ao.hpp) take these very values, so the two agree on them bit for bit.
//! The sample pass's estimator and spiral: A = max(0, 1 - (sum scale) scale2)^exponent, with
//! SAO's term f^3 max((v.n - bias) / (v.v + epsilon), 0), f = max(r2 - v.v, 0), or AlchemyAO's
//! max(0, v.n + z_C bias) / (v.v + epsilon); per tap its alpha_k, the unrotated spiral's
//! direction, and with spinInFloat its float angle (else tapAngle is empty).
struct SampleConstants {
    float r2 = 0, bias = 0, epsilon = 0, scale = 0, scale2 = 1, exponent = 1;
    std::vector<float> alpha, dirX, dirY, tapAngle;
};
SampleConstants sampleConstants(const SaoParams& p);
//! Camera-space position of pixel (x, y)'s centre at depth z: (z fx(x), z fy(y), z) with
//! fx(x) = ax + bx x and fy(y) = ay + by y (paper eq. 3, y down), each evaluated in float.
struct PositionFactors {
    float ax, bx, ay, by;
};
PositionFactors positionFactors(const Projection& p);
//! The bilateral blur's taps in summation order: offsets t (in taps) and spatial weights.
struct BilateralTaps {
    std::vector<int> offset;
    std::vector<float> weight;
};
BilateralTaps bilateralTaps(const BilateralParams& p);

//! Every intermediate of one run (`ssfx ao --save-passes`, the GPU passes' parity tests).
struct AoStages {
    ImageF z;                     //!< camera-space z of the whole buffer (-infinity: sky)
    std::vector<ImageF> pyramid;  //!< SAO with usePyramid: levels 1..maxMip
    Region work;                  //!< the region that raw, quad and horizontal cover (buffer pixels)
    ImageF raw;                   //!< the sample pass's A
    ImageF quad;                  //!< SAO: after the 2x2 quad bilateral (packBlurInput: 8-bit A)
    ImageF zBlur;                 //!< SAO with packBlurInput: the z the blur reads (work region; else empty)
    ImageF horizontal;            //!< after the horizontal bilateral pass (releasedPacking: 8-bit A)
    ImageF result;                //!< the output: A of the inner region
};

//! Per-pass timings of one sao() run, for the speed experiments (milliseconds).
struct SaoTimings {
    double z, pyramid, sample, blur, total;
};
ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& params, const Exec& exec,
           SaoTimings* timings);
//! The same, with every intermediate copied into `stages` (not null).
ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& params, const Exec& exec,
           AoStages* stages);

}  // namespace ssfx::ao
