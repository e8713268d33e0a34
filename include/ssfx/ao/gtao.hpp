// Ground-Truth Ambient Occlusion (Jimenez, Wu, Pesce, Jarabo, "Practical Realtime Strategies
// for Accurate Indirect Occlusion", SIGGRAPH 2016 course; spec gtao.md), with the details of
// Intel's XeGTAO that the spec fixes, on the CPU.
//
// Pipeline (spec gtao.md sections 4-9): depth -> t = -z (sao.md pass 1) -> a 5-level depth
// chain that favours the farthest sample of each 2x2 block (section 4) -> the main pass: per
// pixel, edges to its four neighbours, a normal (from depth, section 6, or a G-buffer), then S
// slices, each a screen direction whose two horizons are found with J steps per side through
// the chain; the slice's visibility is the cosine-weighted integral between the horizons
// (section 2) -> an edge-aware 3x3 denoiser (section 8). Optionally a bent normal (section 9).
// Output: visibility A in [0, 1] of the inner region (1 = unoccluded, sky 1), float32.
//
// Same inputs as SAO (sao.md conventions): hardware depth in [0, 1] with a guard band, the
// camera of the whole buffer, d = 1 is sky. Float32 arithmetic throughout, as a shader does;
// rows in parallel (oneTBB), the same bytes for any thread count. The main pass runs as
// Highway lanes (src/ao/gtao-inl.h: Highway's cos, sin, acos, log2, exp, log instead of
// libm's) except with bent normals or a sampleDistributionPower other than 2;
// gtaoReference() is the scalar loop on one thread, the oracle the lanes are held to
// (tests/ao/test_gtao.cpp states the bound; docs/methods/gtao.md gives it and the speed).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"

