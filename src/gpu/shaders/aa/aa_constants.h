// The push constants of every anti-aliasing compute pass, compiled by both C++
// (src/gpu/aa_pass.cpp, which fills them from the CPU params structs: gpu::aaConstants) and
// GLSL (ppaa.glsl). Every member is a 4-byte scalar, so the std430 push-constant layout is
// the C++ layout: member i at byte offset 4 i. The C++ side checks this with static_asserts
// (SSFX_GPU_CHECK_LAYOUT); GLSL has no offsetof, so the member list is the one macro both use.
#ifndef SSFX_GPU_AA_CONSTANTS_H
#define SSFX_GPU_AA_CONSTANTS_H

// Work-group size of the per-pixel passes: 16 x 16 pixels (its tile: 18 x 18 texels, ppaa.glsl).
#define SSFX_AA_GROUP 16

// X(type, name): the members in order.
#define SSFX_AA_CONSTANTS(X)                                                               \
    X(int, width) /* input size in pixels */                                               \
    X(int, height)                                                                         \
    X(int, outWidth) /* output size (the input's for same-size passes) */                  \
    X(int, outHeight)                                                                      \
    X(float, fw) /* float(width), float(height) */                                         \
    X(float, fh)                                                                           \
    X(float, invW) /* 1 / width, 1 / height rounded to float32 once (spec section 1) */    \
    X(float, invH)                                                                         \
    X(float, edgeThresholdMin) /* early exit (spec section 1) */                           \
    X(float, edgeThreshold)                                                                \
    X(float, chromaWeight) /* colour-aware contrast; 0 = the paper's luma */               \
    X(float, blurW1)       /* blur: direct-neighbour and corner weights, 1 / weight sum */ \
    X(float, blurW2)                                                                       \
    X(float, blurNorm)                                                                     \
    X(float, edgeSharpness) /* fxaa3c */                                                   \
    X(float, diagonalU)     /* fxaa3c: diagonalOffset / W, / H */                          \
    X(float, diagonalV)                                                                    \
    X(float, subpix) /* fxaa3d */                                                          \
    X(int, paperSearchQuirk)                                                               \
    X(float, strength) /* ddaa1, ddaa2 */                                                  \
    X(float, maxDiffusion)                                                                 \
    X(float, ridgeFactor)                                                                  \
    X(int, searchRounds)  /* ddaa2 */                                                      \
    X(int, edgeGroupsMin) /* edge pass: at least this many groups (a loop budget; aa_pass.cpp) */

// The specialization constants, fixed when a pass's pipeline is made: X(constant_id, name,
// default), each a 32-bit int. The choices that select code live here, not in the push
// constants: the device compiles only the branch taken, where a branch on a push constant
// costs both sides on drivers that run shaders as masked SIMD code (lavapipe runs every side
// of every branch). GLSL sees them as spec_<name>.
#define SSFX_AA_SPECIALIZATION(X)                                                                         \
    X(0, sampling, 0)           /* 0: the GPU sampling model (exact); 1: the device's sampler */          \
    X(1, chroma, 0)             /* 1: chromaWeight != 0 (edgeLuma adds the chroma term) */                \
    X(2, diagonalsAtCentres, 0) /* fxaa3c: diagonalOffset == 1 (reads at pixel centres) */                \
    X(3, stage, 0)              /* edge-list methods: SSFX_AA_STAGE_LUMA, _CLASSIFY or _EDGES; else 0 */  \
    X(4, groupX, SSFX_AA_GROUP) /* work-group size: SSFX_AA_GROUP^2, or SSFX_AA_EDGE_GROUP x 1 */         \
    X(5, groupY, SSFX_AA_GROUP)                                                                           \
    X(6, edgeGroups, SSFX_AA_EDGE_MAX_GROUPS) /* edge pass: at most this many groups (aa_pass.cpp) */     \
    X(7, pairReads, 0)        /* ddaa2's edge pass, model: search reads by texel index (aa_pass.cpp) */   \
    X(8, batchedSearch, 0)    /* ddaa2: a round's reads issued before they are tested (aa_pass.cpp) */    \
    X(9, deviceDecode, 0)     /* model: the device's decode of the input format is exact (aa_pass.cpp) */ \
    X(10, srgb, 0)            /* texture=srgb: an sRGB view, decoded, filtered in linear, encoded back */ \
    X(11, srgbDecodeTable, 0) /* texture=srgb, model: levels from the device's decode by a table */       \
    X(12, sideSearch, 0)      /* fxaa3d's walk, ddaa2's search: one side a step (aa_pass.cpp) */

