// Every SIMD target compiled into the library (Highway's runtime dispatch: SSE4, AVX2,
// AVX-512, scalar... as this CPU supports) gives the scalar reference's bytes, for every
// registered method (STYLE.md section 4, after Highway's HWY_EXPORT_AND_TEST_P).
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "src/aa/ppaa_hooks.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {
struct ResetTargets {
    ~ResetTargets() { hwy::SetSupportedTargetsForTest(0); }
};
// Both texture encodings: the vector kernels read unorm texels as integer levels and sRGB
// texels as decoded floats (planes, reads and encode each have two forms).
std::vector<std::pair<const char*, MethodSettings>> encodings() {
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    return {{"unorm", {}}, {"srgb", srgb}};
}
}  // namespace

TEST(SimdTargets, EveryTargetEqualsTheReference) {
    const ResetTargets reset;
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        MethodSettings srgb;  // the sRGB-texture mode's vector parts (decoded luma rows, blur, the encode)
        srgb.params = {{"texture", 1}};
        for (const MethodInfo& m : methods()) {
            const int s = m.inputScale;
            // 300 px wide: chunks far from the borders take the contiguous plane reads too.
            for (const auto& in : {eval::syntheticScene(300, 40, s), test::noise(67 * s, 9 * s, 11)}) {
                EXPECT_EQ(m.run(in.view(), {}, {}), m.reference(in.view(), {}, {}))
                    << hwy::TargetName(target) << " " << m.id << " " << in.width() << "x" << in.height();
                if (m.id != "noaa") {
                    EXPECT_EQ(m.run(in.view(), srgb, {}), m.reference(in.view(), srgb, {}))
                        << hwy::TargetName(target) << " " << m.id << " texture=srgb " << in.width() << "x"
                        << in.height();
                }
            }
        }
    }
    std::printf("[simd] checked %zu targets:", targets.size());
    for (const std::int64_t t : targets) std::printf(" %s", hwy::TargetName(t));
    std::printf("\n");
}

// fxaa3d and ddaa store bytes straight from the reads' integer levels k (value k / 4080):
// ByteOfLevel and ByteOfMeanLevel replace the float quantisation of the scalar code. Both
// are claimed exact over their whole domain, so check all of it: every level, and every
// pair of levels (16.7 million), on every target.
TEST(SimdTargets, BytesFromLevelsEqualTheFloatQuantisation) {
    const ResetTargets reset;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        EXPECT_EQ(aa::detail::levelByteMismatches(), 0) << hwy::TargetName(target);
        EXPECT_EQ(aa::detail::meanLevelByteMismatches(), 0) << hwy::TargetName(target);
    }
}

// fxaa3c with a direction component exactly 0: d2 = 0/0 = NaN, which the scalar code's
// fmax/fmin (and a GPU's clamp) turn into -2. This pixel pins that behaviour on every
// target (on x86, maxps gives it by itself; the kernel also spells it out for targets that
// propagate NaN). The greys were found by search: luma(254) - (luma(194) + 1/384) ==
// luma(23) - luma(8) in float32.
TEST(SimdTargets, Fxaa3cZeroDirectionComponentMatchesTheReference) {
    const ResetTargets reset;
    auto grey = [](int g) { return Rgba8{std::uint8_t(g), std::uint8_t(g), std::uint8_t(g), 255}; };
    ImageRgba8 img(40, 9);
    for (int y = 0; y < 9; ++y)  // a textured background, so that every tap matters
        for (int x = 0; x < 40; ++x) img(x, y) = grey((x * x * 7 + y * y * 13 + x * y * 5) % 256);
    img(19, 3) = grey(8);    // NW of pixel (20, 4) (Lottes: y down)
    img(21, 5) = grey(23);   // SE
    img(19, 5) = grey(254);  // SW
    img(21, 3) = grey(194);  // NE
    const MethodInfo& m = methodById("fxaa3c");
    const ImageRgba8 expected = m.reference(img.view(), {}, {});
    EXPECT_NE(expected(20, 4), img(20, 4));  // the pixel is processed, not early-exited
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        EXPECT_EQ(m.run(img.view(), {}, {}), expected) << hwy::TargetName(target);
    }
}

// The chunked kernels (fxaa3d, ddaa1, ddaa2) tile a row's interior with vectors; the last
// chunk of a row overlaps the one before it and writes through a buffer; fxaa3c lists a
// row's edge pixels and runs them N at a time. Every width from 1 to 3 vectors + 2 puts the
// row's end at every position within a chunk, on every target.
TEST(SimdTargets, EveryRowEndWithinAChunkEqualsTheReference) {
    const ResetTargets reset;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
            const MethodInfo& m = methodById(id);
            for (int w = 1; w <= 50; ++w) {
                const auto in = test::noise(w, 4, unsigned(w));
                for (const auto& [name, settings] : encodings())
                    ASSERT_EQ(m.run(in.view(), settings, {}), m.reference(in.view(), settings, {}))
                        << hwy::TargetName(target) << " " << id << " " << name << " width " << w;
            }
        }
    }
}

