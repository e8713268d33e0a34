// GTAO's tables buffer (spec gtao.md; gpu::Gtao in src/gpu/ao_pass.cpp fills it from
// GtaoParams as the CPU's GtaoSetup does), compiled by both C++ and GLSL (gtao.glsl). Every
// member is a 4-byte scalar (std430: member i at byte 4 i, static_asserts in ao_pass.cpp);
// the noise table follows them. The passes' push constants are the AO family's AoConstants
// (ao_constants.h): the main pass reads rNum (r = rNum / t px, which depends on the buffer's
// width) from `radiusS`, the denoiser its mode from `levels`.
#ifndef SSFX_GPU_GTAO_CONSTANTS_H
#define SSFX_GPU_GTAO_CONSTANTS_H

#define SSFX_GTAO_PARAMS(X)                                                               \
    X(float, re)           /* Re = R radiusMultiplier */                                  \
    X(float, rp)           /* the prefilter's 0.75 Re */                                  \
    X(float, fRp)          /* f 0.75 Re */                                                \
    X(float, fRe)          /* f Re: w(x) = clamp((Re - x) / (f Re), 0, 1) */              \
    X(float, spacingPower) /* sampleDistributionPower */                                  \
    X(float, finalPower)   /* finalValuePower */                                          \
    X(float, mipOffset)    /* depthMipSamplingOffset */                                   \
    X(float, toc1)         /* 1 + thinOccluderCompensation */                             \
    X(float, thickness)    /* the paper's heuristic (0: off) */                           \
    X(float, betaMiddle)   /* the denoiser's centre weight: 1.2 / 5, the last pass 1.2 */ \
    X(float, betaLast)                                                                    \
    X(int, slices)                                                                        \
    X(int, steps)                                                                         \
    X(int, guard)                                                                         \
    X(int, lift) /* booleans as 0 / 1 */                                                  \
    X(int, nearFade)                                                                      \
    X(int, fastAcos)                                                                      \
    X(int, offscreenDiscard) /* offscreen=discard */                                      \
    X(int, minusOne)         /* horizonStart=minusOne */                                  \
    X(int, xegtaoStorage)

// (xs, xt) of (x mod 64, y mod 64) at 2 (64 y + x): the CPU's gtaoNoise(x, y), frame 0.
#define SSFX_GTAO_NOISE 8192

#define SSFX_GTAO_MEMBER(type, name) type name;
#ifdef __cplusplus
namespace ssfx::gpu::detail {
struct GtaoTables {
    SSFX_GTAO_PARAMS(SSFX_GTAO_MEMBER)
    float noise[SSFX_GTAO_NOISE];
};
}  // namespace ssfx::gpu::detail
#else
#define SSFX_GTAO_TABLES_BLOCK SSFX_GTAO_PARAMS(SSFX_GTAO_MEMBER) float noise[SSFX_GTAO_NOISE];
#endif

#endif