// The three dispatches of the methods with an edge test (fxaa3c, fxaa3d, ddaa1, ddaa2;
// edge_list.glsl): the first writes the luma plane and copies every pixel to the output; the
// second tests every pixel and appends the edge pixels to a list; the third, an indirect
// dispatch over the list, computes the edge pixels over their copies.
#define SSFX_AA_STAGE_CLASSIFY 1
#define SSFX_AA_STAGE_EDGES 2
#define SSFX_AA_STAGE_LUMA 3  // before CLASSIFY: the luma plane (SSFX_AA_BINDING_LUMA)
// The edge methods in one dispatch over row segments (gpu::EdgePath::Segments, CPU devices;
// edge_list.glsl, compiled with SSFX_AA_SEGMENTS_MODULE as modules of their own): one
// invocation per SSFX_AA_SEGMENT pixels of a row, its subgroup's edge pixels spread over its
// lanes.
#define SSFX_AA_SEGMENT 8
#define SSFX_AA_EDGE_GROUP 64  // edge pass: invocations per work group (1-D)
// Edge pass: at most this many groups (Vulkan's minimum maxComputeWorkGroupCount); each
// group loops over a contiguous run of the list (edge_list.glsl). The specialization constant
// edgeGroups lowers it on CPU devices (aa_pass.cpp: kCpuEdgeGroups).
#define SSFX_AA_EDGE_MAX_GROUPS 65535

#define SSFX_AA_MEMBER(type, name) type name;

#ifdef __cplusplus
#include <cstdint>
namespace ssfx::gpu::detail {
struct AaConstants {
    SSFX_AA_CONSTANTS(SSFX_AA_MEMBER)
};
#define SSFX_AA_SPEC_MEMBER(id, name, value) std::int32_t name = value;
struct AaSpecialization {
    SSFX_AA_SPECIALIZATION(SSFX_AA_SPEC_MEMBER)
};
#undef SSFX_AA_SPEC_MEMBER
}  // namespace ssfx::gpu::detail
#else
struct AaConstants {
    SSFX_AA_CONSTANTS(SSFX_AA_MEMBER)
};
#define SSFX_AA_SPEC_DECL(id, name, value) layout(constant_id = id) const int spec_##name = value;
SSFX_AA_SPECIALIZATION(SSFX_AA_SPEC_DECL)
#undef SSFX_AA_SPEC_DECL
#endif

// Binding numbers of descriptor set 0, shared by every pass.
#define SSFX_AA_BINDING_INPUT 0   // combined image sampler: the input (linear, clamp to edge)
#define SSFX_AA_BINDING_OUTPUT 1  // storage image rgba8: the output
#define SSFX_AA_BINDING_TABLES 2  // storage buffer: the tables below
#define SSFX_AA_BINDING_EDGES 3   // storage buffer: the edge list (the two-pass methods)
#define SSFX_AA_BINDING_LUMA 4    // storage image rgba32f: the luma plane (the two-pass methods)

// The luma plane packs this many horizontally adjacent lumas per texel (ppaa.glsl); the luma
// and classify dispatches run one invocation per texel.
#define SSFX_AA_LUMA_PACK 4

// The tables buffer (floats): the 16 Mitchell weights of the x4 resolve per axis (read at
// indices that are the same for every invocation; the model's levels k / 4080 are computed,
// exact.glsl's levelOver4080, as a per-pixel table lookup is slow on SIMD CPU drivers).
#define SSFX_AA_MITCHELL4_COUNT 16
// Then texture=srgb's tables: the 256 decoded levels (the CPU's kSrgb8), and encodeSrgb8's
// packed table (ssfx::detail::SrgbEncodeTable::packed), as int bits: per bucket of the floats
// in [2^-14, 1) (by exponent and top 8 mantissa bits) its first level << 16 | the offset of
// its threshold in the bucket (1 << 15 where it holds none); then, for the model where the
// pass built it (aa_pass.cpp: srgbDecodeTable), the same buckets of the device's decoded
// values holding the levels they decode (zeros otherwise).
#define SSFX_AA_SRGB_LEVELS 256
#define SSFX_AA_SRGB_BUCKETS 3584
#define SSFX_AA_SRGB_LOW_BITS 0x38800000u
#define SSFX_AA_SRGB_SHIFT 15
#define SSFX_AA_SRGB_OFFSET_MASK 0x7FFFu

#endif
