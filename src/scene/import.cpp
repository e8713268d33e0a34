// Model import with Assimp and scene files (JSON); see scene.hpp.
#include <assimp/BaseImporter.h>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <span>
#include <string_view>
#include <type_traits>

#include "ssfx/core/error.hpp"
#include "ssfx/core/isolate.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // views keep the file's order

namespace {

ImageRgba8 decodeTexture(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    int w = 0, h = 0, channels = 0;
    // Check the size before decoding (stb_image would allocate whatever the header says).
    if (!stbi_info_from_memory(bytes, int(size), &w, &h, &channels))
        throw Error(fmt::format("texture '{}': cannot decode ({})", name, stbi_failure_reason()));
    checkDimensions(w, h, fmt::format("texture '{}'", name));
    std::uint8_t* pixels = stbi_load_from_memory(bytes, int(size), &w, &h, &channels, 4);
    if (!pixels) throw Error(fmt::format("texture '{}': cannot decode ({})", name, stbi_failure_reason()));
    ImageRgba8 img(w, h);
    std::memcpy(img.data(), pixels, std::size_t(w) * std::size_t(h) * 4);
    stbi_image_free(pixels);
    return img;
}

View defaultView(const Scene& s) {
    const auto [lo, hi] = s.bounds();
    const glm::dvec3 centre = (glm::dvec3(lo) + glm::dvec3(hi)) * 0.5;
    const double radius = std::max(1e-3, glm::length(glm::dvec3(hi) - glm::dvec3(lo)) * 0.5);
    View v;
    v.fovYDeg = 50.0;
    // Far enough that the bounding sphere fits the vertical field of view, looking along -z.
    const double dist = radius / std::sin(v.fovYDeg * std::numbers::pi / 360.0);
    v.eye = centre + glm::dvec3(0.0, radius * 0.25, dist);
    v.target = centre;
    v.zNear = std::max(1e-3, (dist - radius) * 0.05);
    return v;
}

glm::vec3 vec3Of(const Json& j, const std::string& what) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
        throw Error(fmt::format("{} must be an array of three numbers", what));
    const glm::vec3 v{j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw Error(fmt::format("{} must be finite (each within a float's range)", what));
    return v;
}

}  // namespace

