// Depth buffer -> camera-space z and the z pyramid of Scalable Ambient Obscurance
// (McGuire, Mara, Luebke, "Scalable Ambient Obscurance", HPG 2012, sections 2.1-2.2;
// spec sao.md "Passes" 1-2).
//
// Conventions (spec sao.md): camera space is right-handed and the camera looks down -z,
// so visible points have z < 0; zNear and zFar are negative (zFar = -infinity allowed).
// Hardware depth d is in [0, 1], 0 at the near plane. Pixel (x, y) has its centre at
// (x + 0.5, y + 0.5), y down. Depth exactly 1 is what a renderer clears to where nothing
// is drawn: it is sky for *any* far plane (finite or infinite), becomes z = -infinity, and
// every later pass treats it as "nothing there" (A = 1, occludes nothing, not blurred in).
// Geometry must therefore have d < 1, which a rasteriser guarantees (d = 1 is clipped).
#pragma once

#include <array>
#include <string_view>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ssfx/core/camera.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"

namespace ssfx::ao {

//! Camera-space position of the point with depth z at (fractional) pixel position (px, py)
//! (paper eq. 3 with y down): x = z / P00 * (1 - 2 px / w), y = z / P11 * (2 py / h - 1).
struct Vec3 {
    float x, y, z;
};
inline Vec3 reconstructPosition(const Projection& p, float px, float py, float z) {
    return {z / p.p00 * (1.0f - 2.0f * px / float(p.width)), z / p.p11 * (2.0f * py / float(p.height) - 1.0f), z};
}

//! Pass 1: hardware depth -> camera-space z (float32); d = 1 (nothing drawn) -> -infinity
//! for any far plane. Evaluated in double and rounded once, so z is the correctly rounded value for the stored depth:
//! what remains is the depth format's own precision (the Figure 3 experiment), not the arithmetic's. Throws ssfx::Error
//! naming the pixel for a depth that is NaN, infinite or outside [0, 1].
ImageF depthToZ(ImageView<const float> depth, const Camera& camera, const Exec& exec = {});
//! Into a caller's buffer of the depth's size (frame loops: no allocation).
void depthToZ(ImageView<const float> depth, const Camera& camera, ImageView<float> z, const Exec& exec = {});

//! The inverse, for tests and synthetic buffers: the depth a point at camera-space z gets.
double zToDepth(double z, const Camera& camera);

//! Pass 2 filters: the paper's default and its Table 1 alternatives.
enum class PyramidFilter {
    RotatedGrid,   //!< level m+1 (x, y) = level m (2x + (y & 1), 2y + (x & 1)): a real scene value
    Mean,          //!< arithmetic mean of the 2x2 block
    HarmonicMean,  //!< 4 / sum(1 / z)
    Min,           //!< most negative z of the block (farthest)
    Max,           //!< least negative z (nearest)
};
//! The filters' names, in the enum's order (SaoParams::pyramidFilter's choices).
inline constexpr std::array<std::string_view, 5> kPyramidFilterNames{"rotated-grid", "mean", "harmonic-mean", "min",
                                                                     "max"};

//! Levels 0..maxMip: level 0 is `z`, each next level half the size (rounding down, at
//! least 1). Reads beyond the previous level's edge are clamped.
std::vector<ImageF> zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter = PyramidFilter::RotatedGrid,
                             const Exec& exec = {});
//! Into `levels`, whose images are reused where their sizes already match.
void zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter, std::vector<ImageF>& levels,
              const Exec& exec = {});
//! The z pyramid in one buffer, level 0 first: the layout the sample passes read (one base
//! pointer for every tap, so the vector kernel gathers any level). SAO writes z and the
//! levels straight into it; a caller running several sample passes on one z buffer builds
//! it once. Shaping to the same sizes keeps the buffer.
struct ZPyramid {
    std::vector<float> data;
    std::vector<std::int32_t> offset, width, height;  //!< per level
    int levels() const { return int(offset.size()); }
    //! Levels 0..maxMip for a w x h level 0 (each next one half, rounding down, at least 1).
    void shape(int w, int h, int maxMip) {
        offset.clear(), width.clear(), height.clear();
        std::size_t total = 0;
        for (int m = 0; m <= maxMip; ++m) {
            offset.push_back(std::int32_t(total)), width.push_back(w), height.push_back(h);
            total += std::size_t(w) * std::size_t(h);
            w = std::max(1, w / 2), h = std::max(1, h / 2);
        }
        if (data.size() != total) data.resize(total);
    }
    ImageView<float> level(int m) {
        return {data.data() + offset[std::size_t(m)], width[std::size_t(m)], height[std::size_t(m)]};
    }
    ImageView<const float> level(int m) const {
        return {data.data() + offset[std::size_t(m)], width[std::size_t(m)], height[std::size_t(m)]};
    }
};
//! Into one buffer (`out` reshaped, its memory kept while the sizes stay).
void zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter, ZPyramid& out, const Exec& exec = {});

//! One step of the pyramid: `coarser` (max(1, w / 2) x max(1, h / 2) of `finer`) from `finer`.
void zPyramidLevel(ImageView<const float> finer, ImageView<float> coarser, PyramidFilter filter, const Exec& exec = {});

}  // namespace ssfx::ao
