// Fuzzes the camera JSON reader: any text must give a valid camera or throw ssfx::Error.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "ssfx/core/error.hpp"
#include "ssfx/io/camera.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        ssfx::io::CameraBuffer buffer;
        const ssfx::Camera c =
            ssfx::io::parseCameraJson(std::string(reinterpret_cast<const char*>(data), size), "fuzz", &buffer);
        if (!(c.zNear < 0) || !(c.zFar < c.zNear) || !(c.fovY > 0)) __builtin_trap();  // validated on the way
    } catch (const ssfx::Error&) {
    }
    return 0;
}
