// Scenes without the GPU: camera matrices, the procedural scenes, Assimp import of OBJ and
// glTF files written here, scene files, and their errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <span>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/io/camera.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/scene.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx::test {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(outDir()) / "render" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Clip-space depth of camera-space z through the projection.
double clipDepth(const glm::dmat4& p, double z) {
    const glm::dvec4 c = p * glm::dvec4(0.0, 0.0, z, 1.0);
    return c.z / c.w;
}

TEST(RenderCamera, ProjectionMapsNearToZeroAndFarToOne) {
    const auto finite = scene::perspective(1.0, 1.5, 0.2, 50.0);
    EXPECT_NEAR(clipDepth(finite, -0.2), 0.0, 1e-15);
    EXPECT_NEAR(clipDepth(finite, -50.0), 1.0, 1e-15);
    const auto infinite = scene::perspective(1.0, 1.5, 0.2, INFINITY);
    EXPECT_NEAR(clipDepth(infinite, -0.2), 0.0, 1e-15);
    EXPECT_NEAR(clipDepth(infinite, -1e12), 1.0, 1e-12);
    // It is the inverse of the SAO reconstruction (sao.md eq. 2) for both planes.
    Camera cam;
    cam.zNear = -0.2;
    cam.zFar = -50.0;
    for (double z : {-0.3, -1.0, -7.5, -49.0}) EXPECT_NEAR(clipDepth(finite, z), ao::zToDepth(z, cam), 1e-14);
    cam.zFar = -INFINITY;
    for (double z : {-0.3, -1.0, -7.5, -1000.0}) EXPECT_NEAR(clipDepth(infinite, z), ao::zToDepth(z, cam), 1e-14);
    // y down: a point above the axis lands in the upper half (y_ndc < 0).
    const glm::dvec4 up = finite * glm::dvec4(0.0, 1.0, -5.0, 1.0);
    EXPECT_LT(up.y / up.w, 0.0);
    EXPECT_THROW(scene::perspective(1.0, 1.0, 0.0, 10.0), Error);
    EXPECT_THROW(scene::perspective(1.0, 1.0, 1.0, 1.0), Error);
    EXPECT_THROW(scene::perspective(4.0, 1.0, 1.0, 10.0), Error);
}

TEST(RenderCamera, LookAtAndGuardBand) {
    scene::View v;
    v.eye = {1, 2, 3};
    v.target = {1, 2, -7};
    const auto view = scene::lookAt(v.eye, v.target, v.up);
    const glm::dvec4 t = view * glm::dvec4(1, 2, -7, 1);
    EXPECT_NEAR(t.x, 0.0, 1e-12);
    EXPECT_NEAR(t.y, 0.0, 1e-12);
    EXPECT_NEAR(t.z, -10.0, 1e-12);
    const auto s = scene::cameraSetup(v, 200, 100, 50);
    EXPECT_EQ(s.bufferWidth(), 300);
    EXPECT_EQ(s.bufferHeight(), 200);
    // Same pixel size: tan(fov'/2) / (h + 2g) = tan(fov/2) / h.
    EXPECT_NEAR(std::tan(s.camera.fovY / 2) / 200.0, std::tan(std::numbers::pi / 6) / 100.0, 1e-15);
    EXPECT_THROW(scene::lookAt({0, 0, 0}, {0, 5, 0}, {0, 1, 0}), Error);
    EXPECT_THROW(scene::cameraSetup(v, 0, 10), Error);
    EXPECT_THROW(scene::cameraSetup(v, 10, 10, -1), Error);
    // camera.json is readable by the AO tools.
    const Camera back = io::parseCameraJson(scene::cameraSetupJson(s), "camera.json");
    EXPECT_NEAR(back.fovY, s.camera.fovY, 1e-9);
    EXPECT_EQ(back.zNear, s.camera.zNear);
    EXPECT_TRUE(std::isinf(back.zFar));
}

TEST(RenderScenes, BuiltInScenesAreWellFormed) {
    const auto cornell = scene::cornellBox();
    EXPECT_NO_THROW(cornell.validate());
    EXPECT_EQ(cornell.triangleCount(), 34u);  // 5 walls (10) + two boxes (24)
    EXPECT_EQ(cornell.materials.size(), 3u);
    const auto a = scene::atrium();
    EXPECT_NO_THROW(a.validate());
    EXPECT_GT(a.triangleCount(), 10000u);
    EXPECT_GE(a.materials.size(), 6u);
    ASSERT_EQ(a.textures.layers.size(), 2u);  // checker, brick
    EXPECT_EQ(a.textures.size, 256);
    EXPECT_EQ(a.textures.levelCount(), 9);  // 256 .. 1
    EXPECT_GE(a.views.size(), 4u);
    const auto [lo, hi] = a.bounds();
    EXPECT_NEAR(lo.x, -10.0f, 1e-4f);
    EXPECT_NEAR(hi.x, 10.0f, 1e-4f);
    EXPECT_THROW(a.view("nope"), Error);
    EXPECT_THROW(scene::builtinScene("nope"), Error);
    // Mips are 2x2 box filters: the checker's 1x1 level is its mean.
    const auto& top = a.textures.layers[0].back()(0, 0);
    EXPECT_NEAR(int(top.r), (225 + 40) / 2, 1);
}

