// Temporal stability, the kernel experiment and the charts, on small hand-checkable cases.
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/eval/kernels.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/temporal.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Temporal, ScoreByHand) {
    // Two frames of one pixel. Reference: 0 -> 51 (a change of 0.2). Output: 0 -> 102 (0.4).
    // Frame-to-frame differences around the loop: t=0: out +0.4, ref +0.2; t=1: out -0.4,
    // ref -0.2. Error 0.2 in every channel and both steps: flicker = 0.2 * 255 = 51 levels.
    // Per-frame mse: frame 0 equal; frame 1 off by 0.2: mean mse = 0.04 / 2 = 0.02.
    std::vector<ImageRgba8> ref{test::solid(1, 1, {0, 0, 0, 255}), test::solid(1, 1, {51, 51, 51, 255})};
    std::vector<ImageRgba8> out{test::solid(1, 1, {0, 0, 0, 255}), test::solid(1, 1, {102, 102, 102, 255})};
    const auto r = eval::temporalScore(out, ref);
    EXPECT_NEAR(r.flickerLevels, 51.0, 1e-9);
    EXPECT_NEAR(r.temporalPsnr, 10 * std::log10(1 / 0.04), 1e-9);
    EXPECT_NEAR(r.psnr, 10 * std::log10(1 / 0.02), 1e-9);
    // A still output against a still reference: no flicker at all.
    const auto still = eval::temporalScore({ref[0], ref[0]}, {ref[0], ref[0]});
    EXPECT_EQ(still.flickerLevels, 0.0);
    EXPECT_THROW(eval::temporalScore({ref[0]}, {ref[0]}), Error);
}

TEST(Temporal, SupersamplingFlickersLessThanNothing) {
    // A small moving animation through evaluateTemporal: the x4 resolve follows the x8
    // reference far better than the aliased input does.
    auto frame = [](int t, int scale) {
        ImageRgba8 img(32 * scale, 32 * scale, Rgba8{255, 255, 255, 255});
        // A slanted bar moving by 1/4 px per frame (4 frames: loops after 1 px).
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const double u = (x + 0.5) / scale - 10 - 0.25 * t - 0.3 * ((y + 0.5) / scale);
                if (u >= 0 && u < 3) img(x, y) = {0, 0, 0, 255};
            }
        return img;
    };
    eval::TemporalOptions o;
    o.methods = {"noaa", "ssaax4", "ddaa2"};
    const auto run = eval::evaluateTemporal(4, frame, o);
    ASSERT_EQ(run.results.size(), 3u);
    ASSERT_EQ(run.outputs[0].size(), 4u);
    EXPECT_LT(run.results[1].flickerLevels, 0.5 * run.results[0].flickerLevels);
    EXPECT_GT(run.results[0].flickerLevels, 0.0);
    EXPECT_THROW(eval::evaluateTemporal(1, frame, o), Error);
}

TEST(Kernels, AxisAlignedLinesAreExactAndSmoothingHelps) {
    eval::KernelExperimentOptions o;
    o.stepDegrees = 15;
    const auto e = eval::runKernelExperiment(o);
    ASSERT_EQ(e.kernels, (std::vector<std::string>{"central", "sobel", "scharr", "gaussian"}));
    ASSERT_EQ(e.angles, (std::vector<double>{0, 15, 30, 45, 60, 75, 90}));
    for (std::size_t k = 0; k < e.kernels.size(); ++k) {
        // Every symmetric kernel measures 0 and 90 degree lines exactly (this also catches a
        // swapped x/y or a sign error, which would give 90 degrees).
        EXPECT_NEAR(e.errorAt[k].front(), 0.0, 1e-9) << e.kernels[k];
        EXPECT_NEAR(e.errorAt[k].back(), 0.0, 1e-9) << e.kernels[k];
        EXPECT_GT(e.meanError[k], 0.0) << e.kernels[k];
        EXPECT_LE(e.meanError[k], e.maxError[k]) << e.kernels[k];
    }
    // Smoother kernels estimate better on aliased edges than plain central differences.
    EXPECT_LT(e.meanError[3], e.meanError[0]);
    EXPECT_LT(e.meanError[1], e.meanError[0]);
    // With 4x4 coverage (antialiased lines) every kernel does better than on aliased ones.
    o.supersample = 4;
    const auto aa = eval::runKernelExperiment(o);
    for (std::size_t k = 0; k < e.kernels.size(); ++k) EXPECT_LT(aa.meanError[k], e.meanError[k]) << e.kernels[k];
    o.stepDegrees = 0;
    EXPECT_THROW(eval::runKernelExperiment(o), Error);
}

