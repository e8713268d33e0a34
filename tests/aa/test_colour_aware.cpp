// The opt-in colour-aware contrast (chromaWeight, spec ppaa.md section 4).
#include <gtest/gtest.h>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/color.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {

const char* kLumaMethods[] = {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p"};

MethodSettings chroma(double k) {
    MethodSettings s;
    s.params = {{"chromaWeight", k}};
    return s;
}

// A pure-green disc on the grey of (almost) the same luma: sqrt(0.587) vs sqrt(150/255).
ImageRgba8 greenOnGrey(int size) {
    ImageRgba8 img(size, size, Rgba8{150, 150, 150, 255});
    const double c = size / 2.0, r = size / 3.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if ((x + 0.5 - c) * (x + 0.5 - c) + (y + 0.5 - c) * (y + 0.5 - c) < r * r) img(x, y) = {0, 255, 0, 255};
    return img;
}

}  // namespace

TEST(ColourAware, EdgeLumaIsLumaForGreysAndWithZeroWeight) {
    const Rgb grey{0.4f, 0.4f, 0.4f}, green{0.0f, 1.0f, 0.0f};
    EXPECT_EQ(edgeLuma(grey, 0.7f), luma(grey));
    EXPECT_EQ(edgeLuma(green, 0.0f), luma(green));
    EXPECT_FLOAT_EQ(edgeLuma(green, 0.5f), luma(green) + 0.5f);
}

TEST(ColourAware, DefaultMethodsMissTheGreenOnGreyEdge) {
    // The limitation itself: with the paper's luma, the disc's edge is below the threshold.
    const auto img = greenOnGrey(48);
    for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
        const auto out = methodById(id).run(img.view(), {}, {});
        EXPECT_EQ(out, img) << id;
    }
}

TEST(ColourAware, FindsTheGreenOnGreyEdge) {
    const auto img = greenOnGrey(48);
    for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
        const auto out = methodById(id).run(img.view(), chroma(0.5), {});
        int changed = 0, mixed = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                changed += !(out(x, y) == img(x, y));
                // A blend of green and grey has red = blue strictly between 0 and 150.
                mixed += out(x, y).r > 0 && out(x, y).r < 150;
            }
        EXPECT_GT(changed, 20) << id;
        EXPECT_GT(mixed, 20) << id;
    }
}

TEST(ColourAware, GreyImagesAreUnaffected) {
    // Chroma is 0 for greys: any weight gives the default output, bit for bit.
    const ImageRgba8 grey = test::noise(61, 47, 7);
    ImageRgba8 g(61, 47);
    for (int y = 0; y < 47; ++y)
        for (int x = 0; x < 61; ++x) {
            const std::uint8_t v = grey(x, y).g;
            g(x, y) = {v, v, v, grey(x, y).a};
        }
    for (const char* id : kLumaMethods) {
        const MethodInfo& m = methodById(id);
        ImageRgba8 in = g;
        if (m.inputScale == 2) in = ImageRgba8(122, 94, Rgba8{90, 90, 90, 255});
        EXPECT_EQ(m.run(in.view(), chroma(2.0), {}), m.run(in.view(), {}, {})) << id;
    }
}

TEST(ColourAware, DeterministicAcrossThreadsAndRejectsBadWeights) {
    const auto img = test::noise(70, 53, 3);
    for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
        const MethodInfo& m = methodById(id);
        EXPECT_EQ(m.run(img.view(), chroma(1.0), Exec{1}), m.run(img.view(), chroma(1.0), Exec{4})) << id;
        EXPECT_EQ(m.run(img.view(), chroma(1.0), {}), m.reference(img.view(), chroma(1.0), {})) << id;
        EXPECT_THROW(m.run(img.view(), chroma(-0.1), {}), Error) << id;
        EXPECT_THROW(m.run(img.view(), chroma(4.5), {}), Error) << id;
    }
}
