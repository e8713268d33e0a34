// The anti-aliasing methods as Vulkan compute passes (the GPU backend; docs/gpu.md).
//
// A pass is created once per method and device, and records its dispatches into the
// caller's command buffer, the way FidelityFX and NRD passes are integrated:
//
//     auto ctx = vkx::Context::create();                 // or vkx::Context::borrow(...)
//     gpu::AaPass pass(ctx, "ddaa2", settings);          // pipelines, tables, scratch
//     pass.record(cmd, input, output);                   // in the caller's frame
//
// The contract of record():
//  - input: a 2-D image view with SAMPLED usage, in layout SHADER_READ_ONLY_OPTIMAL or
//    GENERAL, its writes made visible to compute-shader reads by the caller, of format
//    R8G8B8A8_UNORM or B8G8R8A8_UNORM for texture=unorm (the default: the methods filter the
//    stored values, spec ppaa.md section 1), R8G8B8A8_SRGB or B8G8R8A8_SRGB for
//    texture=srgb (filtered in linear light; the output holds the sRGB-encoded bytes);
//  - output: a 2-D image view of format R8G8B8A8_UNORM with STORAGE usage, in layout
//    GENERAL, of the output size (the input's, divided by the method's input scale:
//    2 for ssaax2 and ddaa2p, 4 for ssaax4); the pass writes every pixel; the caller's
//    barrier after record() makes the compute-shader writes visible to what reads next;
//  - the pass's own scratch image (ddaa2p) and the barriers between its dispatches are the
//    pass's; descriptors are pushed (VK_KHR_push_descriptor, which the device must have
//    enabled: vkx::Context enables it), so a recorded pass holds no per-call state and
//    may be recorded any number of times, also while earlier recordings are in flight.
//    Only ddaa2p's scratch image is shared between recordings: do not let two recordings
//    of the same ddaa2p pass run at the same time (one pass per frame in flight).
//
// Two sampling modes (Sampling): `model` (the default) reproduces the CPU's GPU sampling
// model in the shader, so the output bytes equal the CPU's on any device; `hardware` is the
// fast path an engine would enable: the device's texture unit (a linear sampler) and its
// own arithmetic and conversions, exact only to the device's precision (docs/gpu.md gives
// the measured agreement). The edge-test methods run on one of three paths (EdgePath), the
// same bytes in any.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx::gpu {

enum class Sampling {
    Model,     //!< the CPU's GPU sampling model in the shader: the CPU's bytes
    Hardware,  //!< the device's own bilinear filtering and arithmetic: the fast path
};
//! "model" or "hardware"; parseSampling throws ssfx::Error for anything else.
std::string_view samplingName(Sampling s);
Sampling parseSampling(std::string_view name);

//! How the methods with an edge test (fxaa3c, fxaa3d, ddaa1, ddaa2 and ddaa2p's ddaa2) run,
//! and blur (docs/gpu.md, "Workgroups, workgroup memory and the paths of the edge-test
//! methods"). All give the same bytes in `model`. The segments need subgroup arithmetic and
//! shuffles in compute shaders, and a subgroup's lanes consecutive invocations of the work
//! group, as the lanes share rows (every desktop GPU and lavapipe have them; a probe checks
//! the layout, and the pass says so where a device does not). blur has two paths: Segments
//! (each texel fetched 2.5 times a pixel) and one pixel an invocation (OnePass; List asks for
//! it too); the other methods without an edge test one (OnePass), whatever is asked.
enum class EdgePath {
    Auto,      //!< on a CPU device (lavapipe) the segments for blur, fxaa3c and ddaa1, and for fxaa3d and
               //!< ddaa2 in `hardware`, else the list; one pass on a GPU; one pass wherever the list would
               //!< not fit
    List,      //!< three dispatches: the luma plane, an edge list, the listed pixels
    OnePass,   //!< one dispatch, every pixel's early exit in place, the lumas in a workgroup tile
    Segments,  //!< one dispatch over 8-pixel row segments, rows shared by a subgroup's lanes, its edge
               //!< pixels spread over them
};
//! "auto", "list", "one-pass" or "segments"; parseEdgePath throws ssfx::Error for anything else.
std::string_view edgePathName(EdgePath p);
EdgePath parseEdgePath(std::string_view name);

