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
#include "ssfx/render/camera.hpp"
#include "ssfx/render/scene.hpp"

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

//! A G-buffer at m x m supersampling: every buffer is (m width) x (m height) samples,
//! row-major, the final pixel (x, y) owning samples [m x, m x + m) x [m y, m y + m).
struct GBuffer {
    static constexpr std::uint16_t kNoMaterial = 0xFFFF;  //!< background samples
    int width = 0, height = 0, m = 1;
    ImageF depth;                         //!< D32F, 1 = background
    std::vector<glm::vec3> normal;        //!< camera space, towards the camera (16-bit snorm on the GPU); 0 on background
    std::vector<glm::vec2> uv;            //!< texture coordinates (float32)
    std::vector<glm::vec4> uvGrad;        //!< (du/dx, dv/dx, du/dy, dv/dy) per *final-image* pixel (float32)
    std::vector<std::uint16_t> material;  //!< material index or kNoMaterial
    std::vector<std::int16_t> layer;      //!< texture layer or -1
    CameraSetup camera;                   //!< of the (m width) x (m height) sample grid
    double gpuMs = 0;

    int sampleWidth() const { return m * width; }
    int sampleHeight() const { return m * height; }
    std::size_t index(int sx, int sy) const { return std::size_t(sy) * std::size_t(sampleWidth()) + std::size_t(sx); }
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
                            ao::DepthFormat format = ao::DepthFormat::D32F, int guard = 0);
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
