// The evaluation's test images (see test_images.hpp), drawn with Cairo. Every coordinate
// below is in scale-1 pixels; cairo_scale() maps them to the requested scale, so line
// widths, radii and font sizes scale with the geometry. Antialiasing is off for shapes and
// text: these are the aliased renders whose anti-aliasing the methods are judged on.
#include "ssfx/eval/test_images.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "src/eval/cairo_image.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::eval {

namespace {

constexpr double kPi = std::numbers::pi;

constexpr std::array<TestImageInfo, 4> kImages{{
    {"lines", 600, 600, 1, 0,
     "stars of 1 px and 4 px lines, growing squares and circles, near-horizontal fans, rotated grids"},
    {"circles", 480, 480, 1, 0, "rings and discs in nine colours on white, black, grey (green's luma) and dark grey"},
    {"plot", 640, 480, 1, 0, "a line plot with text: axes, ticks, labels, title, grid, thick curves with markers"},
    {"animated", 600, 600, 32, 25, "rotating cross, orbiting circles, slanting fans of vertical lines (loops)"},
}};

struct Colour {
    double r, g, b;
};
constexpr Colour rgb8(int r, int g, int b) { return {r / 255.0, g / 255.0, b / 255.0}; }
constexpr Colour kBlack = rgb8(0, 0, 0), kWhite = rgb8(255, 255, 255);

// The surface and context of one render, with the scale applied.
class Canvas {
public:
    Canvas(int width, int height, int scale) {
        surface_.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width * scale, height * scale));
        if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS)
            throw Error(fmt::format("cairo: cannot create a {}x{} surface", width * scale, height * scale));
        cr_.reset(cairo_create(surface_.get()));
        cairo_scale(cr_.get(), scale, scale);
        cairo_set_antialias(cr_.get(), CAIRO_ANTIALIAS_NONE);
        // Text: no antialiasing, no hinting, unhinted metrics, so that the glyph outlines
        // (and the layout) scale exactly with the rest of the drawing.
        cairo_font_options_t* fo = cairo_font_options_create();
        cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_NONE);
        cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
        cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
        cairo_set_font_options(cr_.get(), fo);
        cairo_font_options_destroy(fo);
        cairo_set_line_cap(cr_.get(), CAIRO_LINE_CAP_BUTT);
    }
    cairo_t* cr() const { return cr_.get(); }

    void colour(Colour c) const { cairo_set_source_rgb(cr(), c.r, c.g, c.b); }
    void fillRect(double x, double y, double w, double h, Colour c) const {
        colour(c);
        cairo_rectangle(cr(), x, y, w, h);
        cairo_fill(cr());
    }
    void line(double ax, double ay, double bx, double by, double width, Colour c) const {
        colour(c);
        cairo_set_line_width(cr(), width);
        cairo_move_to(cr(), ax, ay);
        cairo_line_to(cr(), bx, by);
        cairo_stroke(cr());
    }
    void circle(double cx, double cy, double r, double width, Colour c) const {  // width 0: filled
        colour(c);
        cairo_new_sub_path(cr());
        cairo_arc(cr(), cx, cy, r, 0, 2 * kPi);
        if (width > 0) {
            cairo_set_line_width(cr(), width);
            cairo_stroke(cr());
        } else {
            cairo_fill(cr());
        }
    }
    void text(double x, double y, const std::string& s, double size, Colour c, double alignX = 0,
              bool bold = false) const {
        colour(c);
        cairo_select_font_face(cr(), "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr(), size);
        cairo_text_extents_t e;
        cairo_text_extents(cr(), s.c_str(), &e);
        cairo_move_to(cr(), x - alignX * e.x_advance, y);
        cairo_show_text(cr(), s.c_str());
    }

    ImageRgba8 image() const { return detail::imageFromCairo(surface_.get()); }

private:
    struct SurfaceDel {
        void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
    };
    struct ContextDel {
        void operator()(cairo_t* c) const { cairo_destroy(c); }
    };
    std::unique_ptr<cairo_surface_t, SurfaceDel> surface_;
    std::unique_ptr<cairo_t, ContextDel> cr_;
};

