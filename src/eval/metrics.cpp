// Image quality metrics (see metrics.hpp). Every reduction is deterministic for any
// thread count: MSE and the error statistics sum exact integers; SSIM sums per window row
// into a vector that is then added up in row order.
#include "ssfx/eval/metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <vector>

namespace ssfx::eval {

namespace {

void checkSameSize(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const char* what) {
    if (a.width() != b.width() || a.height() != b.height())
        throw Error(fmt::format("{}: images differ in size ({}x{} vs {}x{})", what, a.width(), a.height(), b.width(),
                                b.height()));
    if (a.empty()) throw Error(fmt::format("{}: empty images", what));
}

}  // namespace

double mse(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec) {
    checkSameSize(a, b, "mse");
    std::atomic<std::uint64_t> total{0};  // exact: at most 2^28 px * 3 * 255^2 < 2^46
    parallelRows(a.height(), exec, [&](int y0, int y1) {
        std::uint64_t s = 0;
        for (int y = y0; y < y1; ++y) {
            const Rgba8* pa = a.row(y);
            const Rgba8* pb = b.row(y);
            for (int x = 0; x < a.width(); ++x) {
                const int dr = pa[x].r - pb[x].r, dg = pa[x].g - pb[x].g, db = pa[x].b - pb[x].b;
                s += std::uint64_t(dr * dr + dg * dg + db * db);
            }
        }
        total += s;
    });
    return double(total.load()) / (255.0 * 255.0) / (double(a.pixelCount()) * 3.0);
}

double mse(ImageView<const float> a, ImageView<const float> b) {
    if (a.width() != b.width() || a.height() != b.height())
        throw Error(fmt::format("mse: sizes {}x{} and {}x{} differ", a.width(), a.height(), b.width(), b.height()));
    double s = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const double d = double(a(x, y)) - double(b(x, y));
            s += d * d;
        }
    return s / double(a.pixelCount());
}

double psnrFromMse(double m) { return m <= 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(1.0 / m); }

double psnr(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec) {
    return psnrFromMse(mse(a, b, exec));
}

namespace {

// Whether mask pixel row/column ranges hold a counted pixel: image pixels [x0, x1) x [y0, y1).
bool anyCounted(const PixelMask& m, int x0, int y0, int x1, int y1) {
    if (m.mask.empty()) return true;
    for (int y = y0 / m.scale; y <= (y1 - 1) / m.scale; ++y)
        for (int x = x0 / m.scale; x <= (x1 - 1) / m.scale; ++x)
            if (m.mask(x, y)) return true;
    return false;
}

void checkMask(ImageView<const Rgba8> a, const PixelMask& m, const char* what) {
    if (m.mask.empty()) return;
    if (m.scale < 1 || std::int64_t{m.mask.width()} * m.scale != a.width() ||
        std::int64_t{m.mask.height()} * m.scale != a.height())
        throw Error(fmt::format("{}: a {}x{} mask at scale {} does not cover {}x{} images", what, m.mask.width(),
                                m.mask.height(), m.scale, a.width(), a.height()));
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double ssimOver(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask, const Exec& exec) {
    checkSameSize(a, b, "ssim");
    checkMask(a, mask, "ssim");
    constexpr int kWin = 8;
    const int wx = a.width() / kWin, wy = a.height() / kWin;
    if (wx == 0 || wy == 0)
        throw Error(fmt::format("ssim: images of {}x{} are smaller than one 8x8 window", a.width(), a.height()));
    constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;  // Wang et al. 2004: K1 = 0.01, K2 = 0.03, L = 1
    std::vector<double> rowSums(std::size_t(wy), 0.0);
    std::vector<std::int64_t> rowWindows(std::size_t(wy), 0);
    // Window rows are independent; run them as "rows" of the parallel loop.
    parallelRows(wy, exec, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            double rowSum = 0;
            std::int64_t windows = 0;
            for (int w = 0; w < wx; ++w) {
                if (!anyCounted(mask, w * kWin, r * kWin, (w + 1) * kWin, (r + 1) * kWin)) continue;
                ++windows;
                // Integer moments per channel: exact, then one conversion.
                std::int64_t sa[3] = {}, sb[3] = {}, saa[3] = {}, sbb[3] = {}, sab[3] = {};
                for (int y = r * kWin; y < (r + 1) * kWin; ++y) {
                    const Rgba8* pa = a.row(y) + w * kWin;
                    const Rgba8* pb = b.row(y) + w * kWin;
                    for (int x = 0; x < kWin; ++x) {
                        const int va[3] = {pa[x].r, pa[x].g, pa[x].b};
                        const int vb[3] = {pb[x].r, pb[x].g, pb[x].b};
                        for (int c = 0; c < 3; ++c) {
                            sa[c] += va[c];
                            sb[c] += vb[c];
                            saa[c] += va[c] * va[c];
                            sbb[c] += vb[c] * vb[c];
                            sab[c] += va[c] * vb[c];
                        }
                    }
                }
                constexpr double n = kWin * kWin, s = 1.0 / 255.0;
                for (int c = 0; c < 3; ++c) {
                    const double ma = sa[c] / n * s, mb = sb[c] / n * s;
                    const double va = saa[c] / n * s * s - ma * ma;
                    const double vb = sbb[c] / n * s * s - mb * mb;
                    const double cov = sab[c] / n * s * s - ma * mb;
                    rowSum += ((2 * ma * mb + kC1) * (2 * cov + kC2)) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
                }
            }
            rowSums[std::size_t(r)] = rowSum;
            rowWindows[std::size_t(r)] = windows;
        }
    });
    double total = 0;
    std::int64_t windows = 0;
    for (std::size_t r = 0; r < rowSums.size(); ++r) total += rowSums[r], windows += rowWindows[r];
    return windows ? total / (double(windows) * 3) : kNaN;
}

}  // namespace

