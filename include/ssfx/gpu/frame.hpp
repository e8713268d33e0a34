// The whole frame on one device (docs/frame.md): the three papers as the stages of one
// real-time frame. Per frame:
//
//   depth draw (guard band) --> AO (SAO, AlchemyAO or GTAO) --------------.
//   G-buffer draw (m x m) ---------------------------------> adaptive shading (AO on the
//                                                              ambient term) --> encode (RGBA8)
//                                                              --> anti-aliasing --> read-back
//
// Every pass reads the previous one's output where it is, in GPU memory; the only transfer is
// the final image's read-back. The draws are the renderer's (render::Renderer, one submission
// each, their attachments kept on the device); the compute passes (gpu::AoPass,
// gpu::AdaptiveShading, the encode pass, gpu::AaPass) and the read-back are one submission.
//
//     auto ctx = vkx::Context::create({.graphics = true});
//     gpu::FrameRenderer frame(ctx, scene, settings);    // pipelines, scene upload, targets
//     gpu::FrameResult r = frame.render(view);           // r.image, r.passes (the profile)
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/ao/registry.hpp"
#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/gpu/aa.hpp"
#include "ssfx/gpu/deferred.hpp"
#include "ssfx/scene/scene.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx::gpu {

struct FrameSettings {
    int width = 1280, height = 720;  //!< the final image
    int m = 4;                       //!< the G-buffer's samples per pixel's side (1..4)
    //! An AO method with a GPU pass (sao, alchemy, gtao; hasGpuAo) or "none". Its guard band
    //! (ao::guardBandOf(aoParams)) widens the depth draw.
    std::string ao = "sao";
    ao::AoParams aoParams = ao::SaoParams{};  //!< of `ao`'s type (ignored for none)
    //! An aa method whose input is the output size (inputScale 1: not ssaax2, ssaax4, ddaa2p),
    //! or "none" (the encoded shading is the frame).
    std::string aa = "ddaa2";
    MethodSettings aaSettings;
    deferred::AdaptiveParams shading;          //!< the adaptive supersampling's params
    Schedule schedule = Schedule::FromParams;  //!< the rest pass's schedule (the same image)
    Sampling lookup = Sampling::Model;         //!< the shading's texture lookup
};

//! One pass's time in one frame.
struct FramePassTime {
    std::string pass;  //!< depth draw, ao, gbuffer draw, shading, encode, aa, readback
    double milliseconds = 0;
};

struct FrameResult {
    ImageRgba8 image;                   //!< the final image, read back
    std::vector<FramePassTime> passes;  //!< in the frame's order
    double totalMs() const;
};

//! How the profile's pass times are measured (FrameRenderer::clock()).
enum class FrameClock {
    Timestamps,  //!< GPU timestamps around each pass (the draws: the renderer's)
    Host,        //!< a queue without timestamps: each pass its own submission, timed on the host
};

class FrameRenderer {
public:
    //! ctx: a context with a graphics queue (ContextOptions::graphics) and push descriptors.
    //! Makes the renderer, the passes and the frame's images; throws ssfx::Error for an
    //! unknown or unsupported AO or AA method (named), bad params, a size beyond the
    //! device's image limit (the depth draw with its guard band, the m x m G-buffer), or a
    //! device without what the passes need.
    FrameRenderer(std::shared_ptr<vkx::Context> ctx, const scene::Scene& scene, const FrameSettings& settings);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    //! Renders one frame of `view` and reads back its image, with the pass times.
    FrameResult render(const scene::View& view);
    FrameClock clock() const;
    const FrameSettings& settings() const;
    //! The renderer's and the passes' validation messages (empty when validation is off).
    std::vector<std::string> validationMessages() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! "timestamps" or "host".
std::string_view frameClockName(FrameClock c);

}  // namespace ssfx::gpu
