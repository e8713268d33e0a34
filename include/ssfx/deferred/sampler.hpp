// CPU texture sampling of a scene's texture array, as GLSL's textureGrad behaves
// (adaptive_ss.md "Shading a sample"): the footprint comes from the texture-coordinate
// derivatives; an anisotropic footprint is covered by several trilinear probes along its
// major axis (the EXT_texture_filter_anisotropic formulation: N = min(ceil(Pmax / Pmin),
// maxAnisotropy) probes, level of detail log2(Pmax / N)). Addressing repeats; values are
// the texels' unorm values in [0, 1], not linearised (as the renderer's).
#pragma once

#include <glm/glm.hpp>

#include "ssfx/scene/scene.hpp"

namespace ssfx::deferred {

inline constexpr int kMaxAnisotropy = 16;  //!< the largest maxAnisotropy accepted (as GPUs' limit)

//! Bilinear lookup in one mip level (texel centres at (i + 0.5) / size), repeat addressing.
glm::vec4 textureBilinear(const scene::TextureArray& t, int layer, int level, glm::vec2 uv);
//! Trilinear lookup at a level of detail (clamped to the mip chain).
glm::vec4 textureLod(const scene::TextureArray& t, int layer, glm::vec2 uv, float lod);
//! Anisotropic lookup with explicit derivatives (du/dx, dv/dx) and (du/dy, dv/dy) in
//! texture-coordinate units per pixel (of the footprint wanted). maxAnisotropy in [1, 16].
glm::vec4 textureGrad(const scene::TextureArray& t, int layer, glm::vec2 uv, glm::vec2 dx, glm::vec2 dy,
                      int maxAnisotropy = kMaxAnisotropy);

}  // namespace ssfx::deferred