TEST(RenderImport, ObjWithMaterialAndTexture) {
    const fs::path dir = scratch("obj");
    ImageRgba8 tex(4, 2, Rgba8{10, 200, 30, 255});
    tex(0, 0) = {255, 0, 0, 255};
    io::writePng((dir / "tex.png").string(), tex.view());
    writeText(dir / "m.mtl", "newmtl red\nKd 0.5 0.25 1\nnewmtl tex\nKd 1 1 1\nmap_Kd tex.png\n");
    writeText(dir / "m.obj",
              "mtllib m.mtl\n"
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
              "usemtl red\nf 1/1 2/2 3/3\n"
              "usemtl tex\nf 1/1 3/3 4/4\n");
    const auto s = scene::importModel((dir / "m.obj").string(), 2.0);
    EXPECT_EQ(s.triangleCount(), 2u);
    ASSERT_EQ(s.textures.layers.size(), 1u);
    EXPECT_EQ(s.textures.size, 4);  // power of two covering 4x2
    int textured = 0;
    for (const auto& m : s.materials) {
        if (m.name == "red") {
            EXPECT_EQ(m.diffuse, glm::vec3(0.5f, 0.25f, 1.0f));
        }
        textured += m.textureLayer == 0;
    }
    EXPECT_EQ(textured, 1);
    const auto [lo, hi] = s.bounds();
    EXPECT_EQ(hi, glm::vec3(2.0f, 2.0f, 0.0f));  // scaled
    // OBJ's v = 0 is the image's bottom; ours is the top row: v is flipped.
    for (const auto& v : s.vertices)
        if (v.position == glm::vec3(0.0f)) {
            EXPECT_EQ(v.uv.y, 1.0f);
        }
    // Normals generated where the file has none: the quad lies in z = 0.
    for (const auto& v : s.vertices) EXPECT_NEAR(std::abs(v.normal.z), 1.0f, 1e-5f);
    EXPECT_EQ(s.views.at(0).first, "default");
}

TEST(RenderImport, GltfWithEmbeddedBuffer) {
    const fs::path dir = scratch("gltf");
    // One triangle: three float3 positions (36 bytes) and three uint16 indices (6 bytes),
    // base64 in a data URI. Bytes: (0,0,0), (1,0,0), (0,1,0); indices 0 1 2.
    writeText(dir / "t.gltf", R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "translation": [0, 0, -3]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})");
    const auto s = scene::importModel((dir / "t.gltf").string());
    ASSERT_EQ(s.triangleCount(), 1u);
    const auto [lo, hi] = s.bounds();
    EXPECT_EQ(lo, glm::vec3(0.0f, 0.0f, -3.0f));  // the node's transform is applied
    EXPECT_EQ(hi, glm::vec3(1.0f, 1.0f, -3.0f));
    EXPECT_NEAR(s.materials.at(s.vertices[0].material).diffuse.y, 0.4f, 1e-6f);
}

TEST(RenderImport, SceneFileNamesModelLightsAndViews) {
    const fs::path dir = scratch("scenefile");
    fs::create_directories(dir / "models");
    writeText(dir / "models" / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeText(dir / "s.json", R"({"model": "models/tri.obj", "scale": 3, "ambient": [0.1, 0.2, 0.3],
      "lights": [{"type": "point", "position": [0, 2, 0], "color": [5, 5, 5]}],
      "views": {"b": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "a": {"eye": [1, 1, 5], "target": [0, 0, 0], "z_far": 30}}})");
    const auto s = scene::loadScene((dir / "s.json").string());
    EXPECT_EQ(s.name, "s");
    EXPECT_EQ(s.bounds().second, glm::vec3(3.0f, 3.0f, 0.0f));
    EXPECT_EQ(s.ambient, glm::vec3(0.1f, 0.2f, 0.3f));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, scene::Light::Type::Point);
    ASSERT_EQ(s.views.size(), 2u);
    EXPECT_EQ(s.views[0].first, "b");  // the file's order
    EXPECT_EQ(s.view("a").zFar, 30.0);
    EXPECT_TRUE(std::isinf(s.view("b").zFar));
}

