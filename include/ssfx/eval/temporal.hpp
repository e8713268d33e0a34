// Temporal stability of the anti-aliasing methods: how much a method flickers on a moving
// drawing. The DDAA paper judges this only by eye; we measure it (docs/evaluation.md).
//
// Given an animation of T frames rendered at 1x, 2x, 4x and 8x (same geometry), let
// R_t = the x8 frame t resolved to 1x with the Mitchell filter (aa::downscaleMitchell, the
// supersampled reference) and O_t = the method's output for frame t (ssaax2/ddaa2p take the
// x2 frame, ssaax4 the x4 frame). With frame-to-frame differences, taken around the loop,
//   dO_t = O_{(t+1) mod T} - O_t,   dR_t = R_{(t+1) mod T} - R_t   (RGB in [0, 1], signed),
//   flicker   = sqrt(mean over t, pixels and RGB of (dO_t - dR_t)^2)   (reported in levels, x255)
//   tPSNR     = 10 log10(1 / mean((dO_t - dR_t)^2))                   (dB, higher is steadier)
//   PSNR      = 10 log10(1 / mean over t of mse(O_t, R_t))             (per-frame quality at 1x)
// A method that changes a pixel exactly as the reference changes it has flicker 0; an
// aliased edge that jumps a whole pixel while the reference moves smoothly scores badly.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/registry.hpp"

namespace ssfx::eval {

//! Frame `frame` of the animation at `scale` (1, 2, 4 or 8).
using FrameFn = std::function<ImageRgba8(int frame, int scale)>;

struct TemporalOptions {
    std::vector<std::string> methods;  //!< ids; empty = the quality table's order
    MethodSettings settings;
    Exec exec;
    std::function<void(const std::string&)> progress;
};

struct TemporalResult {
    std::string method;
    double flickerLevels;  //!< RMS error of frame-to-frame differences, in 8-bit levels
    double temporalPsnr;   //!< dB
    double psnr;           //!< dB, outputs vs resolved x8 frames
};

struct TemporalRun {
    std::vector<TemporalResult> results;            //!< one per method, in order
    std::vector<std::vector<ImageRgba8>> outputs;   //!< outputs[m][t]
    std::vector<ImageRgba8> reference;              //!< R_t
};

//! Runs every method on every frame. Needs frames >= 2.
TemporalRun evaluateTemporal(int frames, const FrameFn& frame, const TemporalOptions& options);

//! The metrics for one sequence of outputs against a reference sequence (same sizes).
TemporalResult temporalScore(const std::vector<ImageRgba8>& outputs, const std::vector<ImageRgba8>& reference,
                             const Exec& exec = {});

//! Markdown table (method, flicker, tPSNR, PSNR) and JSON {"METHOD": {"flicker_levels", ...}}.
std::string temporalMarkdown(const std::vector<TemporalResult>& results);
std::string temporalJson(const std::vector<TemporalResult>& results);

}  // namespace ssfx::eval