namespace {

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                                  aiProcess_PreTransformVertices | aiProcess_FlipUVs | aiProcess_SortByPType |
                                  aiProcess_ValidateDataStructure;

// Keeps only the importers that claim `ext` (lower case, no dot). Without this, a file that
// none of them accepts (a corrupt .gltf) goes to Assimp's signature-based detection across
// every importer it has, and some of those (the fuzz target found BVH's) read past the end of
// malformed input. The format is the extension's, as the docs say, and nothing else.
void configure(Assimp::Importer& importer, const std::string& ext, const std::string& what) {
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    std::vector<Assimp::BaseImporter*> others;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        const aiImporterDesc* desc = importer.GetImporterInfo(i);
        bool claims = false;
        if (desc && desc->mFileExtensions) {
            std::string list = desc->mFileExtensions;
            std::transform(list.begin(), list.end(), list.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            for (std::size_t at = 0; at < list.size();) {
                const std::size_t end = std::min(list.find(' ', at), list.size());
                claims = claims || list.compare(at, end - at, ext) == 0;
                at = end + 1;
            }
        }
        if (claims)
            ++kept;
        else
            others.push_back(importer.GetImporter(i));
    }
    if (kept == 0)
        throw Error(fmt::format("{}: '.{}' is not a model format Assimp reads (OBJ, glTF, GLB, Collada, PLY, STL, ...)",
                                what, ext));
    for (Assimp::BaseImporter* other : others) {
        importer.UnregisterLoader(other);
        delete other;  // unregistered loaders are the caller's to delete (Importer.hpp)
    }
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void checkImported(const aiScene* ai, const Assimp::Importer& importer, const std::string& what) {
    if (!ai || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode)
        throw Error(fmt::format("{}: cannot import ({})", what,
                                *importer.GetErrorString() ? importer.GetErrorString()
                                                           : "no complete scene: no meshes, or an unsupported file"));
}

// The imported scene as ours. `dir` is where external textures are looked up; null for a model
// read from memory, which can only use embedded textures.
Scene convert(const aiScene* ai, const std::string& what, const fs::path* dir, double scale) {
    Scene s;
    std::map<std::string, int> layerOf;  // texture path -> layer
    for (unsigned i = 0; i < ai->mNumMaterials; ++i) {
        const aiMaterial* m = ai->mMaterials[i];
        Material mat;
        aiString name;
        if (m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
        aiColor3D diffuse;
        const bool hasDiffuse = m->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS;
        aiString tex;
        if (m->GetTextureCount(aiTextureType_DIFFUSE) > 0 &&
            m->GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS) {
            const std::string texName = tex.C_Str();
            auto found = layerOf.find(texName);
            if (found == layerOf.end()) {
                ImageRgba8 img;
                if (const aiTexture* embedded = ai->GetEmbeddedTexture(texName.c_str())) {
                    if (embedded->mHeight != 0)
                        throw Error(
                            fmt::format("{}: embedded texture '{}' is uncompressed (unsupported)", what, texName));
                    img = decodeTexture(reinterpret_cast<const std::uint8_t*>(embedded->pcData), embedded->mWidth,
                                        texName);
                } else {
                    if (!dir)
                        throw Error(
                            fmt::format("{}: material '{}' names an external texture '{}' (a model read from "
                                        "memory can only use embedded textures)",
                                        what, mat.name, texName));
                    std::string rel = texName;
                    std::replace(rel.begin(), rel.end(), '\\', '/');
                    const fs::path file = *dir / rel;
                    if (!fs::is_regular_file(file))
                        throw Error(fmt::format("{}: material '{}' names texture '{}', not found at {}", what, mat.name,
                                                texName, file.string()));
                    const auto bytes = io::readFile(file.string(), io::kMaxImageFileBytes, "texture");
                    img = decodeTexture(bytes.data(), bytes.size(), file.string());
                }
                found = layerOf.emplace(texName, addTextureLayer(s.textures, img)).first;
            }
            mat.textureLayer = found->second;
        }
        // The file's diffuse colour; without one 0.8, or 1 for a textured material (the texture as is).
        mat.diffuse =
            hasDiffuse ? glm::vec3(diffuse.r, diffuse.g, diffuse.b) : glm::vec3(mat.textureLayer >= 0 ? 1.0f : 0.8f);
        s.materials.push_back(mat);
    }
    if (s.materials.empty()) s.materials.push_back({"default", glm::vec3(0.8f), -1});
    for (unsigned mi = 0; mi < ai->mNumMeshes; ++mi) {
        const aiMesh* mesh = ai->mMeshes[mi];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const auto base = std::uint32_t(s.vertices.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            Vertex vx;
            const aiVector3D& p = mesh->mVertices[v];
            vx.position = glm::vec3(glm::dvec3(p.x, p.y, p.z) * scale);
            if (!std::isfinite(vx.position.x) || !std::isfinite(vx.position.y) || !std::isfinite(vx.position.z))
                throw Error(fmt::format("{}: vertex {} of mesh {} has a non-finite position ({}, {}, {}) x scale {}",
                                        what, v, mi, p.x, p.y, p.z, scale));
            if (mesh->mNormals) vx.normal = {mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z};
            // A missing, zero or non-finite normal (a degenerate face's) becomes +y.
            const float len = glm::length(vx.normal);
            if (!(len > 0.0f) || !std::isfinite(len)) vx.normal = {0, 1, 0};
            vx.normal = glm::normalize(vx.normal);
            if (mesh->mTextureCoords[0]) vx.uv = {mesh->mTextureCoords[0][v].x, mesh->mTextureCoords[0][v].y};
            if (!std::isfinite(vx.uv.x) || !std::isfinite(vx.uv.y))
                throw Error(fmt::format("{}: vertex {} of mesh {} has a non-finite texture coordinate", what, v, mi));
            vx.material = mesh->mMaterialIndex < s.materials.size() ? mesh->mMaterialIndex : 0;
            s.vertices.push_back(vx);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (int k = 0; k < 3; ++k) s.indices.push_back(base + face.mIndices[k]);
        }
    }
    if (s.indices.empty()) throw Error(fmt::format("{}: no triangles", what));
    return s;
}

// The mesh part of a scene (what the importer child makes) as bytes and back: vertices,
// indices, materials, textures. Lights, views and the name are the parent's.
class ByteWriter {
public:
    void raw(const void* data, std::size_t size) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        out.insert(out.end(), p, p + size);
    }
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        raw(&v, sizeof(T));
    }
    template <class T>
    void putVector(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        put(std::uint64_t(v.size()));
        raw(v.data(), v.size() * sizeof(T));
    }
    std::vector<std::uint8_t> out;
};

class ByteReader {
public:
    explicit ByteReader(const std::vector<std::uint8_t>& in) : in_(in) {}
    void raw(void* data, std::size_t size) {
        if (size > in_.size() - at_) throw Error("model import: the importer's result is truncated");
        if (size) std::memcpy(data, in_.data() + at_, size);
        at_ += size;
    }
    template <class T>
    T get() {
        T v;
        raw(&v, sizeof(T));
        return v;
    }
    template <class T>
    std::vector<T> getVector() {
        const auto n = get<std::uint64_t>();
        if (n > (in_.size() - at_) / sizeof(T)) throw Error("model import: the importer's result is truncated");
        std::vector<T> v(n);
        raw(v.data(), n * sizeof(T));
        return v;
    }
    bool done() const { return at_ == in_.size(); }

private:
    const std::vector<std::uint8_t>& in_;
    std::size_t at_ = 0;
};

std::vector<std::uint8_t> meshBytes(const Scene& s) {
    ByteWriter b;
    b.putVector(s.vertices);
    b.putVector(s.indices);
    b.put(std::uint64_t(s.materials.size()));
    for (const Material& m : s.materials) {
        b.putVector(std::vector<char>(m.name.begin(), m.name.end()));
        b.put(m.diffuse);
        b.put(m.textureLayer);
    }
    b.put(s.textures.size);
    b.put(std::uint64_t(s.textures.layers.size()));
    for (const auto& levels : s.textures.layers) {
        b.put(std::uint64_t(levels.size()));
        for (const ImageRgba8& img : levels) {
            b.put(img.width());
            b.put(img.height());
            b.raw(img.data(), std::size_t(img.width()) * std::size_t(img.height()) * sizeof(Rgba8));
        }
    }
    return std::move(b.out);
}

Scene sceneFromMeshBytes(const std::vector<std::uint8_t>& bytes) {
    ByteReader r(bytes);
    Scene s;
    s.vertices = r.getVector<Vertex>();
    s.indices = r.getVector<std::uint32_t>();
    const auto materials = r.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < materials; ++i) {
        Material m;
        const auto name = r.getVector<char>();
        m.name.assign(name.begin(), name.end());
        m.diffuse = r.get<glm::vec3>();
        m.textureLayer = r.get<int>();
        s.materials.push_back(std::move(m));
    }
    s.textures.size = r.get<int>();
    const auto layers = r.get<std::uint64_t>();
    for (std::uint64_t l = 0; l < layers; ++l) {
        std::vector<ImageRgba8> levels(r.get<std::uint64_t>());
        for (ImageRgba8& img : levels) {
            const int w = r.get<int>(), h = r.get<int>();
            checkDimensions(w, h, "model import: a texture level");
            img = ImageRgba8(w, h);
            r.raw(img.data(), std::size_t(w) * std::size_t(h) * sizeof(Rgba8));
        }
        s.textures.layers.push_back(std::move(levels));
    }
    if (!r.done()) throw Error("model import: the importer's result has trailing bytes");
    return s;
}

