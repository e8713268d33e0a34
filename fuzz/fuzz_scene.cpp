// Fuzzes the scene-file reader (JSON): any text must give a scene whose every view the
// renderer accepts, or throw ssfx::Error. The model it names is not read (a fixed
// procedural scene stands in), so that the run stays inside the parser and never opens files;
// model import has its own targets (fuzz_obj, fuzz_gltf).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ssfx/core/error.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const ssfx::scene::Scene model = ssfx::scene::cornellBox();
    try {
        const ssfx::scene::Scene s =
            ssfx::scene::parseSceneFile(std::string_view(reinterpret_cast<const char*>(data), size), "/fuzz/scene.json",
                                        [](const std::string&, double scale) {
                                            if (!(scale > 0.0)) throw ssfx::Error("scale");  // importModel's own check
                                            return model;
                                        });
        if (s.views.empty() || s.lights.empty()) __builtin_trap();
        for (const auto& [name, view] : s.views) (void)ssfx::scene::cameraSetup(view, 16, 16, 0);  // must not throw
    } catch (const ssfx::Error&) {
    }
    return 0;
}