// Edge pixels scattered over a flat image, as on photographs: fxaa3c's list of a row's
// edge pixels has gaps and a last group padded with repeats; every target, every width.
TEST(SimdTargets, ScatteredEdgePixelsEqualTheReference) {
    const ResetTargets reset;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const char* id : {"fxaa3c", "fxaa3d", "ddaa2"}) {
            const MethodInfo& m = methodById(id);
            for (int w = 1; w <= 50; ++w) {
                ImageRgba8 in(w, 7);
                for (int y = 0; y < 7; ++y)
                    for (int x = 0; x < w; ++x) {
                        const unsigned hash =
                            unsigned(x) * 73856093u ^ unsigned(y) * 19349663u ^ unsigned(w) * 83492791u;
                        const std::uint8_t v = hash % 11 == 0 ? std::uint8_t(hash >> 8) : 128;
                        in(x, y) = {v, std::uint8_t(v / 2 + 40), std::uint8_t(255 - v), 255};
                    }
                for (const auto& [name, settings] : encodings()) {
                    const ImageRgba8 expected = m.reference(in.view(), settings, {});
                    ASSERT_EQ(m.run(in.view(), settings, {}), expected)
                        << hwy::TargetName(target) << " " << id << " " << name << " width " << w;
                    if (w == 50) {
                        EXPECT_NE(expected, in) << id << " " << name;  // the dots are processed, not all copied
                    }
                }
            }
        }
    }
}

// The fast paths work in bands of rows, each with the luma planes of the rows its vertical
// searches reach. Near-vertical edges (one pixel across per 40 rows) make long vertical
// walks; a 60 x 400 image crosses several band boundaries.
TEST(SimdTargets, LongVerticalSearchesAcrossBandsEqualTheReference) {
    ImageRgba8 img(60, 400);
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 60; ++x) {
            const int edge = 20 + y / 40, edge2 = 45 - y / 37;
            const std::uint8_t v = x < edge ? 30 : (x < edge2 ? 220 : 120);
            img(x, y) = {v, v, std::uint8_t(v / 2), 255};
        }
    const ImageRgba8 processed = aa::fxaa3dReference(img.view());
    int changed = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) changed += processed(x, y) != img(x, y);
    EXPECT_GT(changed, 1000);  // the edges are processed, not early-exited
    const ResetTargets reset;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const MethodInfo& m : methods()) {
            if (m.inputScale != 1) continue;
            for (const auto& [name, settings] : encodings()) {
                if (m.id == "noaa" && !settings.params.empty()) continue;  // noaa reads no texture
                EXPECT_EQ(m.run(img.view(), settings, {}), m.reference(img.view(), settings, {}))
                    << hwy::TargetName(target) << " " << m.id << " " << name;
            }
        }
        aa::Fxaa3dParams lottes;
        lottes.paperSearchQuirk = false;
        EXPECT_EQ(aa::fxaa3d(img.view(), lottes), aa::fxaa3dReference(img.view(), lottes)) << hwy::TargetName(target);
        for (int rounds = 1; rounds <= 5; ++rounds) {
            aa::Ddaa2Params p;
            p.searchRounds = rounds;
            EXPECT_EQ(aa::ddaa2(img.view(), p), aa::ddaa2Reference(img.view(), p))
                << hwy::TargetName(target) << " searchRounds " << rounds;
        }
    }
}

// The plane rows live in a ring per thread that the next rows of the same call reuse. A
// second call on the same buffer, with new pixels, must not read the first call's rows:
// one thread runs both calls, and the image is shorter than the ring, so the ring still
// holds every row of the first call at the positions the second one reads.
TEST(SimdTargets, PlaneRowsOfAnEarlierCallAreNotReused) {
    auto edges = [](ImageRgba8& img, int shift) {
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const int edge = 20 + shift + y / 40, edge2 = 45 - y / 37;
                const std::uint8_t v = x < edge ? 30 : (x < edge2 ? 220 : 120);
                img(x, y) = {v, std::uint8_t(v / 2 + shift), v, 255};
            }
    };
    ImageRgba8 img(60, 48);
    const Exec one{1};
    for (const char* id : {"fxaa3d", "ddaa2"}) {
        const MethodInfo& m = methodById(id);
        edges(img, 0);
        const ImageRgba8 first = m.run(img.view(), {}, one);
        edges(img, 7);  // same buffer, same size, other pixels
        const ImageRgba8 second = m.run(img.view(), {}, one);
        EXPECT_NE(first, second) << id;
        EXPECT_EQ(second, m.reference(img.view(), {}, {})) << id;
    }
}

// Near-horizontal edges between rows 63 | 64 and 127 | 128: the pixels above them read the
// plane row below, which sits at the ring's first slot while theirs is at its last. Both
// the gathers (40 px wide) and the contiguous loads (130 px) take that path.
TEST(SimdTargets, HorizontalEdgesAtThePlaneRingsWrapEqualTheReference) {
    const ResetTargets reset;
    for (const int w : {40, 130}) {
        ImageRgba8 img(w, 200);
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < w; ++x) {
                const bool band = (y >= 64 + x / 32 && y < 128 + x / 40) || y >= 192 - x / 50;
                const std::uint8_t v = band ? 210 : 35;
                img(x, y) = {v, std::uint8_t(v - 20), v, 255};
            }
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            for (const char* id : {"fxaa3d", "ddaa2"}) {
                const MethodInfo& m = methodById(id);
                for (const auto& [name, settings] : encodings())
                    EXPECT_EQ(m.run(img.view(), settings, {}), m.reference(img.view(), settings, {}))
                        << hwy::TargetName(target) << " " << id << " " << name << " width " << w;
            }
        }
    }
}
