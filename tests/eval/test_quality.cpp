// The quality protocol on the DDAA author's data (../shared/reference/ppaa/, its README).
//
// Tolerances (issue #3): the table computed from the author's own outputs must match the
// README's unrounded values within 0.005 dB (the protocol is deterministic; this allows only
// for the README's rounding to 3 decimals), and the table from our outputs within 0.02 dB
// (our outputs differ from the author's by one level in < 0.1 % of pixels for fxaa3c and
// the resolves).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ssfx/eval/metrics.hpp"
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
    o.protocols = {eval::Protocol::Paper};  // the README's table
    const auto t = eval::evaluateQuality(*dir, o);
    ASSERT_EQ(t.images, (std::vector<std::string>{"lines", "circles"}));
    for (std::size_t m = 0; m < kColumns.size(); ++m) {
        EXPECT_NEAR(t.psnr(0, m), kLines[m], tolerance) << "lines " << kColumns[m];
        EXPECT_NEAR(t.psnr(1, m), kCircles[m], tolerance) << "circles " << kColumns[m];
        EXPECT_GT(t.ssim(0, m), 0.5);
        EXPECT_LT(t.ssim(0, m), 1.0);
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
    EXPECT_TRUE(std::isinf(t.psnr(0, 0)));
    EXPECT_DOUBLE_EQ(t.ssim(0, 1), 1.0);
    EXPECT_TRUE(std::isnan(t.psnr(0, 2)));
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

TEST(Quality, TruthProtocolScoresAgainstTheResolvedX8AndItsEdges) {
    // A 16x16 set whose x8 render has a vertical edge at x8 column 60 (inside 1x column 7,
    // 4/8 black) and whose 1x render has it at column 8: the truth is grey-ish around x = 7.
    const std::string dir = test::outDir() + "/quality_truth";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    ImageRgba8 x1(16, 16, Rgba8{0, 0, 0, 255}), x8(128, 128, Rgba8{0, 0, 0, 255});
    for (int y = 0; y < 16; ++y)
        for (int x = 8; x < 16; ++x) x1(x, y) = {255, 255, 255, 255};
    for (int y = 0; y < 128; ++y)
        for (int x = 60; x < 128; ++x) x8(x, y) = {255, 255, 255, 255};
    io::writePng(dir + "/e.png", x1.view());
    io::writePng(dir + "/ex8.png", x8.view());
    const ImageRgba8 truth = eval::resolveTruth(x8.view());
    const Image<std::uint8_t> edges = eval::edgeMask(truth.view(), x1.view());
    // Given outputs: 'blur' is the truth itself, 'noaa' the aliased input.
    io::writePng(dir + "/e_blur.png", truth.view());
    io::writePng(dir + "/e_noaa.png", x1.view());
    eval::QualityOptions o;
    o.methods = {"blur", "noaa"};
    o.source = eval::OutputSource::Given;
    const auto t = eval::evaluateQuality(dir, o);
    ASSERT_EQ(t.protocols, (std::vector<eval::Protocol>{eval::Protocol::Paper, eval::Protocol::Truth}));
    const std::int64_t n = std::count(edges.pixels().begin(), edges.pixels().end(), std::uint8_t{1});
    EXPECT_EQ(t.edgePixels, (std::vector<std::int64_t>{n}));
    EXPECT_GE(n, 16);   // at least the column the edge crosses
    EXPECT_LT(n, 256);  // and not the flat regions
    using eval::Metric, eval::Protocol, eval::Region;
    // The truth scores perfectly against itself, on every pixel and on the edges.
    for (const Region r : {Region::All, Region::Edges}) {
        const eval::Scores& s = t.at(Protocol::Truth, r, 0, 0);
        EXPECT_TRUE(std::isinf(s.psnr));
        EXPECT_DOUBLE_EQ(s.ssim, 1.0);
        EXPECT_EQ(s.maxError, 0);
        EXPECT_EQ(s.p99Error, 0);
    }
    // noaa: the figures of the aliased input against the truth.
    const eval::ErrorStats e = eval::errorStats(x1.view(), truth.view());
    EXPECT_DOUBLE_EQ(t.value(Protocol::Truth, Region::All, Metric::Psnr, 0, 1), e.psnr);
    EXPECT_EQ(t.value(Protocol::Truth, Region::All, Metric::MaxError, 0, 1), e.maxError);
    EXPECT_GT(e.maxError, 100);
    // Every error lies on the edge pixels (outside them noaa equals the truth), so restricting
    // to them divides the MSE's pixel count: PSNR drops by exactly 10 log10(256 / n).
    EXPECT_NEAR(t.value(Protocol::Truth, Region::Edges, Metric::Psnr, 0, 1), e.psnr - 10 * std::log10(256.0 / n), 1e-9);
    EXPECT_EQ(t.value(Protocol::Truth, Region::Edges, Metric::MaxError, 0, 1), e.maxError);
    // The paper protocol is the x8 comparison, unchanged: scoreAgainstX8's figures.
    EXPECT_DOUBLE_EQ(t.psnr(0, 1), eval::scoreAgainstX8(x1.view(), x8.view()).psnr);
    // JSON and Markdown carry both protocols and the mask size.
    const std::string json = eval::qualityJson(t), md = eval::qualityMarkdown(t);
    EXPECT_NE(json.find("\"truth\""), std::string::npos);
    EXPECT_NE(json.find("\"p99_error\""), std::string::npos);
    EXPECT_NE(json.find(fmt::format("\"e\": {}", n)), std::string::npos) << json;
    EXPECT_NE(md.find("edge pixels only"), std::string::npos);
    // One protocol only: asking for the other is an error naming it.
    o.protocols = {Protocol::Truth};
    const auto truthOnly = eval::evaluateQuality(dir, o);
    EXPECT_FALSE(truthOnly.has(Protocol::Paper));
    const std::string err = test::errorOf([&] { truthOnly.psnr(0, 0); });
    EXPECT_NE(err.find("paper protocol was not evaluated"), std::string::npos) << err;
}

TEST(Quality, ParsesProtocols) {
    using eval::Protocol;
    EXPECT_EQ(eval::parseProtocols("both"), (std::vector<Protocol>{Protocol::Paper, Protocol::Truth}));
    EXPECT_EQ(eval::parseProtocols("truth"), std::vector<Protocol>{Protocol::Truth});
    const std::string err = test::errorOf([] { eval::parseProtocols("ours"); });
    EXPECT_NE(err.find("'ours'"), std::string::npos) << err;
}