// Lights, the default view and the name, after the mesh part (from a child or not).
Scene finish(Scene s, const std::string& name) {
    s.name = name;
    s.validate();
    s.lights.push_back({Light::Type::Directional, glm::normalize(glm::vec3(-0.4f, -1.0f, -0.5f)), glm::vec3(1.0f)});
    s.views.emplace_back("default", defaultView(s));
    return s;
}

void checkScale(double scale, const std::string& what) {
    if (!(scale > 0.0 && std::isfinite(scale))) throw Error(fmt::format("{}: scale {} must be > 0", what, scale));
}

}  // namespace

Scene importModel(const std::string& path, double scale) {
    const std::string what = fmt::format("model '{}'", path);
    checkScale(scale, what);
    if (!fs::is_regular_file(path)) throw Error(fmt::format("{}: no such file", what));
    const std::string ext = lowerExtension(path);
    if (ext.empty()) throw Error(fmt::format("{}: no file extension (it names the format: .obj, .gltf, ...)", what));
    // Assimp and stb_image parse the file and its textures in a child process (isolate.hpp).
    const auto bytes = runIsolated(
        [&] {
            Assimp::Importer importer;
            configure(importer, ext, what);
            const aiScene* ai = importer.ReadFile(path, kImportFlags);
            checkImported(ai, importer, what);
            const fs::path dir = fs::path(path).parent_path();
            return meshBytes(convert(ai, what, &dir, scale));
        },
        what, "model importer (Assimp)");
    return finish(sceneFromMeshBytes(bytes), fs::path(path).stem().string());
}

