// A synthetic aliased drawing for benchmarks and tests that must not depend on external
// files: thin and thick lines at many angles, near-horizontal fans, rings, discs on
// several backgrounds and rotated grids, point-sampled at pixel centres (no
// anti-aliasing), so it has the long edges, thin lines and corners PPAA methods meet.
// The geometry is defined in units of the scale-1 image, so scale 2 and 4 are the same
// drawing at higher resolution (inputs of ssaax2 / ssaax4 / ddaa2p).
#pragma once

#include "ssfx/core/image.hpp"

namespace ssfx::eval {

//! Draws the scene at (width * scale) x (height * scale). Deterministic.
ImageRgba8 syntheticScene(int width, int height, int scale = 1);

}  // namespace ssfx::eval
