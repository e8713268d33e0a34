// The evaluation's test images, drawn by ssfx with Cairo (antialiasing off, text through
// fontconfig/FreeType with the DejaVu fonts). Each image is one vector description in
// units of its scale-1 size; scale 2, 4 and 8 render the same geometry with coordinates
// and line widths multiplied, which is what the DDAA paper's protocol needs (spec ppaa.md
// section 3: the x8 render is the truth, the x2/x4 renders feed the resolves).
//
//   lines     600x600  stars of thin/thick lines, growing squares and circles, near-horizontal
//                      fans, grids rotated by 0/1/5/10/20/45 degrees (cells 10, 5, 2 px)
//   circles   480x480  rings and discs in nine colours on white, black, grey and dark grey,
//                      the grey chosen so pure green has almost its luma (spec section 4)
//   plot      640x480  a line plot: axes, ticks, labels and title in real text, grid,
//                      thick sine and cosine with diamond and circle markers
//   animated  600x600  32 frames at 25 fps, looping: rotating cross, orbiting circles,
//                      fans of vertical lines slanting back and forth
//
// Rendering is deterministic for a given Cairo/FreeType build.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::eval {

struct TestImageInfo {
    std::string_view name;
    int width, height;  //!< at scale 1
    int frames;         //!< 1 for stills
    int fps;            //!< frames per second of an animation (0 for stills)
    std::string_view description;
};

//! The four test images, in report order.
std::span<const TestImageInfo> testImages();
//! Throws ssfx::Error listing the known names.
const TestImageInfo& testImageByName(std::string_view name);

//! Renders frame `frame` of image `name` at `scale` (1..16) without antialiasing.
ImageRgba8 drawTestImage(std::string_view name, int scale, int frame = 0);

}  // namespace ssfx::eval
