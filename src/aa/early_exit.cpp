// Temporary scalar early-exit mask (replaced by the Highway version).
#include "luma_driver.hpp"
namespace ssfx::aa::detail {
void earlyExitRow(const ImageF& L, int y, float thresholdMin, float threshold, std::uint8_t* exitMask) {
    for (int x = 0; x < L.width(); ++x) {
        float range;
        exitMask[x] = belowEdgeThreshold(neighbourhood(L, x, y), thresholdMin, threshold, &range);
    }
}
}  // namespace ssfx::aa::detail