TEST(RenderImport, BadInputsGiveClearErrors) {
    const fs::path dir = scratch("bad");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "missing.obj").string()); }).find("no such file"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { scene::loadScene("nonexistent-builtin"); }).find("not a built-in scene"),
              std::string::npos);
    writeText(dir / "corrupt.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [ {\"primitives\": [");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "corrupt.gltf").string()); }).find("corrupt.gltf"),
              std::string::npos);
    writeText(dir / "garbage.obj", "this is not an OBJ file\n\x01\x02\x03");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "garbage.obj").string()); }).find("garbage.obj"),
              std::string::npos);
    writeText(dir / "notex.mtl", "newmtl t\nmap_Kd missing.png\n");
    writeText(dir / "notex.obj", "mtllib notex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "notex.obj").string()); }).find("missing.png"),
              std::string::npos);
    writeText(dir / "badtex.png", "not a png");
    writeText(dir / "badtex.mtl", "newmtl t\nmap_Kd badtex.png\n");
    writeText(dir / "badtex.obj", "mtllib badtex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "badtex.obj").string()); }).find("cannot decode"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "badtex.obj").string(), -1.0); }).find("scale"),
              std::string::npos);
    writeText(dir / "s1.json", R"({"model": "tri.obj", "camera": 1})");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "s1.json").string()); }).find("unknown key 'camera'"),
              std::string::npos);
    writeText(dir / "s2.json", R"({"scale": 1})");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "s2.json").string()); }).find("'model'"), std::string::npos);
    writeText(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeText(dir / "s3.json", R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0], "target": [0, 0, 0]}}})");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "s3.json").string()); }).find("'eye'"), std::string::npos);
    writeText(dir / "s4.json", R"({"model": "tri.obj", "lights": [{"type": "spot"}]})");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "s4.json").string()); }).find("spot"), std::string::npos);
    writeText(dir / "s5.json", "{not json");
    EXPECT_NE(errorOf([&] { scene::loadScene((dir / "s5.json").string()); }).find("not valid JSON"), std::string::npos);
    // Wrong JSON types: the file and the field (a JSON pointer), never a raw library message;
    // unknown keys inside views and lights are errors as at the top level.
    const std::pair<const char*, const char*> typeErrors[] = {
        {R"({"model": "tri.obj", "scale": "big"})", "/scale"},
        {R"({"model": "tri.obj", "lights": [5]})", "/lights/0"},
        {R"({"model": "tri.obj", "views": {"v": 5}})", "/views/v"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": "60"}}})",
         "/views/v/fov_y_deg"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "z_far": "inf"}}})",
         "/views/v/z_far"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov": 60}}})",
         "unknown key 'fov'"},
        {R"({"model": "tri.obj", "lights": [{"type": "point", "position": [0, 1, 0], "power": 3}]})",
         "unknown key 'power'"},
        // Views are checked on load (the renderer's own checks), not when first rendered.
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 200}}})",
         "view 'v': view: fov_y_deg 200"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 5]}}})", "same point"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "z_near": 0}}})", "z_near 0"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 5], "target": [0, 0, 0], "z_far": 0.05}}})",
         "z_far 0.05"},
        {R"({"model": "tri.obj", "views": {"v": {"eye": [0, 0, 1e300], "target": [0, 0, 0]}}})",
         "'eye' must be finite"},
    };
    // A glTF with no meshes: says what is missing (Assimp gives no text of its own).
    writeText(dir / "empty.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "scene": 0})");
    const std::string empty = errorOf([&] { scene::importModel((dir / "empty.gltf").string()); });
    EXPECT_NE(empty.find("empty.gltf"), std::string::npos) << empty;
    EXPECT_EQ(empty.find("()"), std::string::npos) << empty;
    // Files that crash Debian's Assimp 5.2.5 (found by fuzz_gltf): an error naming the file,
    // and this process lives on (the importer runs in a child process).
    for (const char* crasher : {"gltf-assimp-null-mime.gltf", "gltf-assimp-bvh-overread.gltf"}) {
        const fs::path file = fs::path(SSFX_SOURCE_DIR) / "fuzz" / "regressions" / crasher;
        const std::string m = errorOf([&] { scene::importModel(file.string()); });
        EXPECT_NE(m.find(std::string("model '") + file.string() + "'"), std::string::npos) << m;
        EXPECT_TRUE(m.find("stopped abnormally") != std::string::npos || m.find("cannot import") != std::string::npos)
            << m;
    }
    // The format is the extension's; none, or one that no importer claims, is refused.
    writeText(dir / "tri_noext", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "tri_noext").string()); }).find("no file extension"),
              std::string::npos);
    writeText(dir / "tri.xyzw", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(errorOf([&] { scene::importModel((dir / "tri.xyzw").string()); }).find("'.xyzw' is not a model format"),
              std::string::npos);
    writeText(dir / "inf.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(
        errorOf([&] { scene::importModel((dir / "inf.obj").string()); }).find("vertex 1 of mesh 0 has a non-finite"),
        std::string::npos);
    for (const auto& [text, field] : typeErrors) {
        writeText(dir / "s6.json", text);
        const std::string m = errorOf([&] { scene::loadScene((dir / "s6.json").string()); });
        EXPECT_NE(m.find("s6.json"), std::string::npos) << m;
        EXPECT_NE(m.find(field), std::string::npos) << text << " -> " << m;
        EXPECT_EQ(m.find("[json.exception"), std::string::npos) << m;
    }
}

