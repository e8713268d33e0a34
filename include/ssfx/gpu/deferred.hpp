// Adaptive supersampling for deferred shading as Vulkan compute passes (the GPU backend's
// deferred family; docs/gpu.md, "Adaptive shading"): the CPU's deferred::adaptiveSupersampling
// and deferred::bruteForceSupersampling (spec adaptive_ss.md) on a G-buffer in GPU memory.
//
//     auto ctx = vkx::Context::create();
//     gpu::AdaptiveShading shading(ctx, scene);            // materials, texture array
//     auto r = shading.adaptive(gbuffer, params);          // upload, run, read back
//     shading.record(cmd, deviceGBuffer, params, output);  // or in the caller's frame
//
// Passes (one dispatch each, 8 x 8 pixels per work group): first (S, the sample of dither
// index 0 of every window with the whole pixel's footprint, and its luma), evaluate (k from
// the depth variance, the normal cone and S's luminance range), rest (k - 1 more samples in
// dither order, averaged with the first). Brute force is one dispatch of every sample.
// The rest pass has three schedules (gpu::Schedule): per pixel, tiled (the tile's pixels
// ranked by k, so that the lanes of a subgroup hold similar k: the paper's future work), or
// a sample list (one sample per invocation, an indirect dispatch, a resolve); all give the
// same image, and the pass counts the share of its lanes that idle.
//
// Texture lookups (gpu::Sampling): `model` runs the CPU's sampler model (deferred/sampler.hpp:
// bilinear on the texels' bytes, its probes and level of detail) in the shader; `hardware`
// uses the device's sampler (textureGrad, linear, repeat, anisotropy up to the params'
// maxAnisotropy where the device has anisotropic filtering). The shading arithmetic is the
// device's either way: the image is the CPU's within the bounds docs/gpu.md states, and k is
// the CPU's but at float ties (a metric within float error of a rounding boundary or of
// FXAA's threshold).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/gpu/aa.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/gbuffer.hpp"
#include "ssfx/scene/scene.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx::gpu {

//! A G-buffer while it is on the device (what record() reads): sampled 2-D views in layout
//! SHADER_READ_ONLY_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL (depth) or GENERAL, their writes made
//! visible to compute-shader reads by the caller, each (m width) x (m height).
struct DeviceGBuffer {
    ImageRef depth;                    //!< D32_SFLOAT (the renderer's, its depth aspect) or R32_SFLOAT
    ImageRef normal;                   //!< R16G16B16A16_SNORM (the renderer's) or R32G32B32A32_SFLOAT; camera space
    ImageRef uv;                       //!< R32G32_SFLOAT
    ImageRef uvGrad;                   //!< R32G32B32A32_SFLOAT: du/dx, dv/dx, du/dy, dv/dy per final pixel
    ImageRef ids;                      //!< R16G16_UINT: material, texture layer (0xFFFF: background, none)
    int width = 0, height = 0, m = 1;  //!< the final image and the samples per pixel's side
    Camera camera;                     //!< of the (m width) x (m height) sample grid
    glm::dmat4 view{1.0};              //!< world -> camera (for the lights)
    //! Optional (no view: none): R32_SFLOAT, width x height, values in [0, 1], multiplying the
    //! ambient term of each of a pixel's samples (scene::GBuffer::ambientOcclusion).
    ImageRef ambientOcclusion;
};

//! The renderer's G-buffer left on the device (render::Renderer::renderGBufferOnDevice) as
//! the passes' input: the attachments' views, formats and layouts, the size, m, the camera.
DeviceGBuffer deviceGBuffer(const render::DeviceGBufferImages& images);
//! One of the renderer's images on the device as the passes take it (ImageRef).
ImageRef imageRef(const render::DeviceImage& image);

//! What one run gives: the CPU's DeferredResult (firstMs, evaluateMs and restMs are the
//! passes' GPU times from timestamps, 0 where the queue has none) and the lane counts.
struct GpuDeferredResult : deferred::DeferredResult {
    //! The rest pass's (brute force's) lane-iterations: shaded samples, and issued (per
    //! subgroup: its lanes times its busiest lane's samples). idleLaneShare = 1 - busy / issued.
    std::uint64_t busyLanes = 0, issuedLanes = 0;
    int subgroupSize = 0;
    //! With the sample list (Schedule::SampleList): restMs split into its enqueue, shade and
    //! resolve dispatches (GPU timestamps; the tiny group-count dispatch between the first two
    //! is in restMs only). 0 for the other schedules.
    double listEnqueueMs = 0, listShadeMs = 0, listResolveMs = 0;
    double idleLaneShare() const { return issuedLanes ? 1.0 - double(busyLanes) / double(issuedLanes) : 0.0; }
};

//! How the rest pass spreads its samples over the lanes (the image is the same bit for bit):
//! FromParams: AdaptiveParams::tiled picks Tiled or PerPixel (the CPU's choice);
//! PerPixel: one invocation per pixel loops over its samples (a subgroup runs as long as its
//! largest k); Tiled: each 8 x 8 tile's pixels ranked by k first (the paper's future work);
//! SampleList: the samples enqueued, shaded one per invocation by an indirect dispatch, and
//! summed per pixel in dither order (no lane waits for another pixel's loop).
enum class Schedule { FromParams, PerPixel, Tiled, SampleList };
//! "params", "pixel", "tiled" or "list" (the CLI's --schedule); parseSchedule throws
//! ssfx::Error for anything else.
std::string_view scheduleName(Schedule s);
Schedule parseSchedule(std::string_view name);

class AdaptiveShading {
public:
    //! Uploads the scene's materials and texture array (the model's bytes and the device's
    //! image) and makes the pipelines. Throws ssfx::Error for a device without push
    //! descriptors or subgroup arithmetic and ballot in compute shaders (the lane counts, the
    //! sample list), or a scene that does not validate. The scene is copied where needed: it
    //! need not outlive this.
    AdaptiveShading(std::shared_ptr<vkx::Context> ctx, const scene::Scene& scene, Sampling lookup = Sampling::Model);
    ~AdaptiveShading();
    AdaptiveShading(const AdaptiveShading&) = delete;
    AdaptiveShading& operator=(const AdaptiveShading&) = delete;

    Sampling lookup() const;

    //! The method on a host G-buffer (uploaded, run, read back: image, k, the metrics, the
    //! counts). Throws ssfx::Error as the CPU does for a bad G-buffer or params, and for a
    //! sample grid beyond the device's image limit.
    GpuDeferredResult adaptive(const scene::GBuffer& gbuffer, const deferred::AdaptiveParams& params,
                               Schedule schedule = Schedule::FromParams);
    //! Brute force: every sample with the 1/m footprint (the image and the counts).
    GpuDeferredResult bruteForce(const scene::GBuffer& gbuffer, const deferred::ShadingParams& params);

    //! Records the adaptive passes into `cmd`: reads `gbuffer`, writes every pixel of
    //! `output` (R32G32B32A32_SFLOAT, STORAGE usage, layout GENERAL, width x height; linear
    //! RGB, alpha 1); the caller's barrier after record() makes the writes visible to what
    //! reads next. The pass's scratch images (S, k, the metrics), its setup and counters
    //! buffers and the sample list's buffers (SampleList: 20 bytes per possible sample,
    //! grown on demand) are shared between recordings: one recording in flight at a time.
    void record(const vk::raii::CommandBuffer& cmd, const DeviceGBuffer& gbuffer,
                const deferred::AdaptiveParams& params, const ImageRef& output,
                Schedule schedule = Schedule::FromParams);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ssfx::gpu
