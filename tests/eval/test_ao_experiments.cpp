// The SAO experiments: z precision by its known shape, and a quick full run writing its files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ssfx/ao/depth.hpp"
#include "ssfx/eval/ao_experiments.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(AoExperiments, QuantizeDepthByHand) {
    // 16-bit: 0.5 * 65535 = 32767.5 rounds to even, 32768; 24-bit: 0.25 * (2^24 - 1) =
    // 4194303.75 -> 4194304.
    EXPECT_DOUBLE_EQ(ssfx::quantizeDepth(0.5, DepthFormat::D16), 32768.0 / 65535.0);
    EXPECT_DOUBLE_EQ(ssfx::quantizeDepth(0.25, DepthFormat::D24), 4194304.0 / 16777215.0);
    EXPECT_DOUBLE_EQ(ssfx::quantizeDepth(1.0 / 3.0, DepthFormat::D32F), double(float(1.0 / 3.0)));
    EXPECT_EQ(ssfx::quantizeDepth(1.5, DepthFormat::D16), 1.0);
}

TEST(AoExperiments, ZPrecisionHasTheExpectedShape) {
    const auto zp = eval::zPrecisionExperiment();
    ASSERT_EQ(zp.series.size(), 6u);  // D16, D24, D32F x finite, infinite
    ASSERT_EQ(zp.errorMm[0].size(), zp.distances.size());
    for (std::size_t s = 0; s < 6; ++s) {
        // The error of a standard (not reversed) depth mapping grows roughly with z^2.
        EXPECT_LT(zp.errorMm[s].front() * 1000, zp.errorMm[s].back()) << zp.series[s];
    }
    for (std::size_t i = 0; i < zp.distances.size(); ++i) {
        EXPECT_GT(zp.errorMm[0][i], 10 * zp.errorMm[2][i]);  // 16-bit is far worse than 24-bit
        // An infinite far plane costs almost nothing (paper section 2.1).
        EXPECT_LT(zp.errorMm[3][i], 1.5 * zp.errorMm[2][i] + 1e-9);
        if (zp.distances[i] < 10) {
            EXPECT_LT(zp.errorMm[2][i], 0.1);  // D24: < 0.1 mm within 10 m
        }
    }
}

TEST(AoExperiments, QuickRunWritesItsFiles) {
    const std::string dir = test::outDir() + "/ao_quick";
    std::filesystem::remove_all(dir);
    eval::AoExperimentOptions o;
    o.outDir = dir;
    o.quick = true;
    const eval::Section section = eval::runAoExperiments(o);
    const std::string md = eval::markdown(section);
    for (const char* f :
         {"data/ao.json", "data/ao.md", "plots/ao_z_precision.png", "plots/ao_radius_scaling.png",
          "images/ao_room_raytraced.png", "images/ao_room_sao_rotated_grid.png", "images/ao_corner_sao_min_diff.png"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    std::ifstream in(dir + "/data/ao.json");
    std::stringstream ss;
    ss << in.rdbuf();
    for (const char* key : {"\"z_precision\"", "\"normal_precision\"", "\"accuracy\"", "\"radius_scaling\"",
                            "\"pass_times\"", "\"comparison\"", "\"comparison_mean\"", "\"comparison_verdict\""})
        EXPECT_NE(ss.str().find(key), std::string::npos) << key;
    EXPECT_NE(md.find("Normal precision"), std::string::npos);
    // data/ao.md is the section's Markdown; every figure the section shows exists.
    std::ifstream mdFile(dir + "/data/ao.md");
    std::stringstream mdText;
    mdText << mdFile.rdbuf();
    EXPECT_EQ(mdText.str(), md);
    ASSERT_EQ(section.blocks.size(), 9u);
    std::size_t figures = 0, viewers = 0;
    for (const auto& b : section.blocks) {
        EXPECT_FALSE(b.table.empty()) << b.heading;
        for (const auto& row : b.table.rows) EXPECT_EQ(row.size(), b.table.header.size()) << b.heading;
        for (const auto& f : b.figures) {
            EXPECT_TRUE(std::filesystem::exists(dir + "/" + f.path)) << f.path;
            ++figures;
        }
        for (const auto& v : b.viewers) {
            for (const auto& [label, path] : v.sources) EXPECT_TRUE(std::filesystem::exists(dir + "/" + path)) << path;
            ++viewers;
        }
    }
    EXPECT_GE(figures, 10u);
    EXPECT_EQ(viewers, 2u);  // the method comparison: one per scene (corner, room)
    // The comparison: 9 methods x 3 radii per truth, a verdict naming the closest.
    const eval::Block& summary = section.blocks[4];
    EXPECT_EQ(summary.table.rows.size(), 9u);
    EXPECT_NE(summary.after.find("Against the obscurance truth the closest"), std::string::npos);
    EXPECT_NE(summary.after.find("Against the binary truth the closest"), std::string::npos);
    EXPECT_EQ(section.blocks[5].table.rows.size(), 27u);
    EXPECT_EQ(section.blocks[6].table.rows.size(), 27u);
}
