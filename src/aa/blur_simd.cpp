// Temporary scalar row kernel (replaced by the Highway version).
#include "blur_kernel.hpp"
namespace ssfx::aa::detail {
void blurRow(ImageView<const Rgba8> in, ImageView<Rgba8> out, int y, const BlurWeights& k) {
    for (int x = 0; x < in.width(); ++x) out(x, y) = blurPixel(in, x, y, k);
}
}  // namespace ssfx::aa::detail