namespace ssfx::ao {

//! What a sample beyond the buffer's edge reads (spec section 10).
enum class Offscreen {
    Clamp,    //!< the edge texel's t at the sample's own off-screen position (XeGTAO's sampler)
    Discard,  //!< the sample weighs 0 (ours)
};
inline constexpr std::array<std::string_view, 2> kOffscreenNames{"clamp", "discard"};

//! Where a slice's horizon cosines start (spec sections 5.6 and 11).
enum class HorizonStart {
    Hemisphere,  //!< on the normal's hemisphere: cos(gamma +- pi/2) (XeGTAO)
    MinusOne,    //!< at -1, far samples lerped towards -1, then clamped to the hemisphere (the paper)
};
inline constexpr std::array<std::string_view, 2> kHorizonStartNames{"hemisphere", "minus-one"};

//! XeGTAO's GTAOSettings (spec section 3) and the options the spec names. Defaults: XeGTAO's
//! High preset.
struct GtaoParams {
    float radius = 0.5f;                    //!< R, m: the near-field radius (the ray-traced truth's ray length)
    float radiusMultiplier = 1.457f;        //!< the estimator uses Re = R radiusMultiplier (XeGTAO's auto-tune)
    float falloffRange = 0.615f;            //!< f: the outer fraction of Re over which samples fade
    float sampleDistributionPower = 2.0f;   //!< step spacing exponent: u = ((j + noise) / J)^power
    float thinOccluderCompensation = 0.0f;  //!< stretches dz in the falloff distance
    float finalValuePower = 2.2f;           //!< A <- A^power (auto-tuned, no physical basis)
    float depthMipSamplingOffset = 3.30f;   //!< lod = log2(|offset| px) - this (XeGTAO's code: 3.30)
    int sliceCount = 3;                     //!< S
    int stepsPerSlice = 3;                  //!< J, per side (samples per pixel: 2 S J)
    int denoisePasses = 1;                  //!< 0 off, 1 sharp, 2 medium, 3 soft
    bool projectedNormalLift = true;        //!< l' = 0.95 l + 0.05 (XeGTAO's slope fix); off: l' = l
    bool nearFade = true;                   //!< the v0 = 0.5 clamp((10 - r) / 100, 0, 1) term for small radii
    bool fastAcos = false;                  //!< XeGTAO's approximation of acos instead of the exact one
    Offscreen offscreen = Offscreen::Clamp;
    bool xegtaoStorage = false;  //!< A / 1.5 in 8 bits between passes (XeGTAO's R8 buffers)
    HorizonStart horizonStart = HorizonStart::Hemisphere;
    //! The paper's thickness heuristic (section 11): a sample below the current horizon moves it
    //! by thickness (c_sample - c) instead of being ignored; 0: off (XeGTAO).
    float thickness = 0.0f;
    int guardBand = 0;  //!< px on each side of the depth buffer not output
};

//! GtaoParams' table (core/params.hpp): ranges and docs; the defaults are the initialisers.
inline constexpr auto kGtaoParams = std::array{
    real<&GtaoParams::radius>("radius", "m", 1e-6, 100, "R: near-field radius (the ray-traced truth's ray length)"),
    real<&GtaoParams::radiusMultiplier>("radiusMultiplier", "", 0.3, 3, "the estimator's radius Re = R x this"),
    real<&GtaoParams::falloffRange>("falloffRange", "", 1e-3, 1, "f: outer fraction of Re over which samples fade"),
    real<&GtaoParams::sampleDistributionPower>("sampleDistributionPower", "", 1, 3,
                                               "step spacing exponent ((j + noise) / J)^power"),
    real<&GtaoParams::thinOccluderCompensation>("thinOccluderCompensation", "", 0, 0.7,
                                                "stretches dz in the falloff distance"),
    real<&GtaoParams::finalValuePower>("finalValuePower", "", 0.5, 5, "A <- A^power"),
    real<&GtaoParams::depthMipSamplingOffset>("depthMipSamplingOffset", "", 0, 30,
                                              "depth chain level = log2(step length in px) - this"),
    integer<&GtaoParams::sliceCount>("sliceCount", "", 1, 64, "S: slices (screen directions) per pixel"),
    integer<&GtaoParams::stepsPerSlice>("stepsPerSlice", "", 1, 64, "J: steps per side of a slice"),
    integer<&GtaoParams::denoisePasses>("denoisePasses", "", 0, 3, "3x3 edge-aware passes: 0 off, 1 sharp, 3 soft"),
    boolean<&GtaoParams::projectedNormalLift>("projectedNormalLift",
                                              "l' = 0.95 l + 0.05 (XeGTAO's fix for over-darkening on slopes)"),
    boolean<&GtaoParams::nearFade>("nearFade", "add 0.5 clamp((10 - r px) / 100, 0, 1) for small radii"),
    boolean<&GtaoParams::fastAcos>("fastAcos", "XeGTAO's acos approximation instead of the exact acos"),
    choice<&GtaoParams::offscreen>("offscreen", kOffscreenNames,
                                   "samples beyond the buffer: clamp (edge texel) or discard (weight 0)"),
    boolean<&GtaoParams::xegtaoStorage>("xegtaoStorage", "A / 1.5 in 8 bits between passes (XeGTAO's R8)"),
    choice<&GtaoParams::horizonStart>("horizonStart", kHorizonStartNames,
                                      "horizon cosines start on the hemisphere (XeGTAO) or at -1 (the paper)"),
    real<&GtaoParams::thickness>("thickness", "", 0, 1,
                                 "the paper's thickness heuristic: a lower sample moves the horizon by this "
                                 "fraction (0: off)"),
    integer<&GtaoParams::guardBand>("guardBand", "px", 0, 4096, "guard band on each side, not output"),
};

//! Named configurations (spec section 3 and 11; samples per pixel 2 S J):
//!   "low" 1 x 2, "medium" 2 x 2, "high" 3 x 3 (the defaults), "ultra" 9 x 3: XeGTAO's presets;
//!   "ideal": High's samples with the spec's "ideal" settings (section 12): radiusMultiplier 1,
//!     finalValuePower 1, falloffRange 0.02 (ours: "small f"), projectedNormalLift and nearFade off:
//!     the estimator of the definition, not the auto-tuned look;
//!   "paper": the course's pipeline as far as a full-resolution pass goes (section 11): one slice,
//!     6 steps per side, horizonStart minus-one, thickness 0.1 (ours: the paper gives no value),
//!     radiusMultiplier 1, finalValuePower 1, projectedNormalLift and nearFade off. Ours: full
//!     resolution, the spec's noise and denoiser (the paper: half resolution, a 4x4 noise, temporal
//!     accumulation).
//! Throws ssfx::Error listing the names for an unknown one.
GtaoParams gtaoPreset(const std::string& name);
inline constexpr std::array<std::string_view, 6> kGtaoPresets{"low", "medium", "high", "ultra", "ideal", "paper"};

//! Throws ssfx::Error naming the first out-of-range field.
void validate(const GtaoParams& p);
void setParam(GtaoParams& p, const std::string& name, double value);

//! The 6-level Hilbert index of (x mod 64, y mod 64) (spec section 7; XeGTAO's HilbertIndex).
int hilbertIndex(int x, int y);
//! The per-pixel noise (xs, xt) = frac(0.5 + i (0.75487766624669276, 0.56984029099805327)) in
//! float, i = H(x mod 64, y mod 64) + 288 (frame mod 64): the R2 sequence along the Hilbert curve.
//! x and y count from the output's origin (the buffer's less the guard band).
std::array<float, 2> gtaoNoise(int x, int y, int frame = 0);

//! XeGTAO's acos approximation (spec section 5): (pi/2 - 0.156583 |x|) sqrt(1 - |x|) with its
//! bit-trick square root, pi - that for x < 0.
float fastAcos(float x);

//! Optional inputs and outputs of gtao().
struct GtaoBuffers {
    //! Camera-space normals of the whole buffer (the depth's size), e.g. a G-buffer's; empty:
    //! from depth (section 6). Non-finite or zero normals are replaced by the view vector.
    ImageView<const Vec3> normals;
    //! If not null: the bent normal of each output pixel (unit, camera space; section 9),
    //! denoised with A's weights; sky: the view vector.
    Image<Vec3>* bentNormals = nullptr;
};

//! Every intermediate of one run (`ssfx ao -m gtao --save-passes`, the GPU pass's parity tests).
//! The main pass runs on `work`: the output region grown by the denoiser's reach (one pixel
//! per pass), clamped to the buffer; the passes' values elsewhere cannot reach the output.
struct GtaoStages {
    std::vector<ImageF> chain;  //!< the depth chain t, levels 0..4 of the whole buffer (+infinity: sky)
    Region work;                //!< the region that edges, normals and raw cover (buffer pixels)
    ImageF edges;               //!< quantised edges: L + 4 R + 16 T + 64 B of the steps 0..3 (e = step / 3)
    Image<Vec3> normals;        //!< the normals the main pass used ((0, 0, 0): none, the view vector used)
    ImageF raw;                 //!< the main pass's A
    ImageF result;              //!< the output: A of the inner region
};

//! The whole pipeline: `depth` (hardware depth in [0, 1], guard band included), the camera
//! of the whole buffer. Returns A for the inner region (size minus 2 guardBand). Throws
//! ssfx::Error for a bad parameter, a depth outside [0, 1] or NaN, or normals of another size.
ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params = {}, const Exec& exec = {},
            const GtaoBuffers& buffers = {});
