// Report charts (see plot.hpp).
#include "ssfx/eval/plot.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "src/eval/cairo_image.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::eval {

namespace {

// Colour-blind-friendly palette (Okabe and Ito, 2008), then greys.
constexpr double kPalette[][3] = {{0.90, 0.62, 0.00}, {0.34, 0.71, 0.91}, {0.00, 0.62, 0.45}, {0.94, 0.89, 0.26},
                                  {0.00, 0.45, 0.70}, {0.84, 0.37, 0.00}, {0.80, 0.47, 0.65}, {0.30, 0.30, 0.30},
                                  {0.65, 0.65, 0.65}, {0.10, 0.10, 0.10}};

struct Surface {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> s{nullptr, cairo_surface_destroy};
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr{nullptr, cairo_destroy};
    Surface(int w, int h) {
        s.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
        cr.reset(cairo_create(s.get()));
        cairo_set_source_rgb(cr.get(), 1, 1, 1);
        cairo_paint(cr.get());
        cairo_select_font_face(cr.get(), "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    }
    ImageRgba8 image() { return detail::imageFromCairo(s.get()); }
};

void text(cairo_t* cr, double x, double y, const std::string& s, double size, double alignX, bool bold = false) {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    cairo_move_to(cr, x - alignX * e.x_advance, y);
    cairo_show_text(cr, s.c_str());
}

}  // namespace

std::vector<double> axisTicks(double lo, double hi, bool log) {
    std::vector<double> t;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return t;
    if (log) {
        for (double p = std::pow(10.0, std::floor(std::log10(lo))); p <= hi * 1.0001; p *= 10)
            if (p >= lo * 0.9999) t.push_back(p);
        return t;
    }
    const double raw = (hi - lo) / 6, mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
    // Multiples of the step by an integer count, so that no sum of rounding errors drifts.
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; ++k) t.push_back(k * step);
    return t;
}

std::vector<std::string> tickLabels(const std::vector<double>& ticks, bool log) {
    std::vector<std::string> labels;
    if (log) {
        for (double t : ticks) labels.push_back(fmt::format("{:g}", t));
        return labels;
    }
    // The step's decimals (0.02: 2, 0.5: 1, 5: 0), more if two labels still come out alike.
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
    int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
    for (;; ++decimals) {
        labels.clear();
        for (double t : ticks) labels.push_back(fmt::format("{:.{}f}", std::abs(t) < step * 1e-6 ? 0.0 : t, decimals));
        bool distinct = true;
        for (std::size_t i = 1; i < labels.size(); ++i) distinct = distinct && labels[i] != labels[i - 1];
        if (distinct || decimals >= 9) return labels;
    }
}

namespace {

// A value axis: maps values to pixels, with "nice" ticks.
struct Axis {
    double lo, hi;
    bool log;
    double top, bottom;
    double map(double v) const {
        const double a = log ? std::log10(lo) : lo, b = log ? std::log10(hi) : hi;
        const double t = ((log ? std::log10(v) : v) - a) / (b - a);
        return bottom - t * (bottom - top);
    }
    std::vector<double> ticks() const { return axisTicks(lo, hi, log); }
};

Axis valueAxis(const std::vector<Series>& series, const ChartStyle& st, double top, double bottom) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& s : series)
        for (double v : s.values)
            if (std::isfinite(v) && (!st.logY || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!std::isfinite(lo)) lo = 0, hi = 1;
    if (st.logY) {
        lo = std::pow(10.0, std::floor(std::log10(lo)));
        hi = std::pow(10.0, std::ceil(std::log10(hi)));
        if (hi <= lo) hi = lo * 10;
    } else {
        const double pad = (hi - lo) * 0.08 + 1e-9;
        lo = st.zeroBased ? std::min(0.0, lo) : lo - pad;
        hi = hi + pad;
        if (hi - lo > 5) lo = std::floor(lo), hi = std::ceil(hi);
    }
    return {lo, hi, st.logY, top, bottom};
}

void frame(cairo_t* cr, const ChartStyle& st, const Axis& ax, double left, double right) {
    cairo_set_line_width(cr, 1);
    const std::vector<double> ticks = ax.ticks();
    const std::vector<std::string> labels = tickLabels(ticks, ax.log);
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const double t = ticks[i];
        const double y = std::round(ax.map(t)) + 0.5;
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, left, y);
        cairo_line_to(cr, right, y);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text(cr, left - 6, y + 4, labels[i], 11, 1.0);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_rectangle(cr, left + 0.5, ax.top + 0.5, right - left, ax.bottom - ax.top);
    cairo_stroke(cr);
    text(cr, st.width / 2.0, 22, st.title, 15, 0.5, true);
    if (!st.xLabel.empty()) text(cr, (left + right) / 2, st.height - 8, st.xLabel, 12, 0.5);
    cairo_save(cr);
    cairo_translate(cr, 16, (ax.top + ax.bottom) / 2);
    cairo_rotate(cr, -M_PI / 2);
    text(cr, 0, 0, st.yLabel, 12, 0.5);
    cairo_restore(cr);
}

