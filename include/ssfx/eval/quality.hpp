// The DDAA paper's quality protocol (spec ppaa.md section 3, Table 2), on any directory of
// renders named like ssfx's test images: NAME.png (1x), NAMEx2.png, NAMEx4.png and
// NAMEx8.png (the truth), optionally NAME_METHOD.png (a method's output, for
// OutputSource::Given).
//
// For every image and method, the method's 1x output (ssaax2 and ddaa2p take the x2 render,
// ssaax4 the x4 render) is scored under two protocols (docs/evaluation.md):
//  - paper: the output upscaled x8 with the Mitchell filter (aa::upscaleMitchell) against
//    the x8 render, the paper's Table 2. Its reference is aliased too (a sharp x8 render), so
//    it rewards staying sharp: the aliased input itself scores well.
//  - truth: the output against the truth, the x8 render resolved to 1x with the Mitchell
//    filter (aa::downscaleMitchell): how close a method gets to the anti-aliased image.
// Under each, PSNR, SSIM and the largest and 99th-percentile per-pixel error (metrics.hpp)
// over the whole image and over its edge pixels only: the 1x pixels where the truth differs
// from the aliased 1x render, the pixels anti-aliasing exists for (flat regions, where every
// method is exact, do not dilute the figures). Under the paper protocol a 1x edge pixel
// selects its 8x8 block of the x8 images (an SSIM window).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"

namespace ssfx::eval {

//! Column order of the tables: the paper's Table 2 (ssaax4 ssaax2 blur fxaa3c fxaa3d ddaa1
//! ddaa2), then ddaa2p and noaa (no anti-aliasing, the floor every method should beat).
std::vector<std::string> paperMethodOrder();

//! Names NAME for which DIR has NAME.png (a still PNG) and NAMEx8.png, sorted with ssfx's
//! test images first in their usual order. Throws ssfx::Error if DIR is not a directory.
std::vector<std::string> findRenderSets(const std::string& dir);
//! A render set's file name: NAME.png at scale 1, NAMExS.png at scale S (the x8 is the truth's).
std::string renderSetFile(const std::string& name, int scale);
//! The same in `dir`.
std::string renderSetPath(const std::string& dir, const std::string& name, int scale);

enum class OutputSource {
    Compute,  //!< run each method on the renders
    Given,    //!< read NAME_METHOD.png from the directory
};

enum class Protocol { Paper, Truth };
//! "paper", "truth".
const char* protocolName(Protocol protocol);
//! "paper", "truth" or "both" (both in that order); throws ssfx::Error for anything else.
std::vector<Protocol> parseProtocols(const std::string& text);

//! Which pixels a score covers.
enum class Region { All, Edges };

//! One cell of a table: NaN where there was no output (a missing NAME_METHOD.png, or a
//! missing x2/x4 render for a resolve) or nothing to measure (no edge pixels; SSIM of an
//! image smaller than 8x8).
struct Scores {
    double psnr, ssim;          //!< dB (+infinity when exact); SSIM
    double maxError, p99Error;  //!< per-pixel error, levels
};
//! The metrics of a Scores, in table order, with their names and units.
enum class Metric { Psnr, Ssim, MaxError, P99Error };
inline constexpr Metric kMetrics[] = {Metric::Psnr, Metric::Ssim, Metric::MaxError, Metric::P99Error};
double value(const Scores& scores, Metric metric);
const char* metricKey(Metric metric);    //!< "psnr", "ssim", "max_error", "p99_error"
const char* metricTitle(Metric metric);  //!< "PSNR (dB)", "SSIM", "max error (levels)", ...
int metricDecimals(Metric metric);       //!< in tables: PSNR 3, SSIM 4, errors 1

struct QualityOptions {
    std::vector<Protocol> protocols{Protocol::Paper, Protocol::Truth};
    std::vector<std::string> methods;  //!< ids in column order; empty = paperMethodOrder()
    std::vector<std::string> images;   //!< names; empty = findRenderSets(dir)
    OutputSource source = OutputSource::Compute;
    //! Compute: preset and filtering apply to every method that accepts them; each named
    //! parameter to the methods that have it (an error if no chosen method has it).
    MethodSettings settings;
    std::string outputsDir;  //!< Compute: also write NAME_METHOD.png here when set
    Exec exec;
    ProgressFn progress;  //!< one line per image and method
};

struct QualityTable {
    std::vector<std::string> images, methods;
    std::vector<Protocol> protocols;               //!< those evaluated, in order
    std::vector<std::int64_t> pixels, edgePixels;  //!< per image, at 1x (the edge mask's size)
    //! scores[p][r][i][m]: protocols[p], Region r, images[i], methods[m].
    std::vector<std::array<std::vector<std::vector<Scores>>, 2>> scores;

