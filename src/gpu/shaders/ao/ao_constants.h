// The push constants and specialization constants of the ambient-obscurance compute passes,
// compiled by both C++ (src/gpu/ao_pass.cpp fills them from SaoParams / AlchemyParams:
// gpu::detail::aoConstants) and GLSL (ao.glsl). Every member is a 4-byte scalar, so the
// std430 push-constant layout is the C++ layout, member i at byte 4 i (static_asserts in
// ao_pass.cpp), as for the anti-aliasing passes' aa_constants.h.
#ifndef SSFX_GPU_AO_CONSTANTS_H
#define SSFX_GPU_AO_CONSTANTS_H

// Work-group size of every AO pass: 8 x 8 invocations.
#define SSFX_AO_GROUP 8

// X(type, name): the push constants in order, what changes with the call (sizes, regions,
// the camera); what changes only with the params is in the tables buffer (below).
#define SSFX_AO_CONSTANTS(X)                                                                   \
    X(int, width) /* the z buffer (guard band included) */                                     \
    X(int, height)                                                                             \
    X(int, regionX) /* the region the dispatch computes, in buffer pixels */                   \
    X(int, regionY)                                                                            \
    X(int, regionW)                                                                            \
    X(int, regionH)                                                                            \
    X(int, srcX) /* bilateral: the source region (its taps' range), buffer pixels; pyramid: */ \
    X(int, srcY) /* srcW x srcH is the finer level's size */                                   \
    X(int, srcW)                                                                               \
    X(int, srcH)                                                                               \
    X(int, levels)  /* sample pass: pyramid levels above 0 that taps may read */               \
    X(float, zNear) /* depth -> z: the camera's planes (negative, m) as float pairs hi + lo */ \
    X(float, zNearLo)                                                                          \
    X(float, zFar) /* -infinity for an infinite far plane (zFarLo 0) */                        \
    X(float, zFarLo)                                                                           \
    X(float, zNearFar) /* zNear zFar, its double rounded, as hi + lo */                        \
    X(float, zNearFarLo)                                                                       \
    X(float, ax) /* position factors fx(x) = ax + bx x, fy(y) = ay + by y (ao_sampling.hpp) */ \
    X(float, bx)                                                                               \
    X(float, ay)                                                                               \
    X(float, by)                                                                               \
    X(float, radiusS) /* -radius * pixelsPerMeter: ssRadius = radiusS / z (eq. 5); GTAO: rNum */

// X(type, name): the scalars at the start of the tables buffer, in order.
#define SSFX_AO_PARAMS(X)                                                  \
    X(float, r2)   /* SAO: r^2 */                                          \
    X(float, bias) /* SAO: beta (m); AlchemyAO: beta per metre of depth */ \
    X(float, epsilon)                                                      \
    X(float, scale) /* A = max(0, 1 - (sum scale) scale2)^exponent */      \
    X(float, scale2)                                                       \
    X(float, exponent)                                                     \
    X(float, quadThreshold)                                                \
    X(float, edgeSharpness) /* bilateral */                                \
    X(float, blurEpsilon)                                                  \
    X(float, packZMin)                                                     \
    X(int, numSamples)                                                     \
    X(int, logQ)                                                           \
    X(int, taps) /* bilateral taps */                                      \
    X(int, blurStride)

// The specialization constants, each a 32-bit int; GLSL sees them as spec_<name>.
#define SSFX_AO_SPECIALIZATION(X)                                                                   \
    X(0, filter, 0)      /* z pyramid: PyramidFilter's order (rotated grid, mean, harmonic, ...) */ \
    X(1, estimator, 0)   /* sample pass: 0 SAO's updated falloff, 1 AlchemyAO (eq. 1) */            \
    X(2, spinInFloat, 0) /* sample pass: the released tapLocation() */                              \
    X(3, horizontal, 1)  /* bilateral: 1 horizontal, 0 vertical */                                  \
    X(4, zeroOutside, 0) /* bilateral: taps beyond the source region weigh 0 */                     \
    X(5, packing, 0)     /* quad pass: 0 none, 1 packBlurInput, 2 releasedPacking */                \
    X(6, packOutput, 0)  /* bilateral: store A in 8 bits (the released horizontal pass) */

#define SSFX_AO_MEMBER(type, name) type name;

// The tables buffer: the SSFX_AO_PARAMS scalars; then per tap k < SSFX_AO_MAX_TAPS its
// alpha_k, its unit spiral direction (x, y) and, with spinInFloat, its float angle alpha_k
// float(tau turnAngle) (the CPU's floats); then the bilateral's taps in summation order:
// their offsets t (as floats) and spatial weights.
#define SSFX_AO_MAX_TAPS 64
#define SSFX_AO_MAX_BLUR_TAPS 17

#ifdef __cplusplus
#include <cstdint>
namespace ssfx::gpu::detail {
struct AoConstants {
    SSFX_AO_CONSTANTS(SSFX_AO_MEMBER)
};
#define SSFX_AO_SPEC_MEMBER(id, name, value) std::int32_t name = value;
struct AoSpecialization {
    SSFX_AO_SPECIALIZATION(SSFX_AO_SPEC_MEMBER)
};
#undef SSFX_AO_SPEC_MEMBER
struct AoTables {
    SSFX_AO_PARAMS(SSFX_AO_MEMBER)
    float alpha[SSFX_AO_MAX_TAPS], dirX[SSFX_AO_MAX_TAPS], dirY[SSFX_AO_MAX_TAPS], tapAngle[SSFX_AO_MAX_TAPS];
    float blurOffset[SSFX_AO_MAX_BLUR_TAPS], blurWeight[SSFX_AO_MAX_BLUR_TAPS];
};
}  // namespace ssfx::gpu::detail
#else
struct AoConstants {
    SSFX_AO_CONSTANTS(SSFX_AO_MEMBER)
};
#define SSFX_AO_TABLES_BLOCK                                                                                   \
    SSFX_AO_PARAMS(SSFX_AO_MEMBER)                                                                             \
    float alpha[SSFX_AO_MAX_TAPS], dirX[SSFX_AO_MAX_TAPS], dirY[SSFX_AO_MAX_TAPS], tapAngle[SSFX_AO_MAX_TAPS]; \
    float blurOffset[SSFX_AO_MAX_BLUR_TAPS], blurWeight[SSFX_AO_MAX_BLUR_TAPS];
#define SSFX_AO_SPEC_DECL(id, name, value) layout(constant_id = id) const int spec_##name = value;
SSFX_AO_SPECIALIZATION(SSFX_AO_SPEC_DECL)
#undef SSFX_AO_SPEC_DECL
#endif

#endif
