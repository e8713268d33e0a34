// The G-buffer the renderer writes and adaptive supersampling shades (scenes library:
// no Vulkan needed to hold or shade one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "ssfx/core/image.hpp"
#include "ssfx/scene/camera.hpp"

namespace ssfx::scene {

//! A G-buffer at m x m supersampling: every buffer is (m width) x (m height) samples,
//! row-major, the final pixel (x, y) owning samples [m x, m x + m) x [m y, m y + m).
struct GBuffer {
    static constexpr std::uint16_t kNoMaterial = 0xFFFF;  //!< background samples
    int width = 0, height = 0, m = 1;
    ImageF depth;                   //!< D32F, 1 = background
    std::vector<glm::vec3> normal;  //!< camera space, towards the camera (16-bit snorm on the GPU); 0 on background
    std::vector<glm::vec2> uv;      //!< texture coordinates (float32)
    std::vector<glm::vec4> uvGrad;  //!< (du/dx, dv/dx, du/dy, dv/dy) per *final-image* pixel (float32)
    std::vector<std::uint16_t> material;  //!< material index or kNoMaterial
    std::vector<std::int16_t> layer;      //!< texture layer or -1
    CameraSetup camera;                   //!< of the (m width) x (m height) sample grid
    //! Optional ambient occlusion of the final pixels (width x height, values in [0, 1]): the
    //! shading multiplies the ambient term of each of a pixel's samples by it (how a frame
    //! applies SAO to ambient light); empty: no occlusion. Not part of the G-buffer file.
    ImageF ambientOcclusion;
    double gpuMs = 0;

    int sampleWidth() const { return m * width; }
    int sampleHeight() const { return m * height; }
    std::size_t index(int sx, int sy) const { return std::size_t(sy) * std::size_t(sampleWidth()) + std::size_t(sx); }
};

//! Writes `g` as one float EXR of the sample grid: channels N.X N.Y N.Z (camera-space
//! normal), UV.U UV.V, dUVdx.U dUVdx.V dUVdy.U dUVdy.V, material (-1 on background),
//! layer (-1: none) and Z (the D32F depth). Atomic (io::AtomicFile).
void writeGBufferExr(const std::string& path, const GBuffer& g);

}  // namespace ssfx::scene
