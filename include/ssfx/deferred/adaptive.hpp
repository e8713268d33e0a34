// Adaptive supersampling for deferred shading (Holländer, Boubekeur, Eisemann, "Adaptive
// Supersampling for Deferred Anti-Aliasing", JCGT 2(1) 2013; spec adaptive_ss.md): shade
// the first sample of each pixel's m x m G-buffer window, decide per pixel how many samples
// k it needs from depth variance, normal cone and luminance range, shade k - 1 more in
// ordered-dither order and average. Brute-force supersampling shades all m^2 samples.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/deferred/shading.hpp"

namespace ssfx::deferred {

struct AdaptiveParams {
    //! Metric constants c (paper section 3.1; scene dependent). Depth is camera-space
    //! distance in metres (background: kBackgroundDepth), so cDepth is per square metre.
    float cDepth = 16.0f;  //!< a 1 m step between half the samples gives k = 4
    float cNormal = 24.0f;
    float cShading = 64.0f;
    //! The shading metric's early exit, FXAA's medium preset (ppaa.md section 1).
    float tMin = 0.0625f;  //!< EDGE_THRESHOLD_MIN
    float tEdge = 0.166f;  //!< EDGE_THRESHOLD_MAX
    ShadingParams shading;
    //! The paper's future work: shade per 8x8 tile with the pixels grouped by sample count
    //! (same result, another order; measured by ssfx eval deferred).
    bool tiled = false;
};
//! AdaptiveParams' table (core/params.hpp); the defaults are the initialisers.
inline constexpr auto kAdaptiveParams = concat(
    std::array{
        real<&AdaptiveParams::cDepth>("cDepth", "1/m^2", 0, 1e9,
                                      "c (geometry, section 3.1): k_d = cDepth x variance of the window's camera-space "
                                      "depths (background: 1000 m)"),
        real<&AdaptiveParams::cNormal>(
            "cNormal", "", 0, 1e9,
            "c (geometry, section 3.1): k_n = cNormal sqrt(1 - min |mean n . n_ij|) over the window"),
        real<&AdaptiveParams::cShading>(
            "cShading", "", 0, 1e9,
            "c (shading, section 3.1): k_s = cShading (l_max - l_min) over the pixel and its 4 neighbours in S"),
        real<&AdaptiveParams::tMin>(
            "tMin", "luma", 0, 1,
            "t_minThreshold: the shading metric's early exit (FXAA's EDGE_THRESHOLD_MIN on the PPAA luma)"),
        real<&AdaptiveParams::tEdge>("tEdge", "ratio", 0, 1,
                                     "t_edgeThreshold: the shading metric's early exit (FXAA's EDGE_THRESHOLD_MAX)"),
        boolean<&AdaptiveParams::tiled>("tiled", "shade per 8x8 tile grouped by sample count (same result)"),
    },
    shadingRows<&AdaptiveParams::shading>());
void validate(const AdaptiveParams& p);

//! Depth that background samples count with in the depth metric: any window mixing
//! geometry and background gets every sample.
inline constexpr float kBackgroundDepth = 1000.0f;

//! The ordered-dither index matrix of size m (2, 3, 4), row-major (adaptive_ss.md).
std::vector<int> ditherMatrix(int m);
//! Window positions (x, y) of dither indices 0, 1, ..., m^2 - 1.
std::vector<std::array<int, 2>> ditherOrder(int m);

//! The metrics of one window / pixel (paper section 3.1), before rounding and clamping.
float depthMetric(const float* depths, int n, float c);        //!< c * variance
float normalMetric(const glm::vec3* normals, int n, float c);  //!< c * sqrt(1 - min |mean . n_ij|); 0 if n = 0
//! c * (lMax - lMin) over the pixel and its 4 neighbours, 0 under FXAA's threshold.
float shadingMetric(float centre, float north, float south, float west, float east, float c, float tMin, float tEdge);

struct DeferredResult {
    ImageRgbF image;
    Image<std::uint8_t> samples;                     //!< k per pixel
    ImageF kDepth, kNormal, kShading;                //!< the metrics' values (adaptive only; paper Figure 8)
    std::int64_t shaded = 0;                         //!< samples shaded (a reshaded first sample counts again)
    std::int64_t possible = 0;                       //!< width * height * m^2
    double firstMs = 0, evaluateMs = 0, restMs = 0;  //!< per phase (adaptive); restMs = all (brute force)
    double shadedPercent() const { return possible ? 100.0 * double(shaded) / double(possible) : 0.0; }
    double totalMs() const { return firstMs + evaluateMs + restMs; }
};

//! The method. Where k > 1 and the first sample is textured, it is shaded again with the
//! k-sample footprint so that k = m^2 gives exactly brute force (and counted).
DeferredResult adaptiveSupersampling(const scene::Scene& scene, const scene::GBuffer& gbuffer,
                                     const AdaptiveParams& params, const Exec& exec = {});
//! Brute force: every sample with the 1/m footprint, averaged in dither order.
DeferredResult bruteForceSupersampling(const scene::Scene& scene, const scene::GBuffer& gbuffer,
                                       const ShadingParams& params, const Exec& exec = {});

}  // namespace ssfx::deferred