    bool has(Protocol protocol) const;
    //! Throws ssfx::Error when `protocol` was not evaluated.
    const Scores& at(Protocol protocol, Region region, std::size_t image, std::size_t method) const;
    double value(Protocol protocol, Region region, Metric metric, std::size_t image, std::size_t method) const {
        return eval::value(at(protocol, region, image, method), metric);
    }
    //! Mean over the images that have a value (NaN if none).
    double mean(Protocol protocol, Region region, Metric metric, std::size_t method) const;
    //! The paper's Table 2 figures (whole image).
    double psnr(std::size_t i, std::size_t m) const { return value(Protocol::Paper, Region::All, Metric::Psnr, i, m); }
    double ssim(std::size_t i, std::size_t m) const { return value(Protocol::Paper, Region::All, Metric::Ssim, i, m); }
};

//! PSNR and SSIM of a 1x output against the x8 render, the paper's protocol (the output is
//! upscaled x8).
struct Score {
    double psnr, ssim;
};
Score scoreAgainstX8(ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x, const Exec& exec = {});

//! The truth of a render set: the x8 render resolved to 1x with the Mitchell filter.
ImageRgba8 resolveTruth(ImageView<const Rgba8> render8x, const Exec& exec = {});
//! The edge mask: 1 where the truth differs from the aliased 1x render in R, G or B.
Image<std::uint8_t> edgeMask(ImageView<const Rgba8> truth1x, ImageView<const Rgba8> render1x);

//! Every figure of `output1x` under `protocol` for one Region (`edges` empty: the whole
//! image). `render8x` is read by the paper protocol, `truth1x` by the truth protocol.
Scores scoreOutput(Protocol protocol, ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x,
                   ImageView<const Rgba8> truth1x, ImageView<const std::uint8_t> edges, const Exec& exec = {});

QualityTable evaluateQuality(const std::string& dir, const QualityOptions& options);

//! The part of `settings` that applies to `method` (see QualityOptions::settings).
MethodSettings settingsFor(const MethodInfo& method, const MethodSettings& settings);
//! Throws ssfx::Error naming any parameter of `settings` that none of `methods` has.
void checkSettingsApply(const std::vector<std::string>& methods, const MethodSettings& settings);

//! {"protocols": ["paper", "truth"], "pixels": {IMAGE: n}, "edge_pixels": {IMAGE: n},
//!  "paper": {"all": {"psnr": {IMAGE: {METHOD: dB}}, "ssim": ..., "max_error": ...,
//!  "p99_error": ..., "mean": {"psnr": {METHOD: dB}, ...}}, "edges": {...}}, "truth": {...}};
//! infinite PSNR is written as null.
std::string qualityJson(const QualityTable& table);
//! For each protocol and region, one Markdown table per metric (PSNR in dB to 3 decimals,
//! SSIM to 4, errors in levels), image rows plus a mean row, and the edge masks' sizes.
std::string qualityMarkdown(const QualityTable& table);
//! The same as aligned plain text for a terminal.
std::string qualityText(const QualityTable& table);

}  // namespace ssfx::eval
