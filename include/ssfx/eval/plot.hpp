// Charts for the report, drawn with Cairo (antialiased, DejaVu Sans) into RGBA images that
// the caller writes as PNG: grouped bars (one group per category, one bar per series, as
// the DDAA paper's Figure 8 PSNR chart), stacked bars (the frame profile) and line charts (the
// kernel experiment).
#pragma once

#include <string>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::eval {

struct Series {
    std::string name;
    std::vector<double> values;  //!< one per category (bars) or per x value (lines); NaN = no value
};

//! A chart's size, title and axis labels. Every value axis label names its unit in parentheses
//! ("PSNR (dB)", "SSIM (unitless, 1 = identical)"), and so does a line chart's x label; a bar
//! chart's x label names its categories ("image"). The charts throw ssfx::Error otherwise.
struct ChartStyle {
    int width = 880, height = 420;
    std::string title, xLabel, yLabel;
    bool logY = false;      //!< logarithmic y axis (values must be > 0)
    bool zeroBased = true;  //!< bars start at 0; false: the axis starts just below the smallest value
};

ImageRgba8 groupedBarChart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                           const ChartStyle& style);
//! One bar per category, the series stacked in order from the axis up (a frame profile: one
//! bar per frame, one segment per pass); the axis starts at 0. Values must be >= 0 (NaN: none).
ImageRgba8 stackedBarChart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                           const ChartStyle& style);
ImageRgba8 lineChart(const std::vector<double>& x, const std::vector<Series>& series, const ChartStyle& style);

//! The ticks of a value axis over [lo, hi]: steps of 1, 2 or 5 times a power of ten, about
//! six of them (log axes: the powers of ten).
std::vector<double> axisTicks(double lo, double hi, bool log);
//! Their labels, with as many decimals as the step needs (0.80, 0.82, ... not 0.8, 0.8) and
//! never two alike.
std::vector<std::string> tickLabels(const std::vector<double>& ticks, bool log);

//! A heat map of a float image: lo -> dark blue, through cyan, green, yellow, to red at hi
//! (a piecewise-linear "jet"-like ramp, clamped); NaN -> black.
ImageRgba8 heatMap(ImageView<const float> values, float lo, float hi);

}  // namespace ssfx::eval