Scene importModelFromMemory(std::span<const std::uint8_t> bytes, const std::string& format, const std::string& name,
                            double scale) {
    const std::string what = fmt::format("model '{}'", name);
    checkScale(scale, what);
    if (bytes.empty()) throw Error(fmt::format("{}: no bytes", what));
    if (format.empty() || format.size() > 7 ||
        format.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos)
        throw Error(fmt::format("{}: format '{}' must be a file extension such as obj, gltf or glb", what, format));
    const auto mesh = runIsolated(
        [&] {
            Assimp::Importer importer;
            configure(importer, format, what);
            // Assimp picks the importer from the hint as it would from a file extension; a
            // model read from memory cannot open other files (an OBJ's .mtl, a glTF's
            // external buffers).
            const aiScene* ai = importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, format.c_str());
            checkImported(ai, importer, what);
            return meshBytes(convert(ai, what, nullptr, scale));
        },
        what, "model importer (Assimp)");
    return finish(sceneFromMeshBytes(mesh), name);
}

namespace {
Scene sceneFromJson(const Json& j, const std::string& path, const ModelLoader& loadModel);
}  // namespace

Scene parseSceneFile(std::string_view text, const std::string& path, const ModelLoader& loadModel) {
    Json j;
    try {
        j = Json::parse(text.begin(), text.end());
    } catch (const std::exception& e) {
        throw Error(fmt::format("scene file '{}': not valid JSON ({})", path, e.what()));
    }
    // Every value is read through the checked getters below, which name the file and the
    // field as a JSON pointer; a library type error would still not escape raw.
    try {
        return sceneFromJson(j, path, loadModel);
    } catch (const nlohmann::json::exception& e) {
        throw Error(fmt::format("scene file '{}': a value of the wrong type ({})", path, e.what()));
    }
}

Scene loadSceneFile(const std::string& path) {
    const auto bytes = io::readFile(path, io::kMaxJsonFileBytes, "JSON");
    return parseSceneFile(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path,
                          importModel);
}

