// The kernel experiment (see kernels.hpp).
#include "ssfx/eval/kernels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "ssfx/core/error.hpp"

namespace ssfx::eval {

namespace {

constexpr double kPi = std::numbers::pi;

struct Kernel {
    std::string name;
    int radius;
    std::vector<double> dx;  // (2r+1)^2, row-major, d/dx
};

// Separable kernel: derivative taps along x times smoothing taps along y.
Kernel separable(std::string name, std::vector<double> deriv, std::vector<double> smooth) {
    const int n = int(deriv.size()), r = n / 2;
    Kernel k{std::move(name), r, std::vector<double>(std::size_t(n * n))};
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) k.dx[std::size_t(y * n + x)] = deriv[std::size_t(x)] * smooth[std::size_t(y)];
    return k;
}

std::vector<Kernel> kernels() {
    std::vector<Kernel> ks;
    ks.push_back(separable("central", {-0.5, 0, 0.5}, {0, 1, 0}));
    ks.push_back(separable("sobel", {-0.5, 0, 0.5}, {0.25, 0.5, 0.25}));
    ks.push_back(separable("scharr", {-0.5, 0, 0.5}, {47 / 256.0, 162 / 256.0, 47 / 256.0}));
    // Gaussian derivative, sigma 1, radius 3: g'(x) g(y), normalised so that a unit ramp
    // (f = x) gives 1: sum_x x g'(x) = -1 after scaling, and sum_y g(y) = 1.
    std::vector<double> g(7), dg(7);
    double gs = 0, ramp = 0;
    for (int i = -3; i <= 3; ++i) {
        g[std::size_t(i + 3)] = std::exp(-0.5 * i * i);
        gs += g[std::size_t(i + 3)];
    }
    for (int i = -3; i <= 3; ++i) {
        g[std::size_t(i + 3)] /= gs;
        dg[std::size_t(i + 3)] = i * g[std::size_t(i + 3)];  // -g'(x) up to a constant; sign set below
        ramp += i * dg[std::size_t(i + 3)];
    }
    for (auto& v : dg) v /= ramp;  // correlation with f = x now gives exactly 1
    ks.push_back(separable("gaussian", dg, g));
    return ks;
}

}  // namespace