void legend(cairo_t* cr, const std::vector<Series>& series, double x, double y) {
    for (std::size_t i = 0; i < series.size(); ++i) {
        const auto* c = kPalette[i % std::size(kPalette)];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_rectangle(cr, x, y + 18.0 * double(i), 12, 12);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(cr, x + 18, y + 18.0 * double(i) + 10, series[i].name, 12, 0.0);
    }
}

void checkStyle(const ChartStyle& st) {
    if (st.width < 200 || st.height < 150 || st.width > 4000 || st.height > 4000)
        throw Error(fmt::format("chart size {}x{} is not in [200, 4000] x [150, 4000]", st.width, st.height));
    // Every value axis says what it measures and in which unit: "PSNR (dB)".
    if (st.yLabel.find('(') == std::string::npos || st.yLabel.find(')') == std::string::npos)
        throw Error(
            fmt::format("chart '{}': the value axis label '{}' names no unit, e.g. 'PSNR (dB)'", st.title, st.yLabel));
    if (st.xLabel.empty()) throw Error(fmt::format("chart '{}': no x-axis label", st.title));
}

// The parts every chart shares: validated sizes, a white surface, the plot area, the value
// axis with its grid and labels, the title.
struct Chart {
    Surface sf;
    double left, right, top, bottom;
    Axis ax;
    Chart(const ChartStyle& st, const std::vector<Series>& series, std::size_t valuesPerSeries, const char* unit)
        : sf((checkStyle(st), st.width), st.height),
          left(64),
          right(st.width - 110),
          top(36),
          bottom(st.height - 48),
          ax(valueAxis(series, st, top, bottom)) {
        for (const auto& s : series)
            if (s.values.size() != valuesPerSeries)
                throw Error(fmt::format("chart: series '{}' has {} values for {} {}", s.name, s.values.size(),
                                        valuesPerSeries, unit));
        frame(sf.cr.get(), st, ax, left, right);
    }
};

}  // namespace