// ---- lines ------------------------------------------------------------------------------

// `n` lines through (cx, cy), evenly spread over 180 degrees, inside a circle of the same width.
void star(const Canvas& c, double cx, double cy, int n, double width) {
    const double r = 120;
    for (int i = 0; i < n; ++i) {
        const double a = kPi * i / n;
        c.line(cx - r * std::cos(a), cy - r * std::sin(a), cx + r * std::cos(a), cy + r * std::sin(a), width, kBlack);
    }
    c.circle(cx, cy, r + 10, width, kBlack);
}

// A grid of n x n cells of `cell` px, centred on (cx, cy), rotated by `degrees`.
void grid(const Canvas& c, double cx, double cy, double degrees, double cell, int n) {
    cairo_save(c.cr());
    cairo_translate(c.cr(), cx, cy);
    cairo_rotate(c.cr(), degrees * kPi / 180);
    const double h = cell * n / 2;
    for (int i = 0; i <= n; ++i) {
        const double p = -h + i * cell;
        c.line(p, -h, p, h, 1, kBlack);
        c.line(-h, p, h, p, 1, kBlack);
    }
    cairo_restore(c.cr());
}

void drawLines(const Canvas& c) {
    c.fillRect(0, 0, 600, 600, kWhite);
    star(c, 150, 145, 32, 1);
    star(c, 450, 145, 16, 4);
    // Growing squares and circles: outline on the left half, filled on the right.
    const double sizes[] = {2, 3, 4, 6, 8, 10, 13, 16, 20};
    for (int filled = 0; filled < 2; ++filled) {
        double x = 20 + 300 * filled;
        for (double s : sizes) {
            if (filled) {
                c.fillRect(x, 300 - s / 2, s, s, kBlack);
                c.circle(x + s / 2, 335, s / 2, 0, kBlack);
            } else {
                c.colour(kBlack);
                cairo_set_line_width(c.cr(), 1);
                cairo_rectangle(c.cr(), x, 300 - s / 2, s, s);
                cairo_stroke(c.cr());
                c.circle(x + s / 2, 335, s / 2, 1, kBlack);
            }
            x += s + 10;
        }
    }
    // Fans of long near-horizontal lines (slopes 0 to 1/20), thin then thick.
    for (int k = 0; k <= 5; ++k) c.line(20, 365, 580, 365 + 5.6 * k, 1, kBlack);
    for (int k = 0; k <= 5; ++k) c.line(20, 425, 580, 425 - 5.6 * k, 3, kBlack);
    // Grids: columns by angle, rows by cell size (10, 5, 2 px).
    const double angles[] = {0, 1, 5, 10, 20, 45};
    for (int i = 0; i < 6; ++i) {
        const double cx = 55 + 98 * i;
        grid(c, cx, 485, angles[i], 10, 5);
        grid(c, cx, 548, angles[i], 5, 6);
        grid(c, cx, 585, angles[i], 2, 8);
    }
}

// ---- circles ------------------------------------------------------------------------------

void drawCircles(const Canvas& c) {
    // Backgrounds: white, black, a grey of (almost) the luma of pure green, dark grey.
    // luma = sqrt(0.299 r + 0.587 g + 0.114 b) (spec ppaa.md section 1): green (0,255,0)
    // gives sqrt(0.587) = 0.7662, grey 150 gives sqrt(150/255) = 0.7670.
    const Colour backgrounds[] = {kWhite, kBlack, rgb8(150, 150, 150), rgb8(85, 85, 85)};
    const Colour colours[] = {kBlack,
                              rgb8(128, 128, 128),
                              kWhite,
                              rgb8(255, 0, 0),
                              rgb8(0, 255, 0),
                              rgb8(0, 0, 255),
                              rgb8(0, 255, 255),
                              rgb8(255, 0, 255),
                              rgb8(255, 255, 0)};
    for (int q = 0; q < 4; ++q) {
        const double qx = 240 * (q % 2), qy = 240 * (q / 2);
        c.fillRect(qx, qy, 240, 240, backgrounds[q]);
        for (int i = 0; i < 9; ++i) {
            const double cx = qx + 40 + 80 * (i % 3), cy = qy + 40 + 80 * (i / 3);
            c.circle(cx, cy, 31, 4, colours[i]);
            c.circle(cx, cy, 19, 1, colours[i]);
            c.circle(cx, cy, 9, 0, colours[i]);
        }
    }
}

