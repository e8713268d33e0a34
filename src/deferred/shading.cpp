// Shading of one G-buffer sample (see shading.hpp).
#include "ssfx/deferred/shading.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/deferred/sampler.hpp"

namespace ssfx::deferred {

ImageRgba8 toRgba8(const ImageRgbF& image) {
    ImageRgba8 out(image.width, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 c = glm::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f + 0.5f;
        out.data()[i] = {std::uint8_t(c.r), std::uint8_t(c.g), std::uint8_t(c.b), 255};
    }
    return out;
}

double mse(const ImageRgbF& a, const ImageRgbF& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error(fmt::format("mse: sizes {}x{} and {}x{} differ", a.width, a.height, b.width, b.height));
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::dvec3 d =
            glm::dvec3(glm::clamp(a.pixels[i], 0.0f, 1.0f)) - glm::dvec3(glm::clamp(b.pixels[i], 0.0f, 1.0f));
        sum += glm::dot(d, d);
    }
    return a.pixels.empty() ? 0.0 : sum / (3.0 * double(a.pixels.size()));
}

ImageF absoluteError(const ImageRgbF& a, const ImageRgbF& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error(fmt::format("absoluteError: sizes {}x{} and {}x{} differ", a.width, a.height, b.width, b.height));
    ImageF e(a.width, a.height);
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(glm::clamp(a.pixels[i], 0.0f, 1.0f) - glm::clamp(b.pixels[i], 0.0f, 1.0f));
        e.data()[i] = (d.r + d.g + d.b) / 3.0f;
    }
    return e;
}

void validate(const ShadingParams& p) { validateParams(kShadingParams, &p, "shading"); }

std::vector<CameraLight> cameraLights(const std::vector<scene::Light>& sceneLights, const glm::dmat4& v) {
    std::vector<CameraLight> lights;
    for (const auto& l : sceneLights) {
        if (l.type == scene::Light::Type::Directional)
            lights.push_back({false, glm::normalize(-glm::vec3(glm::dmat3(v) * glm::dvec3(l.vector))), l.color});
        else
            lights.push_back({true, glm::vec3(v * glm::dvec4(glm::dvec3(l.vector), 1.0)), l.color});
    }
    return lights;
}

void validateGBuffer(const scene::GBuffer& g, std::size_t materials, std::size_t layers) {
    const std::size_t n = std::size_t(g.sampleWidth()) * std::size_t(g.sampleHeight());
    if (g.width < 1 || g.height < 1 || g.m < 1 || g.depth.pixelCount() != std::int64_t(n) || g.normal.size() != n ||
        g.uv.size() != n || g.uvGrad.size() != n || g.material.size() != n || g.layer.size() != n)
        throw Error("deferred: the G-buffer's planes do not match its size");
    for (std::size_t i = 0; i < n; ++i) {
        if (g.material[i] != scene::GBuffer::kNoMaterial && g.material[i] >= materials)
            throw Error(
                fmt::format("deferred: G-buffer sample {} names material {} of {}", i, g.material[i], materials));
        if (g.layer[i] >= std::int64_t(layers))
            throw Error(
                fmt::format("deferred: G-buffer sample {} names texture layer {} of {}", i, g.layer[i], layers));
        // Values a caller's (or a file's) G-buffer may carry: named by sample, never shaded.
        const int sx = int(i % std::size_t(g.sampleWidth())), sy = int(i / std::size_t(g.sampleWidth()));
        const float d = g.depth.data()[i];
        if (!(d >= 0.0f && d <= 1.0f))
            throw Error(fmt::format("deferred: G-buffer sample ({}, {}) has depth {} (not in [0, 1])", sx, sy, d));
        const glm::vec3& nrm = g.normal[i];
        const glm::vec2& uv = g.uv[i];
        const glm::vec4& gr = g.uvGrad[i];
        if (!std::isfinite(nrm.x + nrm.y + nrm.z) || !std::isfinite(uv.x + uv.y) ||
            !std::isfinite(gr.x + gr.y + gr.z + gr.w))
            throw Error(
                fmt::format("deferred: G-buffer sample ({}, {}) has a non-finite normal, uv or uv gradient", sx, sy));
    }
    const ImageF& ao = g.ambientOcclusion;
    if (ao.empty()) return;
    if (ao.width() != g.width || ao.height() != g.height)
        throw Error(fmt::format("deferred: the ambient occlusion is {}x{}, the image {}x{}", ao.width(), ao.height(),
                                g.width, g.height));
    for (int y = 0; y < ao.height(); ++y)
        for (int x = 0; x < ao.width(); ++x)
            if (!(ao(x, y) >= 0.0f && ao(x, y) <= 1.0f))
                throw Error(
                    fmt::format("deferred: ambient occlusion {} at pixel ({}, {}) is not in [0, 1]", ao(x, y), x, y));
}

