// The kernel experiment of the DDAA paper (section 2.1, its Figure 3): how well does a
// derivative kernel estimate the direction of an aliased edge?
//
// For each angle theta in [0, 90] degrees (step `stepDegrees`) and each line width, an
// aliased black line on white at angle theta (counter-clockwise from +x, y up) is drawn
// through the centre of a `size` x `size` image by point sampling: a pixel is black when
// its centre lies within width/2 of the line (`supersample` > 1: the pixel's value is the
// coverage of ss x ss samples; `shape` Edge: a half-plane instead of a line). Each kernel
// estimates the gradient at every pixel within `size`/2 - 8 of the centre that a PPAA
// method would process (contrast >= 0.25 over the pixel and its 4 neighbours) and whose
// gradient magnitude is at least 0.1 (for a unit step); the edge direction is the gradient's angle + 90 degrees, and
// the error is its angular distance to theta modulo 180 degrees (so in [0, 90]). The line is drawn at several sub-pixel
// offsets so that no angle is judged on a single lucky placement.
//
// Kernels (x derivative; y is the transpose), each scaled so a unit ramp has slope 1:
//   central   [-1 0 1] / 2
//   sobel     [-1 0 1] / 2 x [1 2 1] / 4
//   scharr    [-1 0 1] / 2 x [47 162 47] / 256   (DDAA's weights, spec ppaa.md ddaa1 step 2)
//   gaussian  derivative of a Gaussian, sigma = 1, 7x7
#pragma once

#include <string>
#include <vector>

namespace ssfx::eval {

struct KernelExperimentOptions {
    double stepDegrees = 0.5;                   //!< angle step in degrees, (0, 45]
    std::vector<double> widths{1.0, 2.0, 4.0};  //!< line widths in pixels
    int size = 64;                              //!< image side in pixels, >= 32
    int supersample = 1;                        //!< 1 = aliased (the PPAA case); n = n x n coverage
    enum class Shape { Line, Edge } shape = Shape::Line;
};

struct KernelExperiment {
    std::vector<std::string> kernels;
    std::vector<double> angles;                //!< degrees
    std::vector<std::vector<double>> errorAt;  //!< [kernel][angle]: mean error over widths, offsets, pixels
    std::vector<double> meanError;             //!< [kernel]: mean over every measured pixel (degrees)
    std::vector<double> maxError;              //!< [kernel]: the largest per-angle mean (degrees)
};

KernelExperiment runKernelExperiment(const KernelExperimentOptions& options = {});

std::string kernelMarkdown(const KernelExperiment& e);
std::string kernelJson(const KernelExperiment& e);

}  // namespace ssfx::eval
