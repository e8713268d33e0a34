// The DDAA paper's quality protocol (spec ppaa.md section 3, Table 2), on any directory of
// renders named like ssfx's test images: NAME.png (1x), NAMEx2.png, NAMEx4.png and
// NAMEx8.png (the truth), optionally NAME_METHOD.png (a method's output, for
// OutputSource::Given).
//
// For every image and method: the method's 1x output (ssaax2 and ddaa2p take the x2
// render, ssaax4 the x4 render) is upscaled x8 with the Mitchell filter
// (aa::upscaleMitchell) and compared with the x8 render by PSNR and SSIM (metrics.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/registry.hpp"

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

struct QualityOptions {
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
    //! psnr[i][m], ssim[i][m] for images[i], methods[m]; NaN where there was no output
    //! (a missing NAME_METHOD.png, or a missing x2/x4 render for a resolve).
    std::vector<std::vector<double>> psnr, ssim;
    //! Mean over the images that have a value (NaN if none).
    double meanPsnr(std::size_t m) const;
    double meanSsim(std::size_t m) const;
};

//! PSNR and SSIM of a 1x output against the x8 render (the truth) (the output is upscaled x8).
struct Score {
    double psnr, ssim;
};
Score scoreAgainstX8(ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x, const Exec& exec = {});

QualityTable evaluateQuality(const std::string& dir, const QualityOptions& options);

//! The part of `settings` that applies to `method` (see QualityOptions::settings).
MethodSettings settingsFor(const MethodInfo& method, const MethodSettings& settings);
//! Throws ssfx::Error naming any parameter of `settings` that none of `methods` has.
void checkSettingsApply(const std::vector<std::string>& methods, const MethodSettings& settings);

//! {"psnr": {IMAGE: {METHOD: dB}}, "ssim": {...}, "mean": {"psnr": {...}, "ssim": {...}}};
//! infinite PSNR is written as null.
std::string qualityJson(const QualityTable& table);
//! Two Markdown tables (PSNR in dB to 3 decimals, SSIM to 4), image rows plus a mean row.
std::string qualityMarkdown(const QualityTable& table);
//! The same as aligned plain text for a terminal.
std::string qualityText(const QualityTable& table);

}  // namespace ssfx::eval
