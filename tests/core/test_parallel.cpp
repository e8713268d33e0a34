#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <vector>

#include "ssfx/core/parallel.hpp"

using namespace ssfx;

TEST(Parallel, CoversEveryRowExactlyOnceInFixedBlocks) {
    for (int threads : {1, 2, 7}) {
        for (int h : {1, 15, 16, 17, 100}) {
            std::vector<std::atomic<int>> hits(static_cast<std::size_t>(h));
            parallelRows(h, Exec{threads}, [&](int y0, int y1) {
                EXPECT_EQ(y0 % kRowBlock, 0);
                EXPECT_LE(y1 - y0, kRowBlock);
                for (int y = y0; y < y1; ++y) hits[std::size_t(y)]++;
            });
            for (auto& c : hits) EXPECT_EQ(c.load(), 1);
        }
    }
}

TEST(Parallel, BlocksOfAGivenHeightCoverEveryRowOnce) {
    for (int threads : {1, 2, 7})
        for (int block : {1, 5, 96})
            for (int h : {1, 95, 96, 97, 400}) {
                std::vector<std::atomic<int>> hits(static_cast<std::size_t>(h));
                parallelRows(
                    h, Exec{threads},
                    [&](int y0, int y1) {
                        EXPECT_EQ(y0 % block, 0);
                        EXPECT_EQ(y1, std::min(h, y0 + block));
                        for (int y = y0; y < y1; ++y) hits[std::size_t(y)]++;
                    },
                    block);
                for (auto& c : hits) EXPECT_EQ(c.load(), 1);
            }
}

TEST(Parallel, ZeroMeansAllHardwareThreads) {
    EXPECT_GE(resolvedThreads(Exec{0}), 1);
    EXPECT_EQ(resolvedThreads(Exec{1}), 1);
    EXPECT_LE(resolvedThreads(Exec{1000}), resolvedThreads(Exec{0}));  // capped at the hardware
}