//! An image as record() takes it: the view, and what the pass checks about it.
struct ImageRef {
    vk::ImageView view;
    vk::Format format = vk::Format::eUndefined;
    vk::ImageUsageFlags usage;
    std::uint32_t width = 0, height = 0;
    vk::ImageLayout layout = vk::ImageLayout::eUndefined;  //!< the layout it will be in when the pass runs
};

//! One method's compute pass on one device.
class AaPass {
public:
    //! `method`: an id of the aa registry (methods()); `settings` as for the CPU (preset,
    //! -p overrides; filtering must be the default Filtering::Gpu, whose GPU form is
    //! Sampling::Model). Throws ssfx::Error for an unknown method, a bad parameter, exact
    //! filtering, or texture=srgb on a device whose sRGB decode does not give the texels'
    //! bytes back (a probe when the pass is made; docs/gpu.md, "sRGB textures").
    AaPass(std::shared_ptr<vkx::Context> ctx, std::string_view method, const MethodSettings& settings = {},
           Sampling sampling = Sampling::Model, EdgePath edges = EdgePath::Auto);
    ~AaPass();
    AaPass(const AaPass&) = delete;
    AaPass& operator=(const AaPass&) = delete;

    const MethodInfo& method() const;
    Sampling sampling() const;
    //! The path the pass takes on this device (never Auto; OnePass or Segments for blur,
    //! OnePass for the other methods without an edge test). An image too large for the list
    //! runs in one pass regardless.
    EdgePath edgePath() const;
    //! Model mode: whether the device's decode of every 8-bit value in the input's format was
    //! found to be the CPU's level (unorm: v / 255 correctly rounded; texture=srgb: kSrgb8) by
    //! a probe when the pass is made (once per device and driver), so the shaders take fetched
    //! values as the texels' levels (docs/gpu.md). lavapipe's unorm decode is one ulp off for
    //! 254: false there.
    bool deviceDecode() const;
    //! Model, texture=srgb, where deviceDecode() is false: whether a texel's level comes from a
    //! table indexed by the device's decoded value (one load a channel), built from a probe of
    //! every byte in both sRGB formats where that gives every byte's level exactly; else the
    //! byte is recovered with the device's pow and its level looked up (docs/gpu.md).
    bool srgbDecodeTable() const;

    //! Records the pass into `cmd` (see the contract above). Throws ssfx::Error when an
    //! image has the wrong format, usage or size, or exceeds the device's limits.
    void record(const vk::raii::CommandBuffer& cmd, const ImageRef& input, const ImageRef& output);

    //! Convenience: uploads `input`, runs the pass, waits and downloads the output (the CLI
    //! and the tests use this). The output is input size / the method's input scale.
    ImageRgba8 run(ImageView<const Rgba8> input);

    //! GPU time of the last run() in milliseconds (timestamps around the dispatches), or
    //! 0 when the queue has no timestamps.
    double lastMilliseconds() const;

    //! One dispatch of the last run(): its stage and its GPU time (timestamps around it).
    struct DispatchTime {
        std::string stage;  //!< luma, classify, edges (the edge-test methods), resolve (ddaa2p's second
                            //!< step), method (a single dispatch), one pass (an image too large for the list)
        double milliseconds = 0;
    };
    //! The last run()'s dispatches in order, for profiles (ssfx bench --backend vulkan). The
    //! barriers between them are in no dispatch's time, so the sum can differ from
    //! lastMilliseconds(). record() into a caller's command buffer writes no timestamps.
    const std::vector<DispatchTime>& lastDispatches() const;
    //! The share of pixels (0..1) that the last run()'s classify dispatch listed as edge
    //! pixels (of the 2x image for ddaa2p), or -1 when it made no list (no edge test, or one pass).
    double lastEdgeShare() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! The methods that have a GPU pass (every aa method today), in registry order.
bool hasGpuPass(std::string_view method);

}  // namespace ssfx::gpu
