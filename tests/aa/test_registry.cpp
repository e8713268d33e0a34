#include <gtest/gtest.h>

#include <set>

#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/registry.hpp"

using namespace ssfx;

TEST(Registry, ListsTheSpecMethodsInOrderWithUniqueIds) {
    std::vector<std::string> ids;
    for (const auto& m : methods()) ids.emplace_back(m.id);
    const std::vector<std::string> spec = {"noaa",   "blur",   "fxaa3c", "fxaa3d", "ddaa1",
                                           "ddaa2",  "ssaax2", "ssaax4", "ddaa2p"};
    EXPECT_EQ(ids, spec);
    EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), ids.size());
    EXPECT_EQ(findMethod("nope"), nullptr);
}

// The registry's documented defaults must be the params structs' defaults.
TEST(Registry, ParamDefaultsMatchTheParamsStructs) {
    auto def = [](std::string_view id, std::string_view name) {
        for (const auto& p : methodById(id).params)
            if (p.name == name) return p.defaultValue;
        ADD_FAILURE() << id << " has no " << name;
        return -1.0;
    };
    const aa::Ddaa2Params d;
    EXPECT_FLOAT_EQ(float(def("ddaa2", "strength")), d.strength);
    EXPECT_FLOAT_EQ(float(def("ddaa2", "maxDiffusion")), d.maxDiffusion);
    EXPECT_FLOAT_EQ(float(def("ddaa2", "edgeThresholdMin")), d.edgeThresholdMin);
    EXPECT_FLOAT_EQ(float(def("ddaa2", "edgeThreshold")), d.edgeThreshold);
    EXPECT_EQ(def("ddaa2", "searchRounds"), d.searchRounds);
    EXPECT_FLOAT_EQ(float(def("fxaa3d", "subpix")), aa::Fxaa3dParams{}.subpix);
    EXPECT_FLOAT_EQ(float(def("fxaa3c", "edgeSharpness")), aa::Fxaa3cParams{}.edgeSharpness);
    EXPECT_FLOAT_EQ(float(def("blur", "sigma")), aa::BlurParams{}.sigma);
    // The medium preset is the default.
    EXPECT_EQ(aa::thresholdsFor(aa::Preset::Medium).edgeThresholdMin, d.edgeThresholdMin);
}

TEST(Registry, OverridesAndPresetsReachTheMethod) {
    ImageRgba8 img(16, 16, Rgba8{255, 255, 255, 255});
    for (int i = 0; i < 16; ++i) img(i, i) = {0, 0, 0, 255};
    const MethodInfo& m = methodById("ddaa2");
    MethodSettings s;
    const auto base = m.run(img.view(), s, {});
    s.params = {{"strength", 0.0}, {"searchRounds", 1.0}};
    EXPECT_NE(m.run(img.view(), s, {}), base);
    EXPECT_EQ(m.run(img.view(), s, {}), aa::ddaa2(img.view(), [] {
                  aa::Ddaa2Params p;
                  p.strength = 0, p.searchRounds = 1;
                  return p;
              }()));
}
