// Every SIMD target compiled into the library (Highway's runtime dispatch: SSE4, AVX2,
// AVX-512, scalar... as this CPU supports) gives the scalar reference's bytes, for every
// registered method (STYLE.md section 4, after Highway's HWY_EXPORT_AND_TEST_P).
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "ssfx/eval/synthetic.hpp"
#include "ssfx/registry.hpp"
#include "support/test_support.hpp"

using namespace ssfx;

namespace {
struct ResetTargets {
    ~ResetTargets() { hwy::SetSupportedTargetsForTest(0); }
};
}  // namespace

TEST(SimdTargets, EveryTargetEqualsTheReference) {
    const ResetTargets reset;
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        for (const MethodInfo& m : methods()) {
            const int s = m.inputScale;
            // 300 px wide: chunks far from the borders take the contiguous plane reads too.
            for (const auto& in : {eval::syntheticScene(300, 40, s), test::noise(67 * s, 9 * s, 11)}) {
                EXPECT_EQ(m.run(in.view(), {}, {}), m.reference(in.view(), {}, {}))
                    << hwy::TargetName(target) << " " << m.id << " " << in.width() << "x" << in.height();
            }
        }
    }
    std::printf("[simd] checked %zu targets:", targets.size());
    for (const std::int64_t t : targets) std::printf(" %s", hwy::TargetName(t));
    std::printf("\n");
}