// ---- plot ----------------------------------------------------------------------------------

void drawPlot(const Canvas& c) {
    c.fillRect(0, 0, 640, 480, kWhite);
    // Plot area and data ranges: x in [0, 2 pi], y in [-1.25, 1.25].
    const double left = 72, right = 616, top = 48, bottom = 420;
    const double xMax = 2 * kPi, yMin = -1.25, yMax = 1.25;
    auto px = [&](double x) { return left + (right - left) * x / xMax; };
    auto py = [&](double y) { return bottom - (bottom - top) * (y - yMin) / (yMax - yMin); };
    const Colour gridColour = rgb8(222, 222, 222), axisColour = rgb8(40, 40, 40);
    // Light grid and ticks with labels.
    for (int i = 0; i <= 6; ++i) {
        c.line(px(i), top, px(i), bottom, 1, gridColour);
        c.line(px(i), bottom, px(i), bottom + 6, 1, axisColour);
        c.text(px(i), bottom + 22, std::to_string(i), 13, axisColour, 0.5);
    }
    for (int i = -2; i <= 2; ++i) {
        const double y = 0.5 * i;
        c.line(left, py(y), right, py(y), 1, gridColour);
        c.line(left - 6, py(y), left, py(y), 1, axisColour);
        c.text(left - 10, py(y) + 5, fmt::format("{:.1f}", y), 13, axisColour, 1.0);
    }
    // Frame, axis labels, title.
    c.colour(axisColour);
    cairo_set_line_width(c.cr(), 1);
    cairo_rectangle(c.cr(), left, top, right - left, bottom - top);
    cairo_stroke(c.cr());
    c.text((left + right) / 2, bottom + 46, "x (radians)", 14, axisColour, 0.5);
    cairo_save(c.cr());
    cairo_translate(c.cr(), 22, (top + bottom) / 2);
    cairo_rotate(c.cr(), -kPi / 2);
    c.text(0, 0, "amplitude", 14, axisColour, 0.5);
    cairo_restore(c.cr());
    c.text((left + right) / 2, 30, "Sine and cosine", 18, kBlack, 0.5, true);
    // Two thick curves with markers every 0.5 (diamonds on sine, circles on cosine).
    const Colour sineColour = rgb8(31, 119, 180), cosColour = rgb8(214, 39, 40);
    for (int curve = 0; curve < 2; ++curve) {
        auto f = [curve](double x) { return curve == 0 ? std::sin(x) : std::cos(x); };
        c.colour(curve == 0 ? sineColour : cosColour);
        cairo_set_line_width(c.cr(), 3);
        cairo_set_line_join(c.cr(), CAIRO_LINE_JOIN_ROUND);
        for (int i = 0; i <= 200; ++i) {
            const double x = xMax * i / 200;
            if (i == 0)
                cairo_move_to(c.cr(), px(x), py(f(x)));
            else
                cairo_line_to(c.cr(), px(x), py(f(x)));
        }
        cairo_stroke(c.cr());
        for (double x = 0; x <= xMax + 1e-9; x += 0.5) {
            const double mx = px(x), my = py(f(x));
            if (curve == 0) {
                cairo_move_to(c.cr(), mx, my - 7);
                cairo_line_to(c.cr(), mx + 7, my);
                cairo_line_to(c.cr(), mx, my + 7);
                cairo_line_to(c.cr(), mx - 7, my);
                cairo_close_path(c.cr());
                cairo_fill(c.cr());
            } else {
                c.circle(mx, my, 5, 0, cosColour);
            }
        }
    }
    // Legend.
    const double lx = right - 130, ly = top + 14;
    c.fillRect(lx, ly, 116, 52, kWhite);
    c.colour(axisColour);
    cairo_set_line_width(c.cr(), 1);
    cairo_rectangle(c.cr(), lx, ly, 116, 52);
    cairo_stroke(c.cr());
    c.line(lx + 10, ly + 17, lx + 40, ly + 17, 3, sineColour);
    c.line(lx + 10, ly + 37, lx + 40, ly + 37, 3, cosColour);
    c.text(lx + 48, ly + 22, "sin(x)", 13, axisColour);
    c.text(lx + 48, ly + 42, "cos(x)", 13, axisColour);
}