KernelExperiment runKernelExperiment(const KernelExperimentOptions& o) {
    if (!(o.stepDegrees > 0 && o.stepDegrees <= 45)) throw Error("kernels: the angle step must be in (0, 45] degrees");
    if (o.widths.empty()) throw Error("kernels: no line widths");
    for (double w : o.widths)
        if (!(w > 0 && w <= 16)) throw Error(fmt::format("kernels: line width {} is not in (0, 16]", w));
    if (o.supersample < 1 || o.supersample > 16) throw Error("kernels: supersample must be in [1, 16]");
    if (o.size < 32 || o.size > 1024) throw Error(fmt::format("kernels: size {} is not in [32, 1024]", o.size));
    const std::vector<Kernel> ks = kernels();
    KernelExperiment e;
    for (const auto& k : ks) e.kernels.push_back(k.name);
    const int steps = int(std::floor(90.0 / o.stepDegrees + 1e-9));
    for (int i = 0; i <= steps; ++i) e.angles.push_back(i * o.stepDegrees);
    e.errorAt.assign(ks.size(), std::vector<double>(e.angles.size(), 0.0));
    std::vector<double> sum(ks.size(), 0.0);
    std::vector<long> count(ks.size(), 0);
    const int n = o.size, ss = o.supersample;
    const bool edge = o.shape == KernelExperimentOptions::Shape::Edge;
    const double c = n / 2.0, reach = n / 2.0 - 8;
    // Sub-pixel placements of the line; none dyadic, so that no pixel centre lies exactly on
    // the line's border (where the rounding of sin/cos would decide, e.g. at 90 degrees).
    const double offsets[][2] = {{0.0137, 0.0291}, {0.2637, 0.1291}, {0.5137, 0.3791}, {0.1437, 0.7091}};
    std::vector<double> img(std::size_t(n * n));
    for (std::size_t a = 0; a < e.angles.size(); ++a) {
        const double th = e.angles[a] * kPi / 180;
        // Unit normal of the line in image coordinates (y down): direction (cos, -sin).
        const double nx = std::sin(th), ny = std::cos(th);
        std::vector<double> angleSum(ks.size(), 0.0);
        std::vector<long> angleCount(ks.size(), 0);
        for (double w : o.widths)
            for (const auto& off : offsets) {
                for (int y = 0; y < n; ++y)
                    for (int x = 0; x < n; ++x) {
                        // Coverage by ss x ss point samples (ss = 1: aliased, the pixel centre).
                        double v = 0;
                        for (int sy = 0; sy < ss; ++sy)
                            for (int sx = 0; sx < ss; ++sx) {
                                const double d =
                                    (x + (sx + 0.5) / ss - c - off[0]) * nx + (y + (sy + 0.5) / ss - c - off[1]) * ny;
                                v += (edge ? d < 0 : std::abs(d) < w / 2) ? 0.0 : 1.0;
                            }
                        img[std::size_t(y * n + x)] = v / (ss * ss);
                    }
                for (std::size_t k = 0; k < ks.size(); ++k) {
                    const int r = ks[k].radius, m = 2 * r + 1;
                    for (int y = 0; y < n; ++y)
                        for (int x = 0; x < n; ++x) {
                            if (std::hypot(x + 0.5 - c, y + 0.5 - c) > reach) continue;
                            double gx = 0, gy = 0;
                            for (int j = -r; j <= r; ++j)
                                for (int i = -r; i <= r; ++i) {
                                    const double v = img[std::size_t((y + j) * n + (x + i))];
                                    gx += ks[k].dx[std::size_t((j + r) * m + (i + r))] * v;
                                    gy += ks[k].dx[std::size_t((i + r) * m + (j + r))] * v;  // transpose
                                }
                            if (std::hypot(gx, gy) < 0.1) continue;
                            // Only pixels a PPAA method would process: contrast across
                            // the centre and its 4 neighbours (the early exit's set).
                            auto at = [&](int i, int j) { return img[std::size_t((y + j) * n + (x + i))]; };
                            const double hi = std::max({at(0, 0), at(1, 0), at(-1, 0), at(0, 1), at(0, -1)});
                            const double lo = std::min({at(0, 0), at(1, 0), at(-1, 0), at(0, 1), at(0, -1)});
                            if (hi - lo < 0.25) continue;
                            // Edge direction in degrees, y up; fold the difference into [0, 90].
                            const double dir = std::atan2(-gy, gx) * 180 / kPi + 90;
                            double err = std::fmod(std::abs(dir - e.angles[a]), 180.0);
                            err = std::min(err, 180 - err);
                            angleSum[k] += err, ++angleCount[k];
                        }
                }
            }
        for (std::size_t k = 0; k < ks.size(); ++k) {
            e.errorAt[k][a] = angleCount[k] ? angleSum[k] / double(angleCount[k]) : 0.0;
            sum[k] += angleSum[k], count[k] += angleCount[k];
        }
    }
    for (std::size_t k = 0; k < ks.size(); ++k) {
        e.meanError.push_back(count[k] ? sum[k] / double(count[k]) : 0.0);
        e.maxError.push_back(*std::max_element(e.errorAt[k].begin(), e.errorAt[k].end()));
    }
    return e;
}

std::string kernelMarkdown(const KernelExperiment& e) {
    std::string s = "| kernel | mean error (deg) | max of per-angle mean (deg) |\n|---|---:|---:|\n";
    for (std::size_t k = 0; k < e.kernels.size(); ++k)
        s += fmt::format("| {} | {:.3f} | {:.3f} |\n", e.kernels[k], e.meanError[k], e.maxError[k]);
    return s;
}

std::string kernelJson(const KernelExperiment& e) {
    nlohmann::ordered_json j;
    j["angles"] = e.angles;
    for (std::size_t k = 0; k < e.kernels.size(); ++k)
        j["kernels"][e.kernels[k]] = {
            {"mean_error", e.meanError[k]}, {"max_error", e.maxError[k]}, {"error_at", e.errorAt[k]}};
    return j.dump(1) + "\n";
}

}  // namespace ssfx::eval
