#include "tests/support/test_support.hpp"

#include <cstdlib>
#include <filesystem>

#include "ssfx/aa/registry.hpp"

namespace ssfx {
void PrintTo(const MethodInfo* m, std::ostream* os) { *os << (m ? m->id : "null"); }
}  // namespace ssfx

namespace ssfx::test {

ImageRgba8 ascii(const std::vector<std::string>& rows) {
    ImageRgba8 img(int(rows[0].size()), int(rows.size()));
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const char c = rows[std::size_t(y)].at(std::size_t(x));
            std::uint8_t v = 255;
            if (c == '#')
                v = 0;
            else if (c >= '0' && c <= '9')
                v = std::uint8_t((c - '0') * 28);
            img(x, y) = {v, v, v, 255};
        }
    return img;
}

ImageRgba8 solid(int w, int h, Rgba8 c) { return ImageRgba8(w, h, c); }

ImageRgba8 noise(int w, int h, unsigned seed) {
    ImageRgba8 img(w, h);
    unsigned s = seed * 2654435761u + 1;
    auto next = [&] {
        s ^= s << 13, s ^= s >> 17, s ^= s << 5;
        return std::uint8_t(s >> 8);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img(x, y) = {next(), next(), next(), next()};
    return img;
}

std::optional<std::string> sharedDir(const std::string& sub) {
    const std::filesystem::path p = std::filesystem::path(SSFX_SHARED_DIR) / sub;
    if (std::filesystem::is_directory(p)) return p.string();
    return std::nullopt;
}

int maxAbsDiff(const ImageRgba8& a, const ImageRgba8& b) {
    int m = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const Rgba8 p = a(x, y), q = b(x, y);
            m = std::max({m, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
        }
    return m;
}

std::string outDir() {
    std::filesystem::create_directories(SSFX_TEST_OUT_DIR);
    return SSFX_TEST_OUT_DIR;
}

}  // namespace ssfx::test