ImageRgba8 groupedBarChart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                           const ChartStyle& st) {
    Chart ch(st, series, categories.size(), "categories");
    cairo_t* cr = ch.sf.cr.get();
    const double left = ch.left, right = ch.right, top = ch.top, bottom = ch.bottom;
    const Axis& ax = ch.ax;
    const double groupW = (right - left) / double(std::max<std::size_t>(1, categories.size()));
    const double barW = groupW * 0.8 / double(std::max<std::size_t>(1, series.size()));
    for (std::size_t g = 0; g < categories.size(); ++g) {
        const double gx = left + groupW * double(g) + groupW * 0.1;
        for (std::size_t s = 0; s < series.size(); ++s) {
            const double v = series[s].values[g];
            if (!std::isfinite(v) || (st.logY && v <= 0)) continue;
            const double y = ax.map(std::clamp(v, ax.lo, ax.hi));
            const auto* c = kPalette[s % std::size(kPalette)];
            cairo_set_source_rgb(cr, c[0], c[1], c[2]);
            cairo_rectangle(cr, gx + barW * double(s), y, barW - 1, bottom - y);
            cairo_fill(cr);
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(cr, gx + groupW * 0.4, bottom + 16, categories[g], 12, 0.5);
    }
    legend(cr, series, right + 12, top + 4);
    return ch.sf.image();
}

ImageRgba8 stackedBarChart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                           const ChartStyle& st) {
    if (st.logY) throw Error(fmt::format("chart '{}': stacked bars need a linear axis", st.title));
    // The value axis spans the stacks' totals, from 0.
    Series totals{"total", std::vector<double>(categories.size(), 0.0)};
    for (const auto& s : series) {
        if (s.values.size() != categories.size())
            throw Error(fmt::format("chart: series '{}' has {} values for {} categories", s.name, s.values.size(),
                                    categories.size()));
        for (std::size_t g = 0; g < categories.size(); ++g) {
            if (s.values[g] < 0)
                throw Error(
                    fmt::format("chart '{}': stacked value {} of '{}' is negative", st.title, s.values[g], s.name));
            if (std::isfinite(s.values[g])) totals.values[g] += s.values[g];
        }
    }
    ChartStyle zero = st;
    zero.zeroBased = true;
    Chart ch(zero, {totals}, categories.size(), "categories");
    cairo_t* cr = ch.sf.cr.get();
    const double groupW = (ch.right - ch.left) / double(std::max<std::size_t>(1, categories.size()));
    for (std::size_t g = 0; g < categories.size(); ++g) {
        const double gx = ch.left + groupW * double(g) + groupW * 0.15;
        double below = 0;  // the stack so far
        for (std::size_t s = 0; s < series.size(); ++s) {
            const double v = series[s].values[g];
            if (!std::isfinite(v) || v == 0) continue;
            const double y0 = ch.ax.map(std::min(below, ch.ax.hi)), y1 = ch.ax.map(std::min(below + v, ch.ax.hi));
            below += v;
            const auto* c = kPalette[s % std::size(kPalette)];
            cairo_set_source_rgb(cr, c[0], c[1], c[2]);
            cairo_rectangle(cr, gx, y1, groupW * 0.7, y0 - y1);
            cairo_fill(cr);
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(cr, gx + groupW * 0.35, ch.bottom + 16, categories[g], 12, 0.5);
    }
    legend(cr, series, ch.right + 12, ch.top + 4);
    return ch.sf.image();
}

ImageRgba8 lineChart(const std::vector<double>& x, const std::vector<Series>& series, const ChartStyle& st) {
    if (x.size() < 2) throw Error("chart: a line chart needs at least two x values");
    if (st.xLabel.find('(') == std::string::npos)
        throw Error(fmt::format("chart '{}': the x axis label '{}' names no unit", st.title, st.xLabel));
    Chart ch(st, series, x.size(), "x values");
    cairo_t* cr = ch.sf.cr.get();
    const double left = ch.left, right = ch.right, bottom = ch.bottom;
    const Axis& ax = ch.ax;
    const double x0 = x.front(), x1 = x.back();
    auto mapX = [&](double v) { return left + (v - x0) / (x1 - x0) * (right - left); };
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    // The x axis gets the value axis's ticks (1, 2 or 5 times a power of ten, distinct labels).
    const std::vector<double> xTicks = axisTicks(x0, x1, false);
    const std::vector<std::string> xLabels = tickLabels(xTicks, false);
    for (std::size_t i = 0; i < xTicks.size(); ++i)
        if (xTicks[i] >= x0 - 1e-9 * std::abs(x1 - x0) && xTicks[i] <= x1 + 1e-9 * std::abs(x1 - x0))
            text(cr, mapX(xTicks[i]), bottom + 16, xLabels[i], 11, 0.5);
    for (std::size_t s = 0; s < series.size(); ++s) {
        const auto* c = kPalette[s % std::size(kPalette)];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_set_line_width(cr, 1.5);
        bool pen = false;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double v = series[s].values[i];
            if (!std::isfinite(v)) {
                pen = false;
                continue;
            }
            const double px = mapX(x[i]), py = ax.map(std::clamp(v, ax.lo, ax.hi));
            if (pen)
                cairo_line_to(cr, px, py);
            else
                cairo_move_to(cr, px, py);
            pen = true;
        }
        cairo_stroke(cr);
    }
    legend(cr, series, right + 12, ch.top + 4);
    return ch.sf.image();
}

ImageRgba8 heatMap(ImageView<const float> values, float lo, float hi) {
    // Stops of the ramp at t = 0, 0.25, 0.5, 0.75, 1.
    static constexpr float kStops[5][3] = {
        {0.05f, 0.05f, 0.45f}, {0.0f, 0.6f, 0.9f}, {0.2f, 0.8f, 0.2f}, {0.95f, 0.85f, 0.1f}, {0.85f, 0.05f, 0.05f}};
    ImageRgba8 out(values.width(), values.height());
    const float span = hi > lo ? hi - lo : 1.0f;
    for (int y = 0; y < values.height(); ++y)
        for (int x = 0; x < values.width(); ++x) {
            const float v = values(x, y);
            if (std::isnan(v)) {
                out(x, y) = {0, 0, 0, 255};
                continue;
            }
            const float t = std::clamp((v - lo) / span, 0.0f, 1.0f) * 4.0f;
            const int i = std::min(int(t), 3);
            const float f = t - float(i);
            Rgba8 c{0, 0, 0, 255};
            std::uint8_t* ch[3] = {&c.r, &c.g, &c.b};
            for (int k = 0; k < 3; ++k)
                *ch[k] = std::uint8_t(std::lround(255.0f * (kStops[i][k] * (1.0f - f) + kStops[i + 1][k] * f)));
            out(x, y) = c;
        }
    return out;
}

}  // namespace ssfx::eval
