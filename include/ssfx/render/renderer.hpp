// The scene renderer: Vulkan 1.3 rasterisation, headless, through Vulkan-Hpp RAII. Runs
// on Mesa's lavapipe (CPU) where there is no GPU. Produces depth buffers in the formats
// of the SAO precision study, supersampled G-buffers for adaptive supersampling, and a
// forward-shaded colour image. See docs/render.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/gbuffer.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::render {

struct DeviceInfo {
    int index = 0;      //!< position in the instance's enumeration
    std::string name;   //!< as the driver reports it, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string type;   //!< discrete, integrated, virtual, cpu, other
    std::string api;    //!< supported Vulkan version, e.g. "1.3.230"
    bool usable = false;  //!< supports Vulkan 1.3 with dynamic rendering
    int maxImageDimension2D = 0;  //!< the largest attachment side it renders (VkPhysicalDeviceLimits)
};

struct RendererOptions {
    //! A device index or a (case-insensitive) part of its name; empty = the first discrete
    //! GPU, else integrated, virtual, then CPU (lavapipe).
    std::string device;
    //! Enable VK_LAYER_KHRONOS_validation and collect its messages (also: SSFX_VK_VALIDATION=1).
    bool validation = false;
};

//! Every Vulkan device of this machine. Throws ssfx::Error when there is no Vulkan loader.
std::vector<DeviceInfo> listDevices();

struct DepthRender {
    ImageF depth;          //!< hardware depth in [0, 1] as stored by the format, guard band included
    CameraSetup camera;
    double gpuMs = 0;      //!< the draw, from timestamp queries
};

struct ColorRender {
    ImageRgba8 color;  //!< diffuse x (ambient + lights), no anti-aliasing, linear values, alpha 255
    double gpuMs = 0;
};

class Renderer {
public:
    //! Creates the instance and device. Throws ssfx::Error when there is no Vulkan driver,
    //! no usable device, or the requested device or validation layer does not exist.
    explicit Renderer(const RendererOptions& options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const DeviceInfo& device() const;
    //! Validation messages (warnings and errors) since creation; empty when validation is off.
    std::vector<std::string> validationMessages() const;

    //! Depth of `view` at width x height plus a guard band of `guard` pixels on each side.
    DepthRender renderDepth(const Scene& scene, const View& view, int width, int height,
                            DepthFormat format = DepthFormat::D32F, int guard = 0);
    //! G-buffer at m x m supersampling (m = 1..4) of a width x height image.
    GBuffer renderGBuffer(const Scene& scene, const View& view, int width, int height, int m);
    //! Forward-shaded colour at (scale width) x (scale height).
    ColorRender renderColor(const Scene& scene, const View& view, int width, int height, int scale = 1);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! The anti-aliasing evaluation's render set (ssfx/eval/quality.hpp) of one view: NAME.png at
//! width x height and NAMEx2.png, NAMEx4.png, NAMEx8.png at 2, 4 and 8 times that size, all
//! forward-shaded without anti-aliasing, written into `dir` (like the paper's sponza image).
void writeAaRenderSet(Renderer& renderer, const Scene& scene, const View& view, int width, int height,
                      const std::string& dir, const std::string& name);

}  // namespace ssfx::render
