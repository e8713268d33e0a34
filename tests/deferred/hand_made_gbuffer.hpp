// A hand-made G-buffer for the adaptive shading tests, CPU and GPU: a textured plane (the
// atrium's checker floor) facing the camera, flat or slanted so that its depth changes along
// x. Slanted, every m x m window has depth variance: k = m^2 everywhere, and the method is
// brute force bit for bit.
#pragma once

#include <cstdint>

#include "ssfx/ao/depth.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/gbuffer.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::test {

inline scene::GBuffer handMadeGBuffer(const scene::Scene& scene, int w, int h, int m, bool slanted) {
    scene::GBuffer g;
    g.width = w;
    g.height = h;
    g.m = m;
    scene::View v;
    v.eye = {0, 1, 5};
    v.target = {0, 1, 0};
    g.camera = scene::cameraSetup(v, m * w, m * h);
    const int sw = m * w, sh = m * h;
    const std::size_t n = std::size_t(sw) * std::size_t(sh);
    g.depth = ImageF(sw, sh);
    g.normal.assign(n, glm::vec3(0, 0, 1));
    g.uv.resize(n);
    g.uvGrad.assign(n, glm::vec4(0.05f, 0.0f, 0.0f, 0.05f));
    g.material.assign(n, 0);  // atrium material 0: the checker floor (texture layer 0)
    g.layer.assign(n, std::int16_t(scene.materials[0].textureLayer));
    for (int y = 0; y < sh; ++y)
        for (int x = 0; x < sw; ++x) {
            const double z = slanted ? -(4.0 + 0.3 * x) : -4.0;
            g.depth(x, y) = float(ao::zToDepth(z, g.camera.camera));
            g.uv[g.index(x, y)] = {0.05f * float(x) / float(m), 0.05f * float(y) / float(m)};
        }
    return g;
}

}  // namespace ssfx::test