// ---- animated ------------------------------------------------------------------------------

void drawAnimated(const Canvas& c, int frame, int frames) {
    const double phase = double(frame) / frames;  // one loop over [0, 1)
    c.fillRect(0, 0, 600, 600, kWhite);
    // Rotating cross: thick arms at 0/90 degrees, thin ones at 45/135, turning by 90 degrees
    // per loop (the cross is symmetric under that turn, so the animation loops seamlessly).
    const double cx = 165, cy = 165, arm = 135, rot = phase * kPi / 2;
    for (int i = 0; i < 4; ++i) {
        const double a = rot + i * kPi / 4;
        const bool thick = i % 2 == 0;
        c.line(cx - arm * std::cos(a), cy - arm * std::sin(a), cx + arm * std::cos(a), cy + arm * std::sin(a),
               thick ? 6 : 1, thick ? rgb8(20, 20, 120) : kBlack);
    }
    // Circles orbiting an off-centre point.
    const double ox = 440, oy = 170, orbit = 95;
    const Colour orbitColours[] = {rgb8(200, 30, 30), rgb8(30, 150, 30), rgb8(30, 30, 200), kBlack, rgb8(200, 120, 0)};
    for (int k = 0; k < 5; ++k) {
        const double a = 2 * kPi * (phase + k / 5.0);
        const double r = 10 + 5 * k;
        c.circle(ox + orbit * std::cos(a), oy + orbit * std::sin(a), r, k % 2 == 0 ? 0 : 2, orbitColours[k]);
    }
    c.circle(ox, oy, 2, 0, kBlack);
    // Fans of vertical lines slanting back and forth: the foot of each line is fixed, its
    // top sways by up to 40 px, more for lines further right in each fan.
    const double sway = 40 * std::sin(2 * kPi * phase);
    for (int k = 0; k < 12; ++k) {
        const double t = (k + 1) / 12.0;
        const double x0 = 30 + 20 * k, x1 = 330 + 20 * k;
        c.line(x0, 575, x0 + sway * t, 350, 1, kBlack);
        c.line(x1, 575, x1 - sway * t, 350, 3, rgb8(90, 0, 90));
    }
}

}  // namespace

std::span<const TestImageInfo> testImages() { return kImages; }

const TestImageInfo& testImageByName(std::string_view name) {
    for (const auto& t : kImages)
        if (t.name == name) return t;
    std::string known;
    for (const auto& t : kImages) known += (known.empty() ? "" : ", ") + std::string(t.name);
    throw Error(fmt::format("unknown test image '{}' (known: {})", name, known));
}

ImageRgba8 drawTestImage(std::string_view name, int scale, int frame) {
    const TestImageInfo& info = testImageByName(name);
    if (scale < 1 || scale > 16) throw Error(fmt::format("test image scale must be 1..16, got {}", scale));
    if (frame < 0 || frame >= info.frames)
        throw Error(fmt::format("test image '{}' has {} frame(s), asked for frame {}", name, info.frames, frame));
    checkDimensions(std::int64_t{info.width} * scale, std::int64_t{info.height} * scale, std::string(name));
    const Canvas c(info.width, info.height, scale);
    if (name == "lines")
        drawLines(c);
    else if (name == "circles")
        drawCircles(c);
    else if (name == "plot")
        drawPlot(c);
    else
        drawAnimated(c, frame, info.frames);
    if (cairo_status(c.cr()) != CAIRO_STATUS_SUCCESS)
        throw Error(fmt::format("cairo: drawing '{}' failed: {}", name, cairo_status_to_string(cairo_status(c.cr()))));
    return c.image();
}

}  // namespace ssfx::eval
