// Golden comparison against the DDAA author's GPU outputs in ../shared/reference/ppaa/.
//
// Tolerance (issue #2): >= 99.9 % of pixels identical and <= 0.01 % off by more than one
// level. Why: the spec's GPU sampling model reproduces blur, fxaa3d, ddaa1 and ddaa2 bit
// for bit; the resolves differ by one level where the author's storage blend scaled
// colours by (weight sum)^3 (spec ppaa.md, ssaax2), and fxaa3c by one level on ties.
// A failure writes actual and diff images under the build's test_out folder.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "ssfx/aa/registry.hpp"
#include "ssfx/io/png.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {
struct Case {
    std::string image, method;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.image << " " << c.method; }
class Golden : public ::testing::TestWithParam<Case> {};
}  // namespace

TEST_P(Golden, MatchesTheAuthorsGpuOutput) {
    const auto dir = test::sharedDir("reference/ppaa");
    if (!dir) GTEST_SKIP() << "../shared/reference/ppaa is absent: golden comparison skipped";
    const Case& c = GetParam();
    const MethodInfo& m = methodById(c.method);
    const std::string suffix = m.inputScale == 1 ? "" : fmt::format("x{}", m.inputScale);
    const auto in = io::readPng(fmt::format("{}/{}{}.png", *dir, c.image, suffix));
    const auto expected = io::readPng(fmt::format("{}/{}_{}.png", *dir, c.image, c.method));
    const auto actual = m.run(in.view(), {}, {});
    ASSERT_EQ(actual.width(), expected.width());
    ASSERT_EQ(actual.height(), expected.height());
    std::int64_t identical = 0, offByMore = 0;
    ImageRgba8 diff(actual.width(), actual.height(), Rgba8{0, 0, 0, 255});
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const Rgba8 a = actual(x, y), e = expected(x, y);  // the author's outputs are RGB: alpha ignored
            const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
            identical += d == 0;
            offByMore += d > 1;
            if (d) diff(x, y) = {255, std::uint8_t(d > 1 ? 0 : 255), 0, 255};
        }
    const double n = double(actual.pixelCount());
    const double identicalPct = 100.0 * double(identical) / n, offPct = 100.0 * double(offByMore) / n;
    RecordProperty("identical_percent", fmt::format("{:.4f}", identicalPct));
    std::printf("[golden] %-8s %-7s identical %.4f %%, off by > 1: %.4f %%\n", c.image.c_str(), c.method.c_str(),
                identicalPct, offPct);
    const bool ok = identicalPct >= 99.9 && offPct <= 0.01;
    if (!ok) {
        const std::string base = fmt::format("{}/{}_{}", test::outDir(), c.image, c.method);
        io::writePng(base + "_actual.png", actual.view());
        io::writePng(base + "_diff.png", diff.view());
    }
    EXPECT_GE(identicalPct, 99.9);
    EXPECT_LE(offPct, 0.01);
}

namespace {
std::vector<Case> cases() {
    std::vector<Case> v;
    for (const char* img : {"lines", "circles"})
        for (const char* m : {"blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ssaax2", "ssaax4", "ddaa2p"})
            v.push_back({img, m});
    return v;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(Ppaa, Golden, ::testing::ValuesIn(cases()),
                         [](const auto& i) { return i.param.image + "_" + i.param.method; });

// The four methods the spec's sampling model reproduces exactly are held to exactness.
TEST(GoldenExact, BitExactMethods) {
    const auto dir = test::sharedDir("reference/ppaa");
    if (!dir) GTEST_SKIP() << "../shared/reference/ppaa is absent: golden comparison skipped";
    for (const char* img : {"lines", "circles"})
        for (const char* id : {"blur", "fxaa3d", "ddaa1", "ddaa2"}) {
            const auto in = io::readPng(fmt::format("{}/{}.png", *dir, img));
            auto expected = io::readPng(fmt::format("{}/{}_{}.png", *dir, img, id));
            auto actual = methodById(id).run(in.view(), {}, {});
            EXPECT_EQ(test::maxAbsDiff(actual, expected), 0) << img << " " << id;
        }
}
