// Properties every registered method must have (STYLE.md section 5). New methods are
// covered automatically through the registry.
#include <gtest/gtest.h>

#include "ssfx/aa/registry.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {

class MethodProperty : public ::testing::TestWithParam<const MethodInfo*> {};

std::string name(const ::testing::TestParamInfo<const MethodInfo*>& i) { return std::string(i.param->id); }

std::vector<const MethodInfo*> all() {
    std::vector<const MethodInfo*> v;
    for (const auto& m : methods()) v.push_back(&m);
    return v;
}

ImageRgba8 flipX(const ImageRgba8& img) {
    ImageRgba8 out(img.width(), img.height());
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) out(x, y) = img(img.width() - 1 - x, y);
    return out;
}

}  // namespace

TEST_P(MethodProperty, FlatImageIsUnchanged) {
    const MethodInfo& m = *GetParam();
    const int s = m.inputScale;
    for (Rgba8 c : {Rgba8{0, 0, 0, 255}, Rgba8{255, 255, 255, 255}, Rgba8{12, 200, 99, 77}}) {
        const ImageRgba8 in(24 * s, 10 * s, c);
        EXPECT_EQ(m.run(in.view(), {}, {}), ImageRgba8(24, 10, c));
    }
}

TEST_P(MethodProperty, SameBytesForAnyThreadCount) {
    const MethodInfo& m = *GetParam();
    const auto in = eval::syntheticScene(150, 70, m.inputScale);  // 70 rows: several row blocks
    const auto one = m.run(in.view(), {}, Exec{1});
    EXPECT_EQ(m.run(in.view(), {}, Exec{2}), one);
    EXPECT_EQ(m.run(in.view(), {}, Exec{8}), one);
}

TEST_P(MethodProperty, FastPathEqualsTheScalarReference) {
    const MethodInfo& m = *GetParam();
    const int s = m.inputScale;
    // 150 rows: more than the fast path's plane rings hold (64), so the searches' reads
    // wrap around them, far from the left and right borders (contiguous loads) and near them.
    for (const auto& in : {eval::syntheticScene(130, 150, s), test::noise(45 * s, 13 * s, 3)}) {
        EXPECT_EQ(m.run(in.view(), {}, {}), m.reference(in.view(), {}, {}));
        MethodSettings exact;
        exact.filtering = Filtering::Exact;
        EXPECT_EQ(m.run(in.view(), exact, {}), m.reference(in.view(), exact, {}));
        if (m.id == "noaa") continue;  // reads no texture
        MethodSettings srgb;           // an sRGB texture: the vector kernels' decoded-float reads
        srgb.params = {{"texture", 1}};
        EXPECT_EQ(m.run(in.view(), srgb, {}), m.reference(in.view(), srgb, {})) << "texture=srgb";
    }
}

TEST_P(MethodProperty, RunIntoEqualsRun) {
    const MethodInfo& m = *GetParam();
    const auto in = eval::syntheticScene(64, 40, m.inputScale);
    ImageRgba8 out(64, 40, Rgba8{1, 2, 3, 4});
    m.runInto(in.view(), out.view(), {}, {});
    EXPECT_EQ(out, m.run(in.view(), {}, {}));
    ImageRgba8 wrong(63, 40);
    EXPECT_THROW(m.runInto(in.view(), wrong.view(), {}, {}), Error);
}

TEST_P(MethodProperty, TinyAndThinImagesWork) {
    const MethodInfo& m = *GetParam();
    const int s = m.inputScale;
    for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 9}, std::pair{9, 1}, std::pair{2, 3}, std::pair{33, 2}}) {
        const auto in = test::noise(w * s, h * s, unsigned(w * 10 + h));
        const auto out = m.run(in.view(), {}, {});
        EXPECT_EQ(out.width(), w);
        EXPECT_EQ(out.height(), h);
        EXPECT_EQ(out, m.reference(in.view(), {}, {}));
    }
}

TEST_P(MethodProperty, AlphaIsCopied) {
    const MethodInfo& m = *GetParam();
    const int s = m.inputScale;
    const auto in = test::noise(20 * s, 12 * s, 21);
    const auto out = m.run(in.view(), {}, {});
    // Scale-1 methods copy the centre pixel's alpha; resolves that of the block's top-left pixel.
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) ASSERT_EQ(out(x, y).a, in(x * s, y * s).a);
}

// Symmetric filters commute with a horizontal flip: blur and noaa exactly, the resolves up
// to float summation order (<= 1 level). The luma methods are not symmetric by
// specification (edge ties go to side 1), so they are not instantiated here.
class SymmetricMethod : public MethodProperty {};

TEST_P(SymmetricMethod, HorizontalFlipCommutes) {
    const MethodInfo& m = *GetParam();
    const int tolerance = m.kind == "resolve" ? 1 : 0;
    const auto in = test::noise(40 * m.inputScale, 9 * m.inputScale, 5);
    const auto a = flipX(m.run(in.view(), {}, {}));
    const auto b = m.run(flipX(in).view(), {}, {});
    EXPECT_LE(test::maxAbsDiff(a, b), tolerance);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, MethodProperty, ::testing::ValuesIn(all()), name);
INSTANTIATE_TEST_SUITE_P(Symmetric, SymmetricMethod,
                         ::testing::Values(&methodById("noaa"), &methodById("blur"), &methodById("ssaax2"),
                                           &methodById("ssaax4")),
                         name);
