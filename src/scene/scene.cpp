// Scene data: validation, bounds, the texture array and name lookup (see scene.hpp).
#include <fmt/format.h>

#include <stb/stb_image_resize.h>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ssfx/core/error.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

const View& Scene::view(const std::string& viewName) const {
    for (const auto& v : views)
        if (v.first == viewName) return v.second;
    std::string known;
    for (const auto& v : views) known += (known.empty() ? "" : ", ") + v.first;
    throw Error(fmt::format("scene '{}' has no view '{}' (views: {})", name, viewName, known.empty() ? "none" : known));
}

std::pair<glm::vec3, glm::vec3> Scene::bounds() const {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& v : vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    return {lo, hi};
}

void Scene::validate() const {
    if (indices.empty() || indices.size() % 3 != 0)
        throw Error(fmt::format("scene '{}': {} indices is not a positive multiple of 3", name, indices.size()));
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertices.size())
            throw Error(fmt::format("scene '{}': index {} = {} is out of range ({} vertices)", name, i, indices[i],
                                    vertices.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const auto& v = vertices[i];
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(v.position[c]) || !std::isfinite(v.normal[c]))
                throw Error(fmt::format("scene '{}': vertex {} has a non-finite position or normal", name, i));
        if (v.material >= materials.size())
            throw Error(
                fmt::format("scene '{}': vertex {} uses material {} of {}", name, i, v.material, materials.size()));
    }
    for (const auto& m : materials)
        if (m.textureLayer >= int(textures.layers.size()) || m.textureLayer < -1)
            throw Error(fmt::format("scene '{}': material '{}' uses texture layer {} of {}", name, m.name,
                                    m.textureLayer, textures.layers.size()));
}

namespace {

// Level m+1 = 2x2 box filter of level m (square power-of-two sizes: exact halving).
std::vector<ImageRgba8> mipChain(ImageRgba8 base) {
    std::vector<ImageRgba8> levels;
    levels.push_back(std::move(base));
    while (levels.back().width() > 1) {
        const ImageRgba8& src = levels.back();
        ImageRgba8 dst(src.width() / 2, src.height() / 2);
        for (int y = 0; y < dst.height(); ++y)
            for (int x = 0; x < dst.width(); ++x) {
                const Rgba8 a = src(2 * x, 2 * y), b = src(2 * x + 1, 2 * y), c = src(2 * x, 2 * y + 1),
                            d = src(2 * x + 1, 2 * y + 1);
                auto avg = [](int p, int q, int r, int s) { return std::uint8_t((p + q + r + s + 2) / 4); };
                dst(x, y) = {avg(a.r, b.r, c.r, d.r), avg(a.g, b.g, c.g, d.g), avg(a.b, b.b, c.b, d.b),
                             avg(a.a, b.a, c.a, d.a)};
            }
        levels.push_back(std::move(dst));
    }
    return levels;
}

int powerOfTwoAtLeast(int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
}

}  // namespace

int addTextureLayer(TextureArray& textures, const ImageRgba8& image) {
    constexpr int kMaxSize = 2048;
    if (textures.layers.empty())
        textures.size = std::min(kMaxSize, powerOfTwoAtLeast(std::max(image.width(), image.height())));
    ImageRgba8 base;
    if (image.width() == textures.size && image.height() == textures.size) {
        base = image;
    } else {
        // One size for the whole array: resample (stb_image_resize, Mitchell filter, wrapping
        // edges as the sampler's repeat mode does).
        base = ImageRgba8(textures.size, textures.size);
        const int ok = stbir_resize_uint8_generic(reinterpret_cast<const unsigned char*>(image.data()), image.width(),
                                                  image.height(), 0, reinterpret_cast<unsigned char*>(base.data()),
                                                  base.width(), base.height(), 0, 4, 3, 0, STBIR_EDGE_WRAP,
                                                  STBIR_FILTER_MITCHELL, STBIR_COLORSPACE_LINEAR, nullptr);
        if (!ok) throw Error("texture resize failed");
    }
    textures.layers.push_back(mipChain(std::move(base)));
    return int(textures.layers.size()) - 1;
}

std::vector<std::string> builtinScenes() { return {"atrium", "cornell"}; }

Scene builtinScene(const std::string& name) {
    if (name == "cornell") return cornellBox();
    if (name == "atrium") return atrium();
    throw Error(fmt::format("unknown built-in scene '{}' (atrium, cornell)", name));
}

Scene loadScene(const std::string& nameOrPath) {
    for (const auto& b : builtinScenes())
        if (nameOrPath == b) return builtinScene(b);
    std::string ext = std::filesystem::path(nameOrPath).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".json") return loadSceneFile(nameOrPath);
    if (ext.empty() && !std::filesystem::exists(nameOrPath))
        throw Error(fmt::format(
            "scene '{}': not a built-in scene (atrium, cornell), a scene file (.json) or a model file", nameOrPath));
    return importModel(nameOrPath);
}

}  // namespace ssfx::scene