double ssim(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const Exec& exec) { return ssimOver(a, b, {}, exec); }

double ssim(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask, const Exec& exec) {
    return ssimOver(a, b, mask, exec);
}

ErrorStats errorStats(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask, const Exec& exec) {
    checkSameSize(a, b, "errorStats");
    checkMask(a, mask, "errorStats");
    // Integer sums and a histogram of e: exact and the same for any thread count.
    std::mutex lock;
    std::array<std::int64_t, 256> histogram{};
    std::uint64_t squares = 0;
    parallelRows(a.height(), exec, [&](int y0, int y1) {
        std::array<std::int64_t, 256> h{};
        std::uint64_t s = 0;
        for (int y = y0; y < y1; ++y) {
            const Rgba8* pa = a.row(y);
            const Rgba8* pb = b.row(y);
            const std::uint8_t* m = mask.mask.empty() ? nullptr : mask.mask.row(y / mask.scale);
            for (int x = 0; x < a.width(); ++x) {
                if (m && !m[x / mask.scale]) continue;
                const int dr = std::abs(pa[x].r - pb[x].r), dg = std::abs(pa[x].g - pb[x].g),
                          db = std::abs(pa[x].b - pb[x].b);
                s += std::uint64_t(dr * dr + dg * dg + db * db);
                ++h[std::size_t(std::max({dr, dg, db}))];
            }
        }
        const std::lock_guard<std::mutex> g(lock);
        squares += s;
        for (std::size_t e = 0; e < h.size(); ++e) histogram[e] += h[e];
    });
    ErrorStats r;
    for (const std::int64_t n : histogram) r.pixels += n;
    if (r.pixels == 0) return {0, kNaN, kNaN, kNaN};
    r.psnr = psnrFromMse(double(squares) / (255.0 * 255.0) / (double(r.pixels) * 3.0));
    // Nearest rank: the smallest e with at least ceil(0.99 n) pixels at or below it.
    const std::int64_t rank = (r.pixels * 99 + 99) / 100;
    std::int64_t below = 0;
    bool found = false;
    for (std::size_t e = 0; e < histogram.size(); ++e) {
        below += histogram[e];
        if (!found && below >= rank) r.p99Error = double(e), found = true;
        if (histogram[e]) r.maxError = double(e);
    }
    return r;
}

Image<std::uint8_t> differenceMask(ImageView<const Rgba8> a, ImageView<const Rgba8> b) {
    checkSameSize(a, b, "differenceMask");
    Image<std::uint8_t> m(a.width(), a.height());
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const Rgba8 p = a(x, y), q = b(x, y);
            m(x, y) = p.r != q.r || p.g != q.g || p.b != q.b;
        }
    return m;
}

}  // namespace ssfx::eval