SampleShader::SampleShader(const scene::Scene& scene, const scene::GBuffer& g, const ShadingParams& params)
    : scene_(scene), g_(g), p_(params) {
    validate(params);
    validateGBuffer(g, scene.materials.size(), scene.textures.layers.size());
    proj_ = ssfx::projection(g.camera.camera, g.sampleWidth(), g.sampleHeight());
    lights_ = cameraLights(scene.lights, g.camera.view);
}

float SampleShader::linearDepth(int sx, int sy) const {
    const float d = g_.depth(sx, sy);
    if (g_.material[g_.index(sx, sy)] == scene::GBuffer::kNoMaterial) return INFINITY;
    return float(-proj_.c0 / (double(d) * proj_.c1 + proj_.c2));  // sao.md eq. 2
}

glm::vec3 SampleShader::shade(int sx, int sy, float footprint) const {
    const std::size_t i = g_.index(sx, sy);
    const std::uint16_t mat = g_.material[i];
    glm::vec3 colour;
    if (mat == scene::GBuffer::kNoMaterial) {
        colour = scene_.background;
    } else {
        const scene::Material& m = scene_.materials[mat];
        glm::vec3 albedo = m.diffuse;
        const int layer = g_.layer[i];
        if (layer >= 0) {
            // The G-buffer's derivatives come from the 2x2 quad of samples around this one;
            // across a material or layer change they mix two parameterisations.
            const int qx = sx & ~1, qy = sy & ~1;
            bool boundary = false;
            for (int y = qy; y < std::min(qy + 2, g_.sampleHeight()); ++y)
                for (int x = qx; x < std::min(qx + 2, g_.sampleWidth()); ++x) {
                    const std::size_t j = g_.index(x, y);
                    boundary = boundary || g_.material[j] != mat || g_.layer[j] != layer;
                }
            const glm::vec4 grad = g_.uvGrad[i] * footprint;
            const glm::vec4 tex = boundary ? textureBilinear(scene_.textures, layer, 0, g_.uv[i])
                                           : textureGrad(scene_.textures, layer, g_.uv[i], {grad.x, grad.y},
                                                         {grad.z, grad.w}, p_.maxAnisotropy);
            albedo *= glm::vec3(tex);
        }
        const float z = -linearDepth(sx, sy);
        const ao::Vec3 c = ao::reconstructPosition(proj_, float(sx) + 0.5f, float(sy) + 0.5f, z);
        const glm::vec3 pos(c.x, c.y, c.z);
        const glm::vec3 n = glm::normalize(g_.normal[i]);
        const glm::vec3 toEye = glm::normalize(-pos);
        glm::vec3 diffuse = scene_.ambient, specular(0.0f);
        if (!g_.ambientOcclusion.empty()) diffuse *= g_.ambientOcclusion(sx / g_.m, sy / g_.m);
        for (const auto& l : lights_) {
            glm::vec3 dir = l.vector, irradiance = l.color;
            if (l.point) {
                const glm::vec3 d = l.vector - pos;
                const float d2 = std::max(glm::dot(d, d), 1e-4f);
                dir = d / std::sqrt(d2);
                irradiance /= d2;
            }
            const float nl = glm::dot(n, dir);
            if (nl <= 0.0f) continue;
            diffuse += irradiance * nl;
            // Blinn-Phong, multiplied by n.l so it fades with the diffuse term at the terminator.
            const float nh = std::max(glm::dot(n, glm::normalize(dir + toEye)), 0.0f);
            specular += irradiance * (p_.specular * std::pow(nh, p_.shininess) * nl);
        }
        colour = albedo * diffuse + specular;
    }
    if (p_.stall > 0) {
        // A chain of dependent integer operations (xorshift) that the compiler must keep:
        // the empty asm statement "uses" the result. It does not change the colour.
        std::uint32_t s = std::uint32_t(i) | 1u;
        for (int k = 0; k < p_.stall; ++k) {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
        }
        asm volatile("" : : "r"(s));
    }
    return colour;
}

}  // namespace ssfx::deferred
