// Shading one G-buffer sample for adaptive supersampling (adaptive_ss.md "Shading a
// sample"): Lambert diffuse plus a Blinn-Phong specular term over all of the scene's
// lights, the albedo looked up in the texture array with anisotropic filtering driven by
// the G-buffer's texture-coordinate derivatives, scaled to the share of the pixel the
// sample stands for; and an optional artificial cost per sample ("stall").
#pragma once

#include <array>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "ssfx/core/camera.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/scene/gbuffer.hpp"

namespace ssfx::deferred {

//! Linear RGB, row-major.
struct ImageRgbF {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;
    ImageRgbF() = default;
    ImageRgbF(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), glm::vec3(0.0f)) {}
    glm::vec3& operator()(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const glm::vec3& operator()(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const ImageRgbF&, const ImageRgbF&) = default;
};
//! Clamped to [0, 1] and rounded to 8 bits, alpha 255.
ImageRgba8 toRgba8(const ImageRgbF& image);
//! Mean over pixels and the three channels of the squared difference of values clamped to [0, 1].
double mse(const ImageRgbF& a, const ImageRgbF& b);
//! Per pixel, the mean over the three channels of |a - b| (values clamped to [0, 1]).
ImageF absoluteError(const ImageRgbF& a, const ImageRgbF& b);

struct ShadingParams {
    float specular = 0.25f;   //!< Blinn-Phong specular colour (white, times the light)
    float shininess = 40.0f;  //!< Blinn-Phong exponent
    int maxAnisotropy = 16;   //!< probes of the anisotropic lookup
    int stall = 0;            //!< extra dependent integer operations per shaded sample
};
//! The shading rows of a table: ShadingParams' own (no Path), or an owner's whose member at
//! Path is a ShadingParams.
template <auto... Path>
constexpr std::array<ParamInfo, 4> shadingRows() {
    return {{
        real<Path..., &ShadingParams::specular>(
            "specular", "", 0, 1, "Blinn-Phong specular colour (white x light), added to the Lambert diffuse"),
        real<Path..., &ShadingParams::shininess>("shininess", "", 1, 10000, "Blinn-Phong exponent"),
        integer<Path..., &ShadingParams::maxAnisotropy>("maxAnisotropy", "", 1, 16, "probes of the anisotropic lookup"),
        integer<Path..., &ShadingParams::stall>("stall", "ops", 0, 1e7,
                                                "extra dependent integer operations per shaded sample"),
    }};
}
//! ShadingParams' table (core/params.hpp); the defaults are the initialisers.
inline constexpr auto kShadingParams = shadingRows<>();
//! Throws ssfx::Error naming the parameter when one is out of range.
void validate(const ShadingParams& p);

//! A light as the shading sees it: in the G-buffer's camera space.
struct CameraLight {
    bool point;
    glm::vec3 vector;  //!< a directional light's unit direction towards it, or a point light's position
    glm::vec3 color;
};
//! The scene's lights in the camera space of `view` (world -> camera), computed in double
//! and rounded once (the CPU's and the GPU pass's lights: deferred_pass.cpp).
std::vector<CameraLight> cameraLights(const std::vector<scene::Light>& lights, const glm::dmat4& view);

//! Throws ssfx::Error when the G-buffer's planes do not match its size, or a sample names a
//! material or texture layer beyond the scene's counts, or has a depth outside [0, 1] or a
//! non-finite normal, uv or uv gradient (named by sample). What SampleShader and the GPU
//! pass check.
void validateGBuffer(const scene::GBuffer& gbuffer, std::size_t materials, std::size_t layers);

class SampleShader {
public:
    //! Throws ssfx::Error when the G-buffer is empty or inconsistent, or the params are bad.
    SampleShader(const scene::Scene& scene, const scene::GBuffer& gbuffer, const ShadingParams& params);

    //! The colour of G-buffer sample (sx, sy) for a sample standing for `footprint` (linear
    //! fraction of a final pixel: 1 = the whole pixel, 1/m = one of m x m samples); the
    //! background colour for background samples. At a material or texture-layer boundary
    //! within the sample's 2x2 quad (where the G-buffer derivatives are meaningless) the
    //! lookup falls back to the un-derived, finest-level bilinear one.
    glm::vec3 shade(int sx, int sy, float footprint) const;
    //! Whether the sample's albedo depends on the footprint (it is textured).
    bool textured(int sx, int sy) const { return g_.layer[g_.index(sx, sy)] >= 0; }
    //! Camera-space depth -z of a sample (metres; +infinity for background).
    float linearDepth(int sx, int sy) const;

private:
    const scene::Scene& scene_;
    const scene::GBuffer& g_;
    ShadingParams p_;
    Projection proj_;
    std::vector<CameraLight> lights_;
};

}  // namespace ssfx::deferred