//! The same, with every intermediate copied into `stages` (not null).
ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params, const Exec& exec,
            const GtaoBuffers& buffers, GtaoStages* stages);

//! The scalar oracle: the same pipeline on one thread, the main pass as the scalar loop.
ImageF gtaoReference(ImageView<const float> depth, const Camera& camera, const GtaoParams& params = {},
                     const GtaoBuffers& buffers = {});

//! The constants GTAO's passes derive from the params and the projection, as floats (the CPU's
//! passes and the GPU's read the same): Re = R radiusMultiplier, the prefilter's rp = 0.75 Re
//! and f rp, f Re, and rNum = Re (W P00 / 2) with r = rNum / t pixels (XeGTAO's footprint).
struct GtaoConstants {
    float re, rp, fRp, fRe, rNum;
};
GtaoConstants gtaoConstants(const GtaoParams& params, const Projection& proj);
//! `out` grown by `by` pixels on each side, within the width x height buffer: the main pass's
//! work region (by = denoisePasses) and each denoiser pass's region (CPU and GPU).
Region gtaoGrown(Region out, int width, int height, int by);

//! Per-pass timings of one gtao() run, for the speed experiments (milliseconds).
struct GtaoTimings {
    double z, chain, main, denoise, total;  //!< main: the edges, the normals and the main pass
};
ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params, const Exec& exec,
            GtaoTimings* timings);

}  // namespace ssfx::ao
