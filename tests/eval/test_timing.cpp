#include <gtest/gtest.h>

#include "ssfx/eval/synthetic.hpp"
#include "ssfx/eval/timing.hpp"

using namespace ssfx;

TEST(Timing, MedianAndTrimmedMeanByHand) {
    EXPECT_DOUBLE_EQ(eval::median({5, 1, 3}), 3);
    EXPECT_DOUBLE_EQ(eval::median({4, 1, 3, 2}), 2.5);
    // 8 samples: drop the 2 smallest and 2 largest, mean of {3, 4, 5, 6}.
    EXPECT_DOUBLE_EQ(eval::trimmedMean({100, 1, 2, 3, 4, 5, 6, 1000}), 4.5);
}

TEST(Timing, InterleavedRunsEveryMethodAndNormalisesToTheBaseline) {
    int a = 0, b = 0;
    const auto r = eval::timeInterleaved({{"blur", [&] { ++a; }, {}}, {"x", [&] { ++b; }, {}}}, 8, 2, "blur");
    EXPECT_EQ(a, 10);
    EXPECT_EQ(b, 10);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0].samplesMs.size(), 8u);
    EXPECT_DOUBLE_EQ(r[0].relative, 100.0);
    EXPECT_THROW(eval::timeInterleaved({{"x", [] {}, {}}}, 4, 0, "blur"), Error);
}

TEST(Timing, MeasuredTimesReplaceTheWallClock) {
    // A GPU pass reports its timestamps: those are the samples, in run order.
    int calls = 0;
    double next = 0;
    const auto r = eval::timeInterleaved(
        {{"blur", [] {}, [] { return 2.0; }}, {"x", [&] { ++calls; }, [&] { return next += 1.0; }}}, 4, 1, "blur");
    EXPECT_EQ(calls, 5);
    // (measuredMs is asked only after the timed rounds, not the warm-up's)
    EXPECT_EQ(r[1].samplesMs, (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
    EXPECT_DOUBLE_EQ(r[1].relative, eval::trimmedMean(r[1].samplesMs) / 2.0 * 100.0);  // over blur's 2
}

TEST(Synthetic, ScalesAreTheSameDrawing) {
    const auto s1 = eval::syntheticScene(240, 240, 1), s2 = eval::syntheticScene(240, 240, 2);
    ASSERT_EQ(s2.width(), 480);
    // Most 1x pixels equal the 2x pixel at the same place (they differ only along edges).
    int same = 0;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 240; ++x) same += s1(x, y) == s2(2 * x + 1, 2 * y + 1);
    EXPECT_GT(same, 240 * 240 * 9 / 10);
    EXPECT_LT(same, 240 * 240);  // and it is not flat
}
