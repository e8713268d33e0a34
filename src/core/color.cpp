// Temporary scalar luma plane (replaced by the Highway version).
#include "ssfx/core/color.hpp"
namespace ssfx {
ImageF lumaPlane(ImageView<const Rgba8> in) {
    ImageF L(in.width(), in.height());
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            const Rgba8 p = in(x, y);
            L(x, y) = luma(kUnorm8[p.r], kUnorm8[p.g], kUnorm8[p.b]);
        }
    return L;
}
}  // namespace ssfx