TEST(RenderImport, ModelFromMemory) {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";
    const auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(obj.data()), obj.size());
    const auto s = scene::importModelFromMemory(bytes, "obj", "mem", 2.0);
    EXPECT_EQ(s.name, "mem");
    EXPECT_EQ(s.triangleCount(), 2u);
    EXPECT_EQ(s.bounds().second, glm::vec3(2.0f, 2.0f, 2.0f));
    // The same bytes from a file give the same scene.
    const fs::path dir = scratch("memory");
    writeText(dir / "mem.obj", obj);
    const auto fromFile = scene::importModel((dir / "mem.obj").string(), 2.0);
    ASSERT_EQ(fromFile.vertices.size(), s.vertices.size());
    for (std::size_t i = 0; i < fromFile.vertices.size(); ++i)
        EXPECT_EQ(fromFile.vertices[i].position, s.vertices[i].position);
    EXPECT_EQ(fromFile.indices, s.indices);
    // An external texture cannot be opened from memory: named, with the reason.
    const std::string textured = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0}], "images": [{"uri": "far.png"}],
      "buffers": [{"byteLength": 68, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8="}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                      {"buffer": 0, "byteOffset": 44, "byteLength": 24}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}]})";
    const std::string ext = errorOf([&] {
        scene::importModelFromMemory(std::span(reinterpret_cast<const std::uint8_t*>(textured.data()), textured.size()),
                                     "gltf", "texmem");
    });
    EXPECT_NE(ext.find("model 'texmem'"), std::string::npos) << ext;
    EXPECT_NE(ext.find("far.png"), std::string::npos) << ext;
    EXPECT_NE(ext.find("embedded"), std::string::npos) << ext;
    EXPECT_NE(errorOf([&] { scene::importModelFromMemory({}, "obj", "none"); }).find("no bytes"), std::string::npos);
    EXPECT_NE(errorOf([&] { scene::importModelFromMemory(bytes, "../x", "bad"); }).find("file extension"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { scene::importModelFromMemory(bytes, "obj", "neg", 0.0); }).find("scale"),
              std::string::npos);
    const std::string junk = "\x01\x02 not a model";
    EXPECT_NE(errorOf([&] {
                  scene::importModelFromMemory(
                      std::span(reinterpret_cast<const std::uint8_t*>(junk.data()), junk.size()), "gltf", "junk");
              }).find("model 'junk'"),
              std::string::npos);
}

TEST(RenderImport, SceneTextWithAnyModelLoader) {
    // The scene file's model path is resolved against the file's directory and handed to the
    // loader with the scale; everything else is the file's.
    std::string seen;
    double seenScale = 0;
    const auto loader = [&](const std::string& path, double scale) {
        seen = path;
        seenScale = scale;
        return scene::cornellBox();
    };
    const auto s = scene::parseSceneFile(R"({"model": "m/x.obj", "scale": 0.5,
        "views": {"v": {"eye": [0, 1, 4], "target": [0, 1, 0]}}})",
                                         "/some/dir/s.json", loader);
    EXPECT_EQ(fs::path(seen), fs::path("/some/dir/m/x.obj"));
    EXPECT_EQ(seenScale, 0.5);
    EXPECT_EQ(s.name, "s");
    ASSERT_EQ(s.views.size(), 1u);
    EXPECT_EQ(s.views[0].first, "v");
    EXPECT_THROW(scene::parseSceneFile("[1]", "/x.json", loader), Error);
}

TEST(RenderImport, SharedModelsLoad) {
    const auto assets = sharedDir("assets");
    if (!assets) GTEST_SKIP() << "../shared/assets is absent";
    const fs::path root = fs::path(SSFX_SOURCE_DIR) / "scenes";
    const auto sponza = scene::loadScene((root / "sponza.json").string());
    EXPECT_EQ(sponza.triangleCount(), 66447u);  // SOURCE.md
    const auto bunny = scene::loadScene((root / "bunny.json").string());
    EXPECT_EQ(bunny.triangleCount(), 69451u);
}

}  // namespace
}  // namespace ssfx::test
