// Temporal stability of the anti-aliasing methods: how much a method flickers on a moving
// drawing. The DDAA paper judges this only by eye; we measure it (docs/evaluation.md).
//
// Given an animation of T frames rendered at 1x, 2x, 4x and 8x (same geometry), let
// R_t = the x8 frame t resolved to 1x with the Mitchell filter (aa::downscaleMitchell, the
// supersampled truth) and O_t = the method's output for frame t (ssaax2/ddaa2p take the
// x2 frame, ssaax4 the x4 frame). With frame-to-frame differences, taken around the loop,
//   dO_t = O_{(t+1) mod T} - O_t,   dR_t = R_{(t+1) mod T} - R_t   (RGB in [0, 1], signed),
//   flicker   = sqrt(mean over t, pixels and RGB of (dO_t - dR_t)^2)   (reported in levels, x255)
//   tPSNR     = 10 log10(1 / mean((dO_t - dR_t)^2))                   (dB, higher is steadier)
//   PSNR      = 10 log10(1 / mean over t of mse(O_t, R_t))             (per-frame quality at 1x)
// A method that changes a pixel exactly as the truth changes it has flicker 0; an
// aliased edge that jumps a whole pixel while the truth moves smoothly scores badly.
// Each frame is also scored under the truth protocol of quality.hpp (O_t against R_t:
// PSNR, SSIM, largest and 99th-percentile per-pixel error), kept per frame and averaged.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/eval/quality.hpp"

namespace ssfx::eval {

//! Frame `frame` of the animation at `scale` (1, 2, 4 or 8).
using FrameFn = std::function<ImageRgba8(int frame, int scale)>;

//! The frames of an animation at each scale, asked for in order t = 0, 1, ... at each
//! scale (each scale on its own); a view stays valid until the next call at its scale.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual int frames() const = 0;
    virtual ImageView<const Rgba8> frame(int t, int scale) = 0;
};
//! A FrameFn as a source (each call draws the frame; the last one of each scale is kept).
std::unique_ptr<FrameSource> drawnFrames(int frames, FrameFn frame);
//! The animation stored as APNG files DIR/NAME.png, NAMEx2.png, NAMEx4.png, NAMEx8.png,
//! each streamed with io::ApngReader: one frame of each scale in memory, whatever the frame
//! count (the x8 file's own frame count; the others must have as many). Files are opened
//! when their scale is first asked for.
std::unique_ptr<FrameSource> apngFrames(const std::string& dir, const std::string& name);

struct TemporalOptions {
    std::vector<std::string> methods;  //!< ids; empty = the quality table's order
    MethodSettings settings;
    Exec exec;
    ProgressFn progress;
    //! Keep every 1x output and truth frame in TemporalRun (off: memory stays a few 1x
    //! frames per method; use onFrame to write them out as they come).
    bool keepOutputs = true;
    //! Called for every frame with the methods' outputs (in `methods` order) and R_t.
    std::function<void(int t, const std::vector<ImageRgba8>& outputs, const ImageRgba8& truth)> onFrame;
};

struct TemporalResult {
    std::string method;
    double flickerLevels;        //!< RMS error of frame-to-frame differences, in 8-bit levels
    double temporalPsnr;         //!< dB
    double psnr;                 //!< dB, outputs vs resolved x8 frames (of the whole sequence's MSE)
    std::vector<Scores> frames;  //!< per frame t: O_t against R_t (the truth protocol)
    Scores mean;                 //!< the mean of `frames`, metric by metric
};

struct TemporalRun {
    std::vector<TemporalResult> results;           //!< one per method, in order
    std::vector<std::vector<ImageRgba8>> outputs;  //!< outputs[m][t] (with keepOutputs)
    std::vector<ImageRgba8> truth;                 //!< R_t (with keepOutputs)
};

//! Runs every method on every frame, streaming: frame t of each scale is read, the x8 one
//! resolved to R_t and dropped, the outputs scored and dropped (unless keepOutputs).
//! Needs frames >= 2.
TemporalRun evaluateTemporal(FrameSource& source, const TemporalOptions& options);
TemporalRun evaluateTemporal(int frames, const FrameFn& frame, const TemporalOptions& options);

//! `--source given`: scores outputs made elsewhere, frame by frame: `given` pairs a method
//! name with an APNG of its 1x outputs (e.g. the DDAA author's DIR/NAME_METHOD.png), each
//! streamed, against the source's resolved x8 frames. Every animation must have the source's
//! frame count and 1x size.
TemporalRun evaluateTemporalGiven(FrameSource& source, const std::vector<std::pair<std::string, std::string>>& given,
                                  const TemporalOptions& options);

//! The metrics accumulated one frame at a time (memory: the first and the previous frame
//! of both sequences), so that any number of frames can be scored.
class TemporalScorer {
public:
    explicit TemporalScorer(Exec exec = {}) : exec_(exec) {}
    //! Output and truth of the next frame (all frames of one size).
    void add(ImageView<const Rgba8> output, ImageView<const Rgba8> truth);
    //! The scores, closing the loop from the last frame to the first. Needs >= 2 frames.
    TemporalResult result() const;

private:
    Exec exec_;
    ImageRgba8 firstOut_, firstRef_, prevOut_, prevRef_;
    std::uint64_t flickerSum_ = 0;  //!< sum of squared differences of differences (levels^2)
    double mseSum_ = 0;
    std::vector<Scores> frameScores_;
    int frames_ = 0;
};

//! The metrics for one sequence of outputs against the truth's sequence (same sizes).
TemporalResult temporalScore(const std::vector<ImageRgba8>& outputs, const std::vector<ImageRgba8>& truth,
                             const Exec& exec = {});

//! Markdown table (method, flicker, tPSNR, PSNR, then the per-frame means of PSNR, SSIM and
//! the errors) and JSON {"METHOD": {"flicker_levels", "temporal_psnr", "psnr", "mean":
//! {"psnr", "ssim", "max_error", "p99_error"}, "frames": {"psnr": [...], ...}}}.
std::string temporalMarkdown(const std::vector<TemporalResult>& results);
std::string temporalJson(const std::vector<TemporalResult>& results);

}  // namespace ssfx::eval
