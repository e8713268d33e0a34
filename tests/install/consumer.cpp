// A user of the installed library: anti-alias a small drawing with ddaa2.
#include <ssfx/aa/ddaa.hpp>
#include <ssfx/aa/registry.hpp>

#include <cstdio>

int main() {
    ssfx::ImageRgba8 img(16, 16, ssfx::Rgba8{255, 255, 255, 255});
    for (int i = 0; i < 16; ++i) img(i, i / 2) = {0, 0, 0, 255};
    const auto out = ssfx::aa::ddaa2(img.view());
    const bool changed = !(out == img);
    std::printf("consumer: %zu methods, ddaa2 %s the image\n", ssfx::methods().size(), changed ? "changed" : "kept");
    return changed ? 0 : 1;
}
