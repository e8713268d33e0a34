// The scene renderer: Vulkan 1.3 rasterisation, headless, through Vulkan-Hpp RAII. Runs
// on Mesa's lavapipe (CPU) where there is no GPU. Produces depth buffers in the formats
// of the SAO precision study, supersampled G-buffers for adaptive supersampling, and a
// forward-shaded colour image. See docs/render.md.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/gbuffer.hpp"
#include "ssfx/scene/scene.hpp"
#include "ssfx/vk/device.hpp"
#include "ssfx/vk/resources.hpp"

#include <vulkan/vulkan_raii.hpp>

namespace ssfx::vkx {
class Context;
}

namespace ssfx::render {

struct RendererOptions {
    //! A device index or a (case-insensitive) part of its name; empty = the first discrete
    //! GPU, else integrated, virtual, then CPU (lavapipe). See vkx::ContextOptions.
    std::string device;
    //! Validation layer with synchronization validation (also: SSFX_VK_VALIDATION=1).
    bool validation = false;
};

struct DepthRender {
    ImageF depth;  //!< hardware depth in [0, 1] as stored by the format, guard band included
    scene::CameraSetup camera;
    double gpuMs = 0;  //!< the draw, from timestamp queries
};

struct ColorRender {
    ImageRgba8 color;  //!< diffuse x (ambient + lights), no anti-aliasing, linear values, alpha 255
    double gpuMs = 0;
};

//! An attachment while it is on the device (Renderer::renderDepthOnDevice,
//! renderGBufferOnDevice): a 2-D view (of the depth aspect for depth), its format, usage
//! (includes SAMPLED), size and the layout it is in.
struct DeviceImage {
    vk::ImageView view;
    vk::Format format = vk::Format::eUndefined;
    vk::ImageUsageFlags usage;
    std::uint32_t width = 0, height = 0;
    vk::ImageLayout layout = vk::ImageLayout::eDepthReadOnlyOptimal;
};
//! A depth image while it is on the device (Renderer::renderDepthOnDevice).
using DeviceDepth = DeviceImage;
//! Records GPU work after the draw, into the draw's command buffer.
using DepthRecorder = std::function<void(const vk::raii::CommandBuffer&, const DeviceDepth&)>;

//! A G-buffer while it is on the device (Renderer::renderGBufferOnDevice): 2-D views of the
//! draw's attachments, (m width) x (m height), SAMPLED, their writes made visible to
//! compute-shader reads. Formats: depth D32_SFLOAT (its depth aspect, layout
//! DEPTH_READ_ONLY_OPTIMAL); normal R16G16B16A16_SNORM (camera space), uv R32G32_SFLOAT,
//! uvGrad R32G32B32A32_SFLOAT (du/dx, dv/dx, du/dy, dv/dy per final pixel), ids R16G16_UINT
//! (material, texture layer; 0xFFFF: background, none), in layout SHADER_READ_ONLY_OPTIMAL.
struct DeviceGBufferImages {
    DeviceImage depth, normal, uv, uvGrad, ids;
    int width = 0, height = 0, m = 1;  //!< the final image and the samples per pixel's side
    scene::CameraSetup camera;         //!< of the (m width) x (m height) sample grid
};
using GBufferRecorder = std::function<void(const vk::raii::CommandBuffer&, const DeviceGBufferImages&)>;

class Renderer {
public:
    //! Creates its own Vulkan context (instance, device, a graphics queue). Throws ssfx::Error
    //! when there is no Vulkan driver, no usable device, or the requested device or
    //! validation layer does not exist.
    explicit Renderer(const RendererOptions& options = {});
    //! Renders on a shared context (one device for the renderer and the GPU effects); it must
    //! have been created with ContextOptions::graphics.
    explicit Renderer(std::shared_ptr<vkx::Context> context);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const vkx::DeviceInfo& device() const;
    const std::shared_ptr<vkx::Context>& context() const;
    //! Validation messages (warnings and errors) since creation; empty when validation is off.
    std::vector<std::string> validationMessages() const;

    //! Depth of `view` at width x height plus a guard band of `guard` pixels on each side.
    DepthRender renderDepth(const scene::Scene& scene, const scene::View& view, int width, int height,
                            DepthFormat format = DepthFormat::D32F, int guard = 0);
    //! The same draw, with the depth left on the device: `after` records into the draw's
    //! command buffer, after it, with the depth image in DEPTH_READ_ONLY_OPTIMAL and the
    //! draw's writes made visible to compute-shader reads (how the GPU AO passes read the
    //! renderer's depth without a copy). Nothing is read back; returns when the submission
    //! is done, with DepthRender::depth empty. With `keep`, the depth image and its view
    //! outlive the call, in DEPTH_READ_ONLY_OPTIMAL, as long as *keep holds them (work in a
    //! later submission reads them: ssfx frame's passes).
    DepthRender renderDepthOnDevice(const scene::Scene& scene, const scene::View& view, int width, int height,
                                    DepthFormat format, int guard, const DepthRecorder& after,
                                    std::shared_ptr<const void>* keep = nullptr);
    //! G-buffer at m x m supersampling (m = 1..4) of a width x height image.
    scene::GBuffer renderGBuffer(const scene::Scene& scene, const scene::View& view, int width, int height, int m);
    //! The same draw with the G-buffer left on the device: `after` records into the draw's
    //! command buffer, after it (how the GPU adaptive shading reads the renderer's G-buffer
    //! without a copy). Nothing is read back; returns when the submission is done, with the
    //! G-buffer's size, m, camera and draw time and no planes. With `keep`, as for
    //! renderDepthOnDevice: the attachments outlive the call while *keep holds them.
    scene::GBuffer renderGBufferOnDevice(const scene::Scene& scene, const scene::View& view, int width, int height,
                                         int m, const GBufferRecorder& after,
                                         std::shared_ptr<const void>* keep = nullptr);
    //! Forward-shaded colour at (scale width) x (scale height).
    ColorRender renderColor(const scene::Scene& scene, const scene::View& view, int width, int height, int scale = 1);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! A scene's texture array as one image on ctx's device: R8G8B8A8_UNORM, one layer per texture
//! with its mip chain (a 1x1 white layer when the scene has none), SAMPLED, in layout
//! SHADER_READ_ONLY_OPTIMAL (its view: 2-D array). What the renderer's and the GPU shading's
//! samplers read.
vkx::Image uploadTextureArray(vkx::Context& ctx, const scene::TextureArray& textures);

//! The anti-aliasing evaluation's render set (ssfx/eval/quality.hpp) of one view: NAME.png at
//! width x height and NAMEx2.png, NAMEx4.png, NAMEx8.png at 2, 4 and 8 times that size, all
//! forward-shaded without anti-aliasing, written into `dir` (like the paper's sponza image).
void writeAaRenderSet(Renderer& renderer, const scene::Scene& scene, const scene::View& view, int width, int height,
                      const std::string& dir, const std::string& name, const ProgressFn& progress = {});

}  // namespace ssfx::render
