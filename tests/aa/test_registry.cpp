#include <gtest/gtest.h>

#include <set>

#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/registry.hpp"

using namespace ssfx;

TEST(Registry, ListsTheSpecMethodsInOrderWithUniqueIds) {
    std::vector<std::string> ids;
    for (const auto& m : methods()) ids.emplace_back(m.id);
    const std::vector<std::string> spec = {"noaa",  "blur",   "fxaa3c", "fxaa3d", "ddaa1",
                                           "ddaa2", "ssaax2", "ssaax4", "ddaa2p"};
    EXPECT_EQ(ids, spec);
    EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), ids.size());
    EXPECT_EQ(findMethod("nope"), nullptr);
}

// run() starts from the medium preset for the threshold methods: the preset must be the
// params structs' defaults (which the tables document), or --help would show other values.
TEST(Registry, MediumPresetIsTheDocumentedDefault) {
    const auto same = [](std::span<const ParamInfo> table, const void* preset, std::string_view id) {
        for (const ParamInfo& p : table) EXPECT_EQ(p.get(preset), p.defaultValue()) << id << " " << p.name;
    };
    const auto c = aa::fxaa3cParamsFor(aa::Preset::Medium);
    same(aa::kFxaa3cParams, &c, "fxaa3c");
    const auto d = aa::fxaa3dParamsFor(aa::Preset::Medium);
    same(aa::kFxaa3dParams, &d, "fxaa3d");
    const auto d1 = aa::ddaa1ParamsFor(aa::Preset::Medium);
    same(aa::kDdaa1Params, &d1, "ddaa1");
    const auto d2 = aa::ddaa2ParamsFor(aa::Preset::Medium);
    same(aa::kDdaa2Params, &d2, "ddaa2");
    // And a preset is what its row says.
    const auto low = aa::ddaa2ParamsFor(aa::Preset::Low);
    EXPECT_EQ(low.edgeThresholdMin, aa::thresholdsFor(aa::Preset::Low).edgeThresholdMin);
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
