// The quality protocol on the DDAA author's data (../shared/reference/ppaa/, its README).
//
// Tolerances (issue #3): the table computed from the author's own outputs must match the
// README's unrounded values within 0.005 dB (the protocol is deterministic; this allows only
// for the README's rounding to 3 decimals), and the table from our outputs within 0.02 dB
// (our outputs differ from the author's by one level in < 0.1 % of pixels for fxaa3c and
// the resolves).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {

// ../shared/reference/README.md, columns ssaax4 ssaax2 blur fxaa3c fxaa3d ddaa1 ddaa2.
const std::vector<std::string> kColumns{"ssaax4", "ssaax2", "blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2"};
const double kLines[] = {17.293, 17.222, 16.215, 16.187, 16.045, 17.095, 16.867};
const double kCircles[] = {22.482, 22.418, 21.292, 21.564, 21.760, 22.315, 22.164};

void expectReadmeTable(eval::OutputSource source, double tolerance) {
    const auto dir = test::sharedDir("reference/ppaa");
    if (!dir) GTEST_SKIP() << "../shared/reference/ppaa is absent: reference table skipped";
    eval::QualityOptions o;
    o.methods = kColumns;
    o.source = source;
    const auto t = eval::evaluateQuality(*dir, o);
    ASSERT_EQ(t.images, (std::vector<std::string>{"lines", "circles"}));
    for (std::size_t m = 0; m < kColumns.size(); ++m) {
        EXPECT_NEAR(t.psnr[0][m], kLines[m], tolerance) << "lines " << kColumns[m];
        EXPECT_NEAR(t.psnr[1][m], kCircles[m], tolerance) << "circles " << kColumns[m];
        EXPECT_GT(t.ssim[0][m], 0.5);
        EXPECT_LT(t.ssim[0][m], 1.0);
    }
}

}  // namespace

TEST(Quality, AuthorsOutputsGiveTheReadmeTable) { expectReadmeTable(eval::OutputSource::Given, 0.005); }

TEST(Quality, OurOutputsGiveTheReadmeTable) { expectReadmeTable(eval::OutputSource::Compute, 0.02); }

TEST(Quality, FindsRenderSetsAndRejectsBadDirectories) {
    EXPECT_THROW(eval::findRenderSets("/nonexistent/ssfx"), Error);
    const std::string dir = test::outDir() + "/quality_sets";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto img = test::solid(8, 8, {10, 20, 30, 255}), img8 = test::solid(64, 64, {10, 20, 30, 255});
    io::writePng(dir + "/b.png", img.view());
    io::writePng(dir + "/bx8.png", img8.view());
    io::writePng(dir + "/a.png", img.view());       // no a x8: not a set
    io::writePng(dir + "/b_blur.png", img.view());  // an output, not a set
    EXPECT_EQ(eval::findRenderSets(dir), std::vector<std::string>{"b"});
    // A flat image: every method leaves it flat, so the x8 upscale equals the x8 render.
    eval::QualityOptions o;
    o.methods = {"blur", "ddaa2", "ssaax2"};  // ssaax2 needs bx2.png: skipped, NaN
    const auto t = eval::evaluateQuality(dir, o);
    EXPECT_TRUE(std::isinf(t.psnr[0][0]));
    EXPECT_DOUBLE_EQ(t.ssim[0][1], 1.0);
    EXPECT_TRUE(std::isnan(t.psnr[0][2]));
    EXPECT_NE(eval::qualityJson(t).find("\"psnr\""), std::string::npos);
    EXPECT_NE(eval::qualityMarkdown(t).find("| b |"), std::string::npos);
    // An x8 render of the wrong size is an error naming the file.
    io::writePng(dir + "/bx8.png", img.view());
    try {
        eval::evaluateQuality(dir, o);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bx8.png"), std::string::npos) << e.what();
    }
}
