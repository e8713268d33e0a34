// A user of the installed renderer and adaptive supersampling libraries: build a scene, its
// camera and the dither order (no Vulkan device needed).
#include <ssfx/deferred/adaptive.hpp>
#include <ssfx/scene/camera.hpp>
#include <ssfx/scene/scene.hpp>

#include <cstdio>

int main() {
    const auto scene = ssfx::scene::cornellBox();
    const auto cam = ssfx::scene::cameraSetup(scene.view("front"), 64, 64, 8);
    const auto order = ssfx::deferred::ditherOrder(4);
    std::printf("consumer_render: %zu triangles, buffer %dx%d, %zu samples in dither order\n", scene.triangleCount(),
                cam.bufferWidth(), cam.bufferHeight(), order.size());
    return scene.triangleCount() == 34 && cam.bufferWidth() == 80 && order.size() == 16 ? 0 : 1;
}
