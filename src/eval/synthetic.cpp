// Synthetic aliased drawing (see synthetic.hpp). Each primitive is rasterised over its
// bounding box by testing the pixel centre, in the scale-1 coordinate system.
#include "ssfx/eval/synthetic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ssfx::eval {

namespace {

struct Canvas {
    ImageRgba8& img;
    double scale;
    // Paints pixels whose centre (in scale-1 units) satisfies inside(px, py) in [x0,x1]x[y0,y1].
    template <class Inside>
    void fill(double x0, double y0, double x1, double y1, Rgba8 c, const Inside& inside) {
        const int ix0 = std::max(0, int(std::floor(x0 * scale)));
        const int iy0 = std::max(0, int(std::floor(y0 * scale)));
        const int ix1 = std::min(img.width() - 1, int(std::ceil(x1 * scale)));
        const int iy1 = std::min(img.height() - 1, int(std::ceil(y1 * scale)));
        for (int y = iy0; y <= iy1; ++y)
            for (int x = ix0; x <= ix1; ++x)
                if (inside((x + 0.5) / scale, (y + 0.5) / scale)) img(x, y) = c;
    }
    void rect(double x0, double y0, double x1, double y1, Rgba8 c) {
        fill(x0, y0, x1, y1, c, [&](double px, double py) { return px >= x0 && px < x1 && py >= y0 && py < y1; });
    }
    void line(double ax, double ay, double bx, double by, double width, Rgba8 c) {
        const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy, r = width / 2;
        fill(std::min(ax, bx) - r, std::min(ay, by) - r, std::max(ax, bx) + r, std::max(ay, by) + r, c,
             [&](double px, double py) {
                 const double t = std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0);
                 const double qx = ax + t * dx - px, qy = ay + t * dy - py;
                 return qx * qx + qy * qy <= r * r;
             });
    }
    void ring(double cx, double cy, double radius, double width, Rgba8 c) {
        const double ro = radius + width / 2, ri = std::max(0.0, radius - width / 2);
        fill(cx - ro, cy - ro, cx + ro, cy + ro, c, [&](double px, double py) {
            const double d2 = (px - cx) * (px - cx) + (py - cy) * (py - cy);
            return d2 <= ro * ro && d2 >= ri * ri;
        });
    }
    void disc(double cx, double cy, double radius, Rgba8 c) { ring(cx, cy, radius / 2, radius, c); }
};

}  // namespace

ImageRgba8 syntheticScene(int width, int height, int scale) {
    ImageRgba8 img(width * scale, height * scale, Rgba8{255, 255, 255, 255});
    Canvas cv{img, double(scale)};
    const Rgba8 black{0, 0, 0, 255}, grey{128, 128, 128, 255}, red{220, 40, 40, 255}, blue{40, 70, 220, 255};
    const Rgba8 green{0, 160, 0, 255}, dark{30, 30, 40, 255}, yellow{240, 200, 40, 255};
    constexpr double pi = std::numbers::pi;
    // Tiles of 240 x 240 units, repeated over the image with varying content.
    for (double ty = 0; ty < height; ty += 240)
        for (double tx = 0; tx < width; tx += 240) {
            const int tile = int(tx / 240) + int(ty / 240) * 3;  // staggered: columns differ per row
            const double cx = tx + 120, cy = ty + 120;
            switch (tile % 4) {
                case 0:  // star of thin and thick lines with a ring
                    for (int i = 0; i < 24; ++i) {
                        const double a = i * pi / 24 + 0.013 * tile;
                        cv.line(cx - 100 * std::cos(a), cy - 100 * std::sin(a), cx + 100 * std::cos(a),
                                cy + 100 * std::sin(a), i % 3 == 0 ? 4.0 : 1.0, black);
                    }
                    cv.ring(cx, cy, 105, 2, red);
                    break;
                case 1:  // discs and rings on a dark background, green on grey
                    cv.rect(tx, ty, tx + 240, ty + 240, dark);
                    cv.rect(tx + 120, ty + 120, tx + 240, ty + 240, grey);
                    for (int i = 0; i < 4; ++i) {
                        cv.disc(tx + 40 + 50 * i, ty + 50, 8 + 4 * i, i % 2 ? yellow : blue);
                        cv.ring(tx + 40 + 50 * i, ty + 180, 10 + 3 * i, 1 + i, i % 2 ? green : red);
                    }
                    break;
                case 2:  // fan of long near-horizontal lines
                    for (int i = 0; i < 14; ++i)
                        cv.line(tx + 5, ty + 10 + 16 * i, tx + 235, ty + 14 + 16 * i + 0.35 * i, 1 + (i % 3), blue);
                    break;
                default:  // rotated grid
                {
                    const double a = (5.0 + 10.0 * (tile % 5)) * pi / 180, ca = std::cos(a), sa = std::sin(a);
                    cv.fill(tx, ty, tx + 240, ty + 240, dark, [&](double px, double py) {
                        const double u = (px - cx) * ca + (py - cy) * sa, v = -(px - cx) * sa + (py - cy) * ca;
                        if (std::fabs(u) > 100 || std::fabs(v) > 100) return false;
                        const double fu = u / 10 - std::floor(u / 10), fv = v / 10 - std::floor(v / 10);
                        return fu < 0.15 || fv < 0.15;
                    });
                }
            }
        }
    return img;
}

}  // namespace ssfx::eval