TEST(Plot, ChartsDrawBarsAndLines) {
    eval::ChartStyle st{300, 200, "t", "x (m)", "y (dB)", false, true};
    const auto bars = eval::groupedBarChart({"a", "b"}, {{"s1", {1.0, 2.0}}, {"s2", {NAN, 3.0}}}, st);
    EXPECT_EQ(bars.width(), 300);
    EXPECT_EQ(bars.height(), 200);
    int coloured = 0;  // the palette's colours, not grey/white/black
    for (const auto& p : bars.pixels()) coloured += std::abs(int(p.r) - int(p.b)) > 60;
    EXPECT_GT(coloured, 500);
    const auto lines = eval::lineChart({0, 1, 2}, {{"k", {1, 3, 2}}}, st);
    EXPECT_EQ(lines.width(), 300);
    EXPECT_THROW(eval::groupedBarChart({"a"}, {{"s", {1.0, 2.0}}}, st), Error);
    EXPECT_THROW(eval::lineChart({0}, {{"k", {1}}}, st), Error);
    st.width = 10;
    EXPECT_THROW(eval::lineChart({0, 1}, {{"k", {1, 2}}}, st), Error);
    // Every axis names its unit (the value axis of both kinds, the x axis of line charts).
    st.width = 300;
    st.yLabel = "y";
    std::string e = test::errorOf([&] { eval::groupedBarChart({"a"}, {{"s", {1.0}}}, st); });
    EXPECT_NE(e.find("names no unit"), std::string::npos) << e;
    st.yLabel = "y (dB)";
    st.xLabel = "x";
    e = test::errorOf([&] { eval::lineChart({0, 1}, {{"k", {1, 2}}}, st); });
    EXPECT_NE(e.find("x axis label 'x' names no unit"), std::string::npos) << e;
    st.xLabel = "";
    EXPECT_THROW(eval::groupedBarChart({"a"}, {{"s", {1.0}}}, st), Error);
}

TEST(Plot, StackedBarsStackTheSeriesFromZero) {
    const eval::ChartStyle st{300, 200, "profile", "frame", "time (ms)", false, false};
    // Two frames; the second's stack (10) is twice the first's (5): its bar reaches twice as high.
    const auto img = eval::stackedBarChart({"0", "1"}, {{"draw", {2.0, 4.0}}, {"shade", {3.0, 6.0}}}, st);
    ASSERT_EQ(img.width(), 300);
    const auto topOf = [&](int x0, int x1) {  // the highest row with a palette colour in columns [x0, x1)
        for (int y = 0; y < img.height(); ++y)
            for (int x = x0; x < x1; ++x)
                if (std::abs(int(img(x, y).r) - int(img(x, y).b)) > 60) return y;
        return img.height();
    };
    const int bottom = 200 - 48, left = 64, groupW = (300 - 110 - 64) / 2;
    const int h0 = bottom - topOf(left, left + groupW), h1 = bottom - topOf(left + groupW, left + 2 * groupW);
    EXPECT_GT(h0, 10);
    EXPECT_NEAR(double(h1) / double(h0), 2.0, 0.1);
    EXPECT_THROW(eval::stackedBarChart({"0"}, {{"s", {-1.0}}}, st), Error);
    EXPECT_THROW(eval::stackedBarChart({"0", "1"}, {{"s", {1.0}}}, st), Error);
}

TEST(Plot, TickLabelsAreDistinctAndHaveTheStepsDigits) {
    // The report's SSIM chart spans about 0.78..0.99: ticks 0.80, 0.85, ... must not all read "0.8"/"0.9".
    const auto ticks = eval::axisTicks(0.78, 0.99, false);
    ASSERT_GE(ticks.size(), 4u);
    EXPECT_EQ(eval::tickLabels(ticks, false).front(), "0.78");
    // Every range of value axes the report draws (PSNR in dB, SSIM, ms, degrees of error,
    // tiny and huge spans): the labels are distinct, and read back within half a step.
    const std::pair<double, double> ranges[] = {{0.78, 0.99},    {0.86, 0.875}, {15.2, 46.7}, {0, 100},
                                                {0.001, 0.0042}, {-3.5, 2.25},  {0, 12000},   {0.9990, 0.99995}};
    for (const auto& [lo, hi] : ranges) {
        const auto t = eval::axisTicks(lo, hi, false);
        const auto l = eval::tickLabels(t, false);
        ASSERT_GE(t.size(), 3u) << lo << ".." << hi;
        const double step = t[1] - t[0];
        for (std::size_t i = 0; i < t.size(); ++i) {
            EXPECT_GE(t[i], lo - step * 1e-6);
            EXPECT_LE(t[i], hi + step * 1e-6);
            EXPECT_NEAR(std::stod(l[i]), t[i], step / 2) << l[i];
            if (i > 0) {
                EXPECT_NE(l[i], l[i - 1]) << lo << ".." << hi;
            }
        }
    }
    const auto logTicks = eval::axisTicks(0.1, 1000, true);
    EXPECT_EQ(eval::tickLabels(logTicks, true), (std::vector<std::string>{"0.1", "1", "10", "100", "1000"}));
    EXPECT_TRUE(eval::axisTicks(1, 1, false).empty());
}
