// Fuzzes model import through Assimp from memory, in the format SSFX_FUZZ_FORMAT ("obj" for
// fuzz_obj, "gltf" for fuzz_gltf): any bytes must give a valid scene (Scene::validate passes,
// at least one triangle) or throw ssfx::Error. The import runs in a child process
// (core/isolate.hpp), so an importer that crashes is an ssfx::Error too.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "ssfx/core/error.hpp"
#include "ssfx/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const ssfx::scene::Scene s =
            ssfx::scene::importModelFromMemory(std::span(data, size), SSFX_FUZZ_FORMAT, "fuzz");
        if (s.triangleCount() == 0) __builtin_trap();
        s.validate();  // throws ssfx::Error: the import let an invalid scene through
    } catch (const ssfx::Error& e) {
        if (std::string_view(e.what()).starts_with("scene '")) __builtin_trap();  // validate() failed after import
    }
    return 0;
}