namespace {

// A number at `pointer` (a JSON pointer for the message), or `fallback` where it is absent.
double numberAt(const Json& o, const char* key, double fallback, const std::string& where, const std::string& pointer) {
    if (!o.contains(key)) return fallback;
    if (!o[key].is_number()) throw Error(fmt::format("{}: {} must be a number", where, pointer));
    return o[key].get<double>();
}

// Unknown keys of a view or a light are errors, as at the top level (docs/render.md).
void onlyKeys(const Json& o, std::initializer_list<const char*> known, const std::string& what) {
    for (auto it = o.begin(); it != o.end(); ++it) {
        bool ok = false;
        for (const char* k : known) ok = ok || it.key() == k;
        if (!ok) {
            std::string list;
            for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
            throw Error(fmt::format("{}: unknown key '{}' ({})", what, it.key(), list));
        }
    }
}

Scene sceneFromJson(const Json& j, const std::string& path, const ModelLoader& loadModel) {
    if (!j.is_object()) throw Error(fmt::format("scene file '{}': must be a JSON object", path));
    for (auto it = j.begin(); it != j.end(); ++it)
        if (it.key() != "model" && it.key() != "scale" && it.key() != "ambient" && it.key() != "background" &&
            it.key() != "lights" && it.key() != "views")
            throw Error(
                fmt::format("scene file '{}': unknown key '{}' (model, scale, ambient, background, lights, views)",
                            path, it.key()));
    if (!j.contains("model") || !j["model"].is_string())
        throw Error(fmt::format("scene file '{}': 'model' (a path) is required", path));
    const double scale = numberAt(j, "scale", 1.0, fmt::format("scene file '{}'", path), "/scale");
    fs::path model = j["model"].get<std::string>();
    if (model.is_relative()) model = fs::path(path).parent_path() / model;
    Scene s = loadModel(model.string(), scale);
    s.name = fs::path(path).stem().string();
    const std::string where = fmt::format("scene file '{}'", path);
    if (j.contains("ambient")) s.ambient = vec3Of(j["ambient"], where + ": 'ambient'");
    if (j.contains("background")) s.background = vec3Of(j["background"], where + ": 'background'");
    if (j.contains("lights")) {
        s.lights.clear();
        if (!j["lights"].is_array()) throw Error(where + ": 'lights' must be an array");
        for (std::size_t li = 0; li < j["lights"].size(); ++li) {
            const Json& l = j["lights"][li];
            if (!l.is_object()) throw Error(fmt::format("{}: /lights/{} must be an object", where, li));
            onlyKeys(l, {"type", "direction", "position", "color"}, fmt::format("{}: /lights/{}", where, li));
            if (l.contains("type") && !l["type"].is_string())
                throw Error(fmt::format("{}: /lights/{}/type must be a string", where, li));
            const std::string type = l.value("type", "");
            Light light;
            if (type == "directional") {
                light.type = Light::Type::Directional;
                light.vector = vec3Of(l.value("direction", Json()), where + ": a directional light's 'direction'");
                if (!(glm::length(light.vector) > 0.0f))
                    throw Error(where + ": a directional light's direction is zero");
                light.vector = glm::normalize(light.vector);
            } else if (type == "point") {
                light.type = Light::Type::Point;
                light.vector = vec3Of(l.value("position", Json()), where + ": a point light's 'position'");
            } else {
                throw Error(fmt::format("{}: light type '{}' (directional, point)", where, type));
            }
            light.color = vec3Of(l.value("color", Json::array({1, 1, 1})), where + ": a light's 'color'");
            s.lights.push_back(light);
        }
    }
    if (j.contains("views")) {
        if (!j["views"].is_object() || j["views"].empty()) throw Error(where + ": 'views' must be a non-empty object");
        s.views.clear();
        for (auto it = j["views"].begin(); it != j["views"].end(); ++it) {
            const Json& v = it.value();
            const std::string what = fmt::format("{}: view '{}'", where, it.key());
            if (!v.is_object()) throw Error(fmt::format("{}: /views/{} must be an object", where, it.key()));
            onlyKeys(v, {"eye", "target", "up", "fov_y_deg", "z_near", "z_far"}, what);
            View view;
            view.eye = glm::dvec3(vec3Of(v.value("eye", Json()), what + " 'eye'"));
            view.target = glm::dvec3(vec3Of(v.value("target", Json()), what + " 'target'"));
            if (v.contains("up")) view.up = glm::dvec3(vec3Of(v["up"], what + " 'up'"));
            const std::string at = "/views/" + it.key() + "/";
            view.fovYDeg = numberAt(v, "fov_y_deg", view.fovYDeg, where, at + "fov_y_deg");
            view.zNear = numberAt(v, "z_near", view.zNear, where, at + "z_near");
            if (v.contains("z_far") && !v["z_far"].is_null())
                view.zFar = numberAt(v, "z_far", view.zFar, where, at + "z_far (a number, or null for infinity)");
            try {  // the renderer's own checks (camera.cpp), here so that a bad view fails on load
                (void)cameraSetup(view, 16, 16, 0);
            } catch (const Error& e) {
                throw Error(fmt::format("{}: {}", what, e.what()));
            }
            s.views.emplace_back(it.key(), view);
        }
    }
    return s;
}

}  // namespace

}  // namespace ssfx::scene
