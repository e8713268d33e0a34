// The parameter tables of the aa and ao families (support/param_tables.hpp), and the
// parameter layer itself: parsing, messages, choices.
#include <gtest/gtest.h>

#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/ao/sao.hpp"
#include "tests/support/param_tables.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx::test {
namespace {

// Runs a method on a small image with the params, so that its own validation speaks.
template <class P>
std::function<void(const P&)> through(void (*method)(ImageView<const Rgba8>, ImageView<Rgba8>, const P&, const Exec&)) {
    return [method](const P& p) {
        ImageRgba8 in(8, 8, Rgba8{10, 20, 30, 255}), out(8, 8);
        method(in.view(), out.view(), p, Exec{1});
    };
}

TEST(ParamTables, Aa) {
    checkParamTable<aa::BlurParams>(aa::kBlurParams, "blur", through<aa::BlurParams>(&aa::blur));
    checkParamTable<aa::Fxaa3cParams>(aa::kFxaa3cParams, "fxaa3c", through<aa::Fxaa3cParams>(&aa::fxaa3c));
    checkParamTable<aa::Fxaa3dParams>(aa::kFxaa3dParams, "fxaa3d", through<aa::Fxaa3dParams>(&aa::fxaa3d));
    checkParamTable<aa::Ddaa1Params>(aa::kDdaa1Params, "ddaa1", through<aa::Ddaa1Params>(&aa::ddaa1));
    checkParamTable<aa::Ddaa2Params>(aa::kDdaa2Params, "ddaa2", through<aa::Ddaa2Params>(&aa::ddaa2));
    checkParamTable<aa::MitchellParams>(aa::kMitchellParams, "ssaax4", [](const aa::MitchellParams& p) {
        ImageRgba8 in(8, 8, Rgba8{10, 20, 30, 255}), out(2, 2);
        aa::ssaax4(in.view(), out.view(), p, Exec{1});
    });
}

TEST(ParamTables, EveryRegistryMethodUsesItsTable) {
    // The registry's rows are the params structs' tables: a value outside one is refused by
    // MethodSettings too, and a default reaches the method unchanged.
    ImageRgba8 img(16, 16, Rgba8{200, 200, 200, 255});
    for (const MethodInfo& m : methods())
        for (const ParamInfo& row : m.params) {
            ImageRgba8 in(16 * m.inputScale, 16 * m.inputScale, Rgba8{200, 200, 200, 255});
            MethodSettings s;
            s.params = {{std::string(row.name), row.max + 1}};
            EXPECT_THROW(m.run(in.view(), s, Exec{1}), Error) << m.id << " " << row.name;
            s.params = {{std::string(row.name), row.defaultValue()}};
            EXPECT_EQ(m.run(in.view(), s, Exec{1}), m.run(in.view(), MethodSettings{}, Exec{1}))
                << m.id << " " << row.name;
        }
}

TEST(ParamTables, Ao) {
    checkParamTable<ao::SaoParams>(
        ao::kSaoParams, "sao", [](const ao::SaoParams& p) { ao::validate(p); },
        [](ao::SaoParams& p, std::string_view row) { p.packBlurInput = p.packBlurInput || row == "releasedPacking"; });
    checkParamTable<ao::AlchemyParams>(ao::kAlchemyParams, "alchemy",
                                       [](const ao::AlchemyParams& p) { ao::validate(p); });
    checkParamTable<ao::RaytracedParams>(ao::kRaytracedParams, "raytraced",
                                         [](const ao::RaytracedParams& p) { ao::validate(p); });
}

TEST(Params, ParsingAndMessages) {
    const ParamInfo& rounds = findParam(aa::kDdaa2Params, "ddaa2", "searchRounds");
    EXPECT_EQ(parseParamValue(rounds, "+3", "ddaa2"), 3.0);
    EXPECT_EQ(parseParamValue(rounds, "1e0", "ddaa2"), 1.0);
    for (const char* bad : {"", "3x", "0x10", "three", " 3"})
        EXPECT_THROW(parseParamValue(rounds, bad, "ddaa2"), Error) << bad;
    aa::Ddaa2Params p;
    EXPECT_EQ(errorOf([&] { setParam(aa::kDdaa2Params, &p, "ddaa2", "searchRounds", 2.5); }),
              "ddaa2: searchRounds = 2.5 is not an integer in [1, 5]");
    EXPECT_EQ(errorOf([&] { setParam(aa::kDdaa2Params, &p, "ddaa2", "strength", -1); }),
              "ddaa2: strength = -1 is not in [0, 100]");
    EXPECT_EQ(errorOf([&] { setParam(aa::kDdaa2Params, &p, "ddaa2", "strenght", 1); }).substr(0, 38),
              "ddaa2: unknown parameter 'strenght' (p");
    EXPECT_EQ(p.searchRounds, 5);  // a refused value leaves the struct as it was
    // A choice by name or index; its message lists the names.
    ao::SaoParams s;
    const ParamInfo& filter = findParam(ao::kSaoParams, "sao", "pyramidFilter");
    setParam(ao::kSaoParams, &s, "sao", "pyramidFilter", parseParamValue(filter, "harmonic-mean", "sao"));
    EXPECT_EQ(s.pyramidFilter, ao::PyramidFilter::HarmonicMean);
    EXPECT_EQ(filter.valueText(filter.defaultValue()), "rotated-grid");
    EXPECT_EQ(filter.rangeText(), "rotated-grid|mean|harmonic-mean|min|max");
    EXPECT_NE(errorOf([&] { parseParamValue(filter, "median", "sao"); }).find("is not one of rotated-grid, mean"),
              std::string::npos);
    const ParamInfo& pyramid = findParam(ao::kSaoParams, "sao", "usePyramid");
    EXPECT_EQ(parseParamValue(pyramid, "false", "sao"), 0.0);
    EXPECT_EQ(errorOf([&] { setParam(ao::kSaoParams, &s, "sao", "usePyramid", 2); }),
              "sao: usePyramid = 2 is not 0 or 1");
    // A Real is checked as stored: 1e-300 is 0 in a float, outside radius' (0, 100].
    EXPECT_THROW(setParam(ao::kSaoParams, &s, "sao", "radius", 1e-300), Error);
}

}  // namespace
}  // namespace ssfx::test
