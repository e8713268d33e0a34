// Scenes for the renderer: triangle meshes with materials, a texture array, lights and
// named camera viewpoints. Built in code (the procedural scenes), imported with Assimp
// (OBJ, glTF 2.0, Collada), or described by a scene file (JSON) that names a model.
//
// Conventions: world space is right-handed with y up, units metres. Texture coordinates
// have v = 0 at the top row of the image (Vulkan's convention; imported models are
// flipped to it). Normals are per vertex; surfaces are two-sided (the renderer turns
// back faces' normals towards the camera).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::scene {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
    std::uint32_t material = 0;  //!< index into Scene::materials
};

struct Material {
    std::string name;
    glm::vec3 diffuse{0.8f};  //!< linear RGB albedo, multiplied with the texture
    int textureLayer = -1;    //!< layer of Scene::textures, or -1 for none
};

//! All of a scene's textures as one array: square, the same power-of-two size, with a
//! full mip chain per layer made by 2x2 box filtering (level 0 first).
struct TextureArray {
    int size = 0;
    std::vector<std::vector<ImageRgba8>> layers;  //!< [layer][level]
    int levelCount() const { return layers.empty() ? 0 : int(layers[0].size()); }
};
//! Resizes `image` to size x size (size a power of two) when needed and appends it with its mips.
int addTextureLayer(TextureArray& textures, const ImageRgba8& image);

struct Light {
    enum class Type { Directional, Point } type = Type::Directional;
    glm::vec3 vector{0.0f, -1.0f, 0.0f};  //!< Directional: the direction light travels; Point: the position
    glm::vec3 color{1.0f};                //!< Directional: irradiance; Point: intensity (falls off as 1/d^2)
};

//! A named camera viewpoint. Distances are positive metres (the camera space of the AO
//! code has z_near = -zNear).
struct View {
    glm::dvec3 eye{0.0, 1.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDeg = 60.0;                                  //!< vertical field of view of the image (no guard band)
    double zNear = 0.1;                                     //!< > 0
    double zFar = std::numeric_limits<double>::infinity();  //!< > zNear, or infinity
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  //!< triangles, three per face
    std::vector<Material> materials;
    TextureArray textures;
    std::vector<Light> lights;
    glm::vec3 ambient{0.15f};
    glm::vec3 background{0.55f, 0.7f, 0.9f};  //!< clear colour of the forward render (sky)
    std::vector<std::pair<std::string, View>> views;

    std::size_t triangleCount() const { return indices.size() / 3; }
    //! The view called `name`; throws ssfx::Error listing the scene's views if there is none.
    const View& view(const std::string& name) const;
    //! Axis-aligned bounds of the vertices (min, max).
    std::pair<glm::vec3, glm::vec3> bounds() const;
    //! Throws ssfx::Error for an index out of range, a material or texture layer that does
    //! not exist, or a non-finite vertex.
    void validate() const;
};

//! The built-in procedural scenes: "cornell" (a Cornell box) and "atrium" (columns,
//! arches, stairs, thin bars, a folded curtain, checker and brick textures).
std::vector<std::string> builtinScenes();
Scene builtinScene(const std::string& name);
Scene cornellBox();
Scene atrium();

//! Imports a model file with Assimp (OBJ, glTF 2.0, Collada, ...), scaled by `scale`;
//! diffuse textures are decoded with stb_image. One default light and a "default" view
//! framing the model are added. Throws ssfx::Error naming the file for a missing or
//! corrupt model and for a missing texture.
Scene importModel(const std::string& path, double scale = 1.0);

//! The same from bytes in memory. `format` is the file extension Assimp would choose the
//! importer by ("obj", "gltf", "glb", ...); `name` names the scene and the messages. Such a
//! model cannot open other files, so its textures must be embedded (a glTF's data URIs or
//! a GLB's buffer views); an external one is an error naming it.
Scene importModelFromMemory(std::span<const std::uint8_t> bytes, const std::string& format, const std::string& name,
                            double scale = 1.0);

//! A scene file (JSON):
//!   {"model": "relative/or/absolute/path.obj", "scale": 1, "ambient": [r, g, b],
//!    "background": [r, g, b],
//!    "lights": [{"type": "directional", "direction": [x, y, z], "color": [r, g, b]},
//!               {"type": "point", "position": [x, y, z], "color": [r, g, b]}],
//!    "views": {"name": {"eye": [x, y, z], "target": [x, y, z], "up": [0, 1, 0],
//!                        "fov_y_deg": 60, "z_near": 0.1, "z_far": null}}}
//! The model path is relative to the scene file. Lights and views replace the model's defaults.
Scene loadSceneFile(const std::string& path);

//! Loads the model a scene file names (an absolute path, already resolved against the file's
//! directory) at the given scale.
using ModelLoader = std::function<Scene(const std::string& modelPath, double scale)>;
//! A scene file's text, `path` naming it in messages and anchoring a relative model path;
//! `loadModel` reads the model (importModel for loadSceneFile).
Scene parseSceneFile(std::string_view text, const std::string& path, const ModelLoader& loadModel);

//! A built-in name, a scene file (.json) or a model file.
Scene loadScene(const std::string& nameOrPath);

}  // namespace ssfx::scene
