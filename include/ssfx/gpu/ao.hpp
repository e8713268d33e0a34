// Scalable Ambient Obscurance, the AlchemyAO baseline and GTAO as Vulkan compute passes (the GPU
// backend's AO family; docs/gpu.md, "Ambient obscurance"). A pipeline object is made once per
// params and device, and records its passes into the caller's command buffer, reading the
// renderer's depth image where it is (no copy):
//
//     auto ctx = vkx::Context::create();              // or the renderer's, or borrow()
//     gpu::Sao sao(ctx, ao::saoPreset("paper"));      // pipelines, tables
//     sao.record(cmd, depth, camera, output);         // in the caller's frame
//
// The passes are those of the CPU's ao::sao() and ao::alchemy() (spec sao.md), one dispatch
// each: depth -> z, the z pyramid (SAO with usePyramid: one dispatch per level), the sample
// pass, the 2x2 quad bilateral (SAO), the horizontal and the vertical bilateral pass.
//
// The contract of record():
//  - depth: a 2-D view of the depth aspect of an image of format D16_UNORM,
//    X8_D24_UNORM_PACK32, D24_UNORM_S8_UINT, D32_SFLOAT or D32_SFLOAT_S8_UINT, with SAMPLED
//    usage, in layout DEPTH_STENCIL_READ_ONLY_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL,
//    SHADER_READ_ONLY_OPTIMAL or GENERAL, the renderer's depth writes made visible to
//    compute-shader reads by the caller; its size is the whole buffer, guard band included
//    (params.guardBand on each side). Depth 1 is sky for any far plane, as on the CPU; a D32F
//    value that is NaN or outside [0, 1] (which the CPU refuses) is taken as sky.
//  - camera: the camera of the whole buffer (ssfx::Camera), as on the CPU.
//  - output: a 2-D view of format R32_SFLOAT with STORAGE usage, in layout GENERAL, of the
//    inner size (depth size minus 2 guardBand); the pipeline writes every pixel with the
//    ambient visibility A in [0, 1]; the caller's barrier after record() makes the
//    compute-shader writes visible to what reads next.
//  - the scratch images (z and its pyramid, the raw and blurred A) and the barriers between
//    the dispatches are the pipeline's; descriptors are pushed (VK_KHR_push_descriptor).
//    The scratch images are shared between recordings: do not let two recordings of one
//    pipeline run at the same time (one pipeline per frame in flight).
//
// Parity with the CPU (docs/gpu.md gives the measured figures): every step but the sample
// pass's sine and cosine is the CPU's float arithmetic, correctly rounded, and depth -> z is
// the CPU's double rounded once, in float pairs (one ulp off in rare pixels); the final A is
// within the bound that tests/gpu/test_gpu_ao.cpp states (on lavapipe: the CPU's floats).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ssfx/ao/registry.hpp"
#include "ssfx/core/camera.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/gpu/aa.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx::gpu {

//! Every intermediate of one run, read back (the CPU's struct: ao::AoStages).
using ao::AoStages;

//! One dispatch group of the last run(): its stage and GPU time (timestamps around it).
struct AoDispatchTime {
    std::string stage;  //!< z, pyramid (all levels), sample, quad, blur h, blur v
    double milliseconds = 0;
};

class AoPipeline;

//! An AO method's GPU pipeline on one device (the shared part of Sao and Alchemy).
class AoPass {
public:
    //! By the AO registry's id ("sao" or "alchemy"; ao::aoMethods()) and its params struct.
    //! Throws ssfx::Error for a method without a GPU pipeline (raytraced), a bad parameter
    //! (ao::validate) or a device without push descriptors.
    AoPass(std::shared_ptr<vkx::Context> ctx, std::string_view method, const ao::AoParams& params);
    ~AoPass();
    AoPass(const AoPass&) = delete;
    AoPass& operator=(const AoPass&) = delete;

    //! Records the passes (see the contract above). Throws ssfx::Error when an image has the
    //! wrong format, usage, layout or size, or exceeds the device's limits.
    void record(const vk::raii::CommandBuffer& cmd, const ImageRef& depth, const Camera& camera,
                const ImageRef& output);
    //! Convenience: uploads `depth` into an image of `format` (values rounded to the format as
    //! ssfx::quantizeDepth does), runs, waits and returns A for the inner region. Throws
    //! ssfx::Error naming the first depth that is NaN or outside [0, 1], as the CPU does.
    ImageF run(ImageView<const float> depth, const Camera& camera, DepthFormat format = DepthFormat::D32F);
    //! The same, with every intermediate read back.
    AoStages runStages(ImageView<const float> depth, const Camera& camera, DepthFormat format = DepthFormat::D32F);
    //! GPU time of the last run() in milliseconds (0 when the queue has no timestamps), and
    //! per stage. record() into a caller's command buffer writes no timestamps.
    double lastMilliseconds() const;
    const std::vector<AoDispatchTime>& lastDispatches() const;

private:
    std::unique_ptr<AoPipeline> impl_;
};

//! SAO (ao::sao()) on one device.
class Sao : public AoPass {
public:
    Sao(std::shared_ptr<vkx::Context> ctx, const ao::SaoParams& params = {})
        : AoPass(std::move(ctx), "sao", params), params_(params) {}
    const ao::SaoParams& params() const { return params_; }

private:
    ao::SaoParams params_;
};

//! The AlchemyAO baseline (ao::alchemy()) on one device.
class Alchemy : public AoPass {
public:
    Alchemy(std::shared_ptr<vkx::Context> ctx, const ao::AlchemyParams& params = {})
        : AoPass(std::move(ctx), "alchemy", params), params_(params) {}
    const ao::AlchemyParams& params() const { return params_; }

private:
    ao::AlchemyParams params_;
};

//! Ground-Truth AO (ao::gtao(), spec gtao.md) on one device: depth -> z, the depth chain
//! (one dispatch per level), the edges and normals from depth, the main pass, the denoiser's
//! passes (one dispatch each; with denoisePasses 0 one that clamps A into the output). The
//! normals are always reconstructed from depth (the CPU's AoInput::normals and bent normals
//! are CPU-only). Stages (runStages): z, the chain's levels 1-4 as z (= -t) in `pyramid`,
//! the main pass's A in `raw`, the result.
class Gtao : public AoPass {
public:
    Gtao(std::shared_ptr<vkx::Context> ctx, const ao::GtaoParams& params = {})
        : AoPass(std::move(ctx), "gtao", params), params_(params) {}
    const ao::GtaoParams& params() const { return params_; }

private:
    ao::GtaoParams params_;
};

//! The AO registry's methods that have a GPU pipeline: sao, alchemy, gtao.
bool hasGpuAo(std::string_view method);

//! The Vulkan format of a depth format's images (D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT).
vk::Format depthVkFormat(DepthFormat format);

}  // namespace ssfx::gpu
