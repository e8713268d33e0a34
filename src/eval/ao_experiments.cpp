// The SAO paper's experiments on analytic scenes (see ao_experiments.hpp).
#include "ssfx/eval/ao_experiments.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/ao/registry.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/timing.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/analytic.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/gpu/ao.hpp"
#endif

namespace ssfx::eval {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

const char* formatName(DepthFormat f) { return f == DepthFormat::D16 ? "D16" : f == DepthFormat::D24 ? "D24" : "D32F"; }
constexpr DepthFormat kFormats[] = {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F};

ImageRgba8 grey(const ImageF& a, float offset = 0.0f, float gain = 1.0f) {
    ImageRgba8 out(a.width(), a.height());
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const float v = std::clamp(offset + gain * a(x, y), 0.0f, 1.0f);
            const auto g = std::uint8_t(std::lround(v * 255.0f));
            out(x, y) = {g, g, g, 255};
        }
    return out;
}

ImageF difference(const ImageF& a, const ImageF& b) {
    ImageF d(a.width(), a.height());
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) d(x, y) = a(x, y) - b(x, y);
    return d;
}

// Hardware depth of `g` stored in `format` (from the exact z, not from the float depth).
ImageF depthIn(const scene::GeometryBuffer& g, const Camera& cam, DepthFormat format) {
    ImageF d(g.z.width(), g.z.height());
    for (int y = 0; y < d.height(); ++y)
        for (int x = 0; x < d.width(); ++x)
            d(x, y) = std::isinf(g.z(x, y)) ? 1.0f : float(ssfx::quantizeDepth(ao::zToDepth(g.z(x, y), cam), format));
    return d;
}

template <class Fn>
double medianMs(int reps, const Fn& fn) {
    std::vector<double> t;
    for (int i = 0; i < reps; ++i) {
        const auto a = Clock::now();
        fn();
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - a).count());
    }
    return median(t);
}

// What every experiment below shares.
struct Context {
    const AoExperimentOptions& o;
    fs::path out;
    nlohmann::ordered_json& j;
#ifdef SSFX_HAVE_GPU
    std::shared_ptr<vkx::Context> gpu;  //!< --backend vulkan
#endif
    void say(const std::string& s) const {
        if (o.progress) o.progress({s});
    }
    std::string image(const std::string& file) const { return (out / "images" / file).string(); }
};

Figure aoFigure(const std::string& file, const std::string& caption) {
    return Figure{"images/" + file, caption, Figure::Kind::Image, 0, 0};
}

// Pixels of the inner region whose 3x3 neighbourhood lies on one plane of the geometry (all
// hit, the same true normal, the same plane offset n.p within 1 mm per metre of distance),
// and the root mean square of A's 4-neighbour Laplacian over them: how much structure a
// configuration leaves on surfaces that are flat (the truth's own is their AO gradient).
struct FlatMask {
    std::vector<char> flat;  //!< inner region, row-major
    int w = 0, h = 0, count = 0;
};
FlatMask flatPixels(const scene::GeometryBuffer& g, const Camera& cam, int guard) {
    const int W = g.z.width(), H = g.z.height();
    const Projection proj = ssfx::projection(cam, W, H);
    FlatMask m;
    m.w = W - 2 * guard, m.h = H - 2 * guard;
    m.flat.assign(std::size_t(m.w) * std::size_t(m.h), 0);
    auto offset = [&](int x, int y, const ao::Vec3d& n) {
        const ao::Vec3 p = ao::reconstructPosition(proj, float(x) + 0.5f, float(y) + 0.5f, g.z(x, y));
        return n.x * p.x + n.y * p.y + n.z * p.z;
    };
    for (int j = 1; j + 1 < m.h; ++j)
        for (int i = 1; i + 1 < m.w; ++i) {
            const int x = i + guard, y = j + guard;
            if (std::isinf(g.z(x, y))) continue;
            const ao::Vec3d n = g.normals[std::size_t(y) * std::size_t(W) + std::size_t(x)];
            const double d0 = offset(x, y, n), tol = 1e-3 * std::abs(double(g.z(x, y)));
            bool same = true;
            for (int dy = -1; dy <= 1 && same; ++dy)
                for (int dx = -1; dx <= 1 && same; ++dx) {
                    const ao::Vec3d q = g.normals[std::size_t(y + dy) * std::size_t(W) + std::size_t(x + dx)];
                    same = !std::isinf(g.z(x + dx, y + dy)) && q.x * n.x + q.y * n.y + q.z * n.z > 0.99999 &&
                           std::abs(offset(x + dx, y + dy, n) - d0) < tol;
                }
            if (same) m.flat[std::size_t(j) * std::size_t(m.w) + std::size_t(i)] = 1, ++m.count;
        }
    return m;
}
double rmsLaplacian(const ImageF& a, const FlatMask& m) {
    double s = 0;
    for (int j = 1; j + 1 < m.h; ++j)
        for (int i = 1; i + 1 < m.w; ++i) {
            if (!m.flat[std::size_t(j) * std::size_t(m.w) + std::size_t(i)]) continue;
            const double l = double(a(i - 1, j)) + a(i + 1, j) + a(i, j - 1) + a(i, j + 1) - 4.0 * a(i, j);
            s += l * l;
        }
    return m.count ? std::sqrt(s / m.count) : 0.0;
}

// SAO as the paper's text describes it (the defaults), as the authors' released shaders run
// it (the "released" preset, at its own radius of 0.7 m), the released preset at the paper's
// r = 1 m, and the paper's configuration with the released blur alone (9 taps at stride 2,
// the released weights; the edge weight 2000 per key unit of z / -300 m is 6.67 per metre).
// Accuracy against the truth at each one's radius, and the flat-surface smoothness.
Block releasedComparison(const Context& c, const std::vector<AoRenderedScene>& entries, int aw, int ah, int guard,
                         int rays) {
    const AoExperimentOptions& o = c.o;
    struct Config {
        std::string name, file;
        ao::SaoParams p;
    };
    std::vector<Config> configs{{"paper (defaults)", "paper", ao::saoPreset("paper")},
                                {"released preset", "released", ao::saoPreset("released")},
                                {"released preset, r = 1 m", "released_r1", ao::saoPreset("released")},
                                {"paper + released blur", "released_blur", ao::saoPreset("paper")}};
    configs[2].p.radius = 1.0f;
    {
        const ao::SaoParams r = ao::saoPreset("released");
        ao::BilateralParams& b = configs[3].p.blur;
        b = r.blur;
        b.edgeSharpness = r.blur.edgeSharpness / -r.packZMin;  // per key unit -> per metre
    }
    Block b;
    b.heading = "The paper's configuration and the released shaders' (sao.md, \"released\")";
    b.text = fmt::format(
        "SAO as the paper's "
        "text describes it (our defaults), as the authors' released shaders run it (`--preset released`, at its "
        "radius of 0.7 m), that preset at r = 1 m, and the paper's configuration with the released blur alone. "
        "PSNR (dB) against the ray-traced truth at each one's radius ({} rays per pixel), and the rms of A's "
        "4-neighbour Laplacian over pixels whose 3x3 neighbourhood lies on one plane (flat surfaces: lower is "
        "smoother; the truth's own value is its real shading gradient), at {}x{} with a {} px guard band. "
        "Images: images/ao_SCENE_paper.png, images/ao_SCENE_released.png, images/ao_SCENE_released_blur.png.",
        rays, aw, ah, guard);
    b.table.header = {"scene",   "configuration", "radius (m)", "PSNR vs truth (dB)", "rms Laplacian, flat",
                      "truth's", "flat pixels"};
    for (const AoRenderedScene& e : entries) {
        const scene::GeometryBuffer g =
            scene::castGeometry(*e.geometry, e.camera, aw + 2 * guard, ah + 2 * guard, o.exec);
        const FlatMask flat = flatPixels(g, e.camera, guard);
        std::vector<std::pair<float, ImageF>> truths;  // by radius
        for (const Config& cfg : configs) {
            const float r = cfg.p.radius;
            auto it = std::find_if(truths.begin(), truths.end(), [&](const auto& t) { return t.first == r; });
            if (it == truths.end()) {
                c.say(fmt::format("ao: {} ray-traced truth at r = {} m ({} rays per pixel)", e.name, r, rays));
                ao::RaytracedParams rp;
                rp.raysPerPixel = rays, rp.guardBand = guard, rp.radius = r;
                truths.emplace_back(r,
                                    ao::raytraced(*e.geometry, e.camera, aw + 2 * guard, ah + 2 * guard, rp, o.exec));
                it = truths.end() - 1;
            }
            ao::SaoParams p = cfg.p;
            p.guardBand = guard;
            const ImageF a = ao::sao(e.depth.view(), e.camera, p, o.exec);
            const double psnr = psnrFromMse(mse(a.view(), it->second.view())), lap = rmsLaplacian(a, flat),
                         truthLap = rmsLaplacian(it->second, flat);
            if (cfg.file != "released_r1") {
                const std::string file = fmt::format("ao_{}_{}.png", e.name, cfg.file);
                io::writePng(c.image(file), grey(a).view());
                // Shown: the room and the first rendered scene.
                if (e.name == "room" || &e == entries.data() + 2)
                    b.figures.push_back(aoFigure(file, fmt::format("{}: {}", e.name, cfg.file)));
            }
            b.table.addRow({e.name, cfg.name, fmt::format("{:g}", r), fmt::format("{:.2f}", psnr),
                            fmt::format("{:.4f}", lap), fmt::format("{:.4f}", truthLap), std::to_string(flat.count)});
            c.j["released_comparison"][e.name][cfg.name] = {{"radius_m", r},
                                                            {"psnr_vs_raytraced", psnr},
                                                            {"rms_laplacian_flat", lap},
                                                            {"truth_rms_laplacian_flat", truthLap},
                                                            {"flat_pixels", flat.count}};
        }
    }
    return b;
}

}  // namespace

ZPrecision zPrecisionExperiment() {
    ZPrecision r;
    for (int i = 0; i < 24; ++i) r.distances.push_back(0.2 * std::pow(2500.0, i / 23.0));  // 0.2 .. 500 m
    for (DepthFormat f : kFormats)
        for (bool infinite : {false, true}) {
            Camera cam;
            cam.zNear = -0.1;
            cam.zFar = infinite ? -INFINITY : -1000.0;
            const Projection p = ssfx::projection(cam, 1, 1);
            r.series.push_back(fmt::format("{} {}", formatName(f), infinite ? "infinite" : "finite"));
            std::vector<double> errs;
            for (double d : r.distances) {
                double worst = 0;
                for (int k = 0; k < 256; ++k) {
                    const double z = -d * (1.0 + 0.1 * k / 255.0);
                    const double dq = ssfx::quantizeDepth(ao::zToDepth(z, cam), f);
                    const double zr = p.c0 / (dq * p.c1 + p.c2);
                    worst = std::max(worst, std::abs(zr - z) * 1000.0);
                }
                errs.push_back(worst);
            }
            r.errorMm.push_back(errs);
        }
    return r;
}

namespace {

const Camera kCamera;  // 60 degree vertical field of view, near 0.1 m, infinite far plane

// ---- Figure 3: z precision ----------------------------------------------------------
Block zPrecisionBlock(const Context& c) {
    c.say("ao: z precision (Figure 3)");
    const ZPrecision zp = zPrecisionExperiment();
    std::vector<Series> series;
    for (std::size_t s = 0; s < zp.series.size(); ++s) {
        std::vector<double> logErr;
        for (double e : zp.errorMm[s]) logErr.push_back(std::max(e, 1e-6));
        series.push_back({zp.series[s], logErr});
    }
    std::vector<double> logDist;
    for (double d : zp.distances) logDist.push_back(std::log10(d));
    io::writePng((c.out / "plots" / "ao_z_precision.png").string(),
                 lineChart(logDist, series,
                           {880, 420, "Largest camera-space z error vs distance (near plane 0.1 m)",
                            "log10 distance (m)", "error (mm), log scale", true, true})
                     .view());
    Block b;
    b.heading = "z precision (paper Figure 3)";
    b.text =
        "Largest |z error| in mm over 256 points within 10 % beyond each distance; near plane 0.1 m, finite far "
        "plane 1000 m.";
    b.table.header = {"series"};
    const std::size_t picks[] = {0, 5, 9, 13, 17, 21, 23};
    for (std::size_t i : picks) b.table.header.push_back(fmt::format("{:.3g} m", zp.distances[i]));
    for (std::size_t s = 0; s < zp.series.size(); ++s) {
        std::vector<std::string> row{zp.series[s]};
        for (std::size_t i : picks) row.push_back(fmt::format("{:.3g}", zp.errorMm[s][i]));
        b.table.addRow(row);
    }
    b.figures.push_back({"plots/ao_z_precision.png", "z precision", Figure::Kind::Plot, 880, 420});
    c.j["z_precision"] = {{"distances_m", zp.distances}, {"series", zp.series}, {"error_mm", zp.errorMm}};
    return b;
}

// Reconstructed-normal error (degrees) at each pixel whose 2x2 quad lies within one face of
// the analytic geometry `g` (all hit, the same true normal, on the same plane), from `z`.
std::vector<double> normalErrors(const scene::GeometryBuffer& g, const ImageF& z, const Projection& proj,
                                 const Exec& exec) {
    const int nw = z.width(), nh = z.height();
    const std::vector<ao::Vec3> n = ao::faceNormals(z.view(), proj, exec);
    std::vector<double> errs;
    for (int y = 0; y < nh; ++y)
        for (int x = 0; x < nw; ++x) {
            const int xa = x & ~1, ya = y & ~1;
            if (xa + 1 >= nw || ya + 1 >= nh) continue;
            const ao::Vec3d tn = g.normals[std::size_t(y) * std::size_t(nw) + std::size_t(x)];
            bool same = !std::isinf(g.z(x, y));
            double plane = 0;
            for (int k = 0; k < 4 && same; ++k) {
                const int qx = xa + (k & 1), qy = ya + (k >> 1);
                const ao::Vec3d qn = g.normals[std::size_t(qy) * std::size_t(nw) + std::size_t(qx)];
                const ao::Vec3d dir = ao::primaryRay(proj, float(qx) + 0.5f, float(qy) + 0.5f);
                const double t = double(g.z(qx, qy)) / dir.z;
                const double dist = tn.x * dir.x * t + tn.y * dir.y * t + tn.z * dir.z * t;
                same = !std::isinf(g.z(qx, qy)) && qn.x == tn.x && qn.y == tn.y && qn.z == tn.z &&
                       (k == 0 || std::abs(dist - plane) < 1e-3 * std::abs(g.z(x, y)));
                if (k == 0) plane = dist;
            }
            const ao::Vec3 rn = n[std::size_t(y) * std::size_t(nw) + std::size_t(x)];
            if (!same || (rn.x == 0 && rn.y == 0 && rn.z == 0)) continue;
            const double cosine =
                std::clamp(double(rn.x) * tn.x + double(rn.y) * tn.y + double(rn.z) * tn.z, -1.0, 1.0);
            errs.push_back(std::acos(cosine) * 180 / M_PI);
        }
    return errs;
}

// ---- Figure 4: normal precision ------------------------------------------------------
Block normalPrecisionBlock(const Context& c, const scene::AnalyticScene& room) {
    c.say("ao: normal precision (Figure 4)");
    const int nw = c.o.quick ? 320 : 1280, nh = c.o.quick ? 180 : 720;
    const scene::GeometryBuffer g = scene::castGeometry(room, kCamera, nw, nh, c.o.exec);
    const Projection proj = ssfx::projection(kCamera, nw, nh);
    Block b;
    b.heading = "Normal precision (paper Figure 4)";
    b.text = fmt::format(
        "Angle (degrees) between the face normal reconstructed from z by quad-pair differences and the "
        "true normal, at {}x{} on the analytic room, over pixels whose 2x2 quad lies within one face.",
        nw, nh);
    b.table.header = {"depth format", "pixels", "mean", "99th percentile", "max"};
    for (DepthFormat f : kFormats) {
        const ImageF z = ao::depthToZ(depthIn(g, kCamera, f).view(), kCamera, c.o.exec);
        std::vector<double> errs = normalErrors(g, z, proj, c.o.exec);
        std::sort(errs.begin(), errs.end());
        double mean = 0;
        for (double e : errs) mean += e / double(errs.size());
        const double p99 = errs.empty() ? 0 : errs[std::size_t(double(errs.size() - 1) * 0.99)];
        const double mx = errs.empty() ? 0 : errs.back();
        b.table.addRow({formatName(f), std::to_string(errs.size()), fmt::format("{:.4f}", mean),
                        fmt::format("{:.4f}", p99), fmt::format("{:.4f}", mx)});
        c.j["normal_precision"][formatName(f)] = {
            {"pixels", errs.size()}, {"mean_deg", mean}, {"p99_deg", p99}, {"max_deg", mx}};
    }
    return b;
}

// The accuracy experiment's scenes: the analytic ones (exact ray casting) and, when the
// caller supplies them, rendered ones; depth at aw x ah plus the guard band.
std::vector<AoRenderedScene> accuracyScenes(const Context& c, int aw, int ah, int guard) {
    std::vector<AoRenderedScene> entries;
    for (const char* name : {"corner", "room"}) {
        auto geometry = std::make_shared<scene::AnalyticScene>(scene::analyticSceneByName(name));
        scene::GeometryBuffer g = scene::castGeometry(*geometry, kCamera, aw + 2 * guard, ah + 2 * guard, c.o.exec);
        entries.push_back({name, std::move(g.depth), kCamera, geometry});
    }
    if (c.o.renderedScenes)
        for (auto& r : c.o.renderedScenes(aw, ah, guard)) entries.push_back(std::move(r));
    for (const AoRenderedScene& e : entries)
        if (e.depth.width() != aw + 2 * guard || e.depth.height() != ah + 2 * guard)
            throw Error(fmt::format("ao: scene '{}' depth is {}x{}, not {}x{}", e.name, e.depth.width(),
                                    e.depth.height(), aw + 2 * guard, ah + 2 * guard));
    return entries;
}

// ---- Table 1 and accuracy: pyramid filters and baselines against the ray-traced truth --
Block accuracyBlock(const Context& c, const std::vector<AoRenderedScene>& entries, int aw, int ah, int guard,
                    int rays) {
    struct Variant {
        std::string name;
        bool sao, pyramid;
        ao::PyramidFilter filter;
        bool packed = false;
    };
    const std::vector<Variant> variants{{"alchemy", false, false, ao::PyramidFilter::RotatedGrid},
                                        {"sao, no pyramid", true, false, ao::PyramidFilter::RotatedGrid},
                                        {"sao, rotated grid", true, true, ao::PyramidFilter::RotatedGrid},
                                        {"sao, mean", true, true, ao::PyramidFilter::Mean},
                                        {"sao, harmonic mean", true, true, ao::PyramidFilter::HarmonicMean},
                                        {"sao, min", true, true, ao::PyramidFilter::Min},
                                        {"sao, max", true, true, ao::PyramidFilter::Max},
                                        {"sao, packed A and z", true, true, ao::PyramidFilter::RotatedGrid, true}};
    Block b;
    b.heading = "Accuracy against the ray-traced truth; z pyramid filters (paper Table 1)";
    b.text = fmt::format(
        "PSNR (dB) of A against the ray-traced obscurance ({} cosine-weighted rays per pixel, same radius "
        "r = 1 m and falloff) at {}x{} with a {} px guard band. Images: images/ao_SCENE_METHOD.png, "
        "differences from SAO without a pyramid x4 around grey: images/ao_SCENE_METHOD_diff.png.",
        rays, aw, ah, guard);
    std::vector<std::vector<double>> psnrTable(variants.size(), std::vector<double>(entries.size()));
    std::vector<std::vector<double>> gpuRows(2);  // --backend vulkan: sao (rotated grid), alchemy
    double gpuGap = 0;                            // the largest |GPU - CPU| PSNR difference (dB)
    for (std::size_t si = 0; si < entries.size(); ++si) {
        const AoRenderedScene& e = entries[si];
        c.say(fmt::format("ao: {} ray-traced truth ({} rays per pixel)", e.name, rays));
        ao::RaytracedParams rp;
        rp.raysPerPixel = rays;
        rp.guardBand = guard;
        const ImageF truth = ao::raytraced(*e.geometry, e.camera, aw + 2 * guard, ah + 2 * guard, rp, c.o.exec);
        io::writePng(c.image(fmt::format("ao_{}_raytraced.png", e.name)), grey(truth).view());
        ImageF noPyramid;
        for (std::size_t v = 0; v < variants.size(); ++v) {
            ImageF a;
            if (variants[v].sao) {
                ao::SaoParams p;
                p.guardBand = guard;
                p.usePyramid = variants[v].pyramid;
                p.pyramidFilter = variants[v].filter;
                p.packBlurInput = variants[v].packed;
                a = ao::sao(e.depth.view(), e.camera, p, c.o.exec);
            } else {
                ao::AlchemyParams p;
                p.guardBand = guard;
                a = ao::alchemy(e.depth.view(), e.camera, p, c.o.exec);
            }
            if (v == 1) noPyramid = ImageF::copyOf(a.view());
            psnrTable[v][si] = psnrFromMse(mse(a.view(), truth.view()));
            std::string file = variants[v].name;
            std::replace(file.begin(), file.end(), ' ', '_');
            file.erase(std::remove(file.begin(), file.end(), ','), file.end());
            io::writePng(c.image(fmt::format("ao_{}_{}.png", e.name, file)), grey(a).view());
            if (v >= 2)
                io::writePng(c.image(fmt::format("ao_{}_{}_diff.png", e.name, file)),
                             grey(difference(a, noPyramid), 0.5f, 4.0f).view());
            c.j["accuracy"][e.name][variants[v].name] = {{"psnr_vs_raytraced", psnrTable[v][si]}};
        }
#ifdef SSFX_HAVE_GPU
        if (c.gpu) {  // the GPU passes on the same depth, against the same truth
            ao::SaoParams sp;
            sp.guardBand = guard;
            ao::AlchemyParams ap;
            ap.guardBand = guard;
            const double gs = psnrFromMse(mse(gpu::Sao(c.gpu, sp).run(e.depth.view(), e.camera).view(), truth.view()));
            const double ga =
                psnrFromMse(mse(gpu::Alchemy(c.gpu, ap).run(e.depth.view(), e.camera).view(), truth.view()));
            gpuRows[0].push_back(gs), gpuRows[1].push_back(ga);
            c.j["accuracy"][e.name]["sao, rotated grid (vulkan)"] = {{"psnr_vs_raytraced", gs}};
            c.j["accuracy"][e.name]["alchemy (vulkan)"] = {{"psnr_vs_raytraced", ga}};
            gpuGap = std::max({gpuGap, std::abs(gs - psnrTable[2][si]), std::abs(ga - psnrTable[0][si])});
        }
#endif
    }
    b.table.header = {"method"};
    for (const auto& e : entries) b.table.header.push_back(e.name);
    for (std::size_t v = 0; v < variants.size(); ++v) {
        std::vector<std::string> row{variants[v].name};
        for (std::size_t si = 0; si < entries.size(); ++si) row.push_back(fmt::format("{:.2f}", psnrTable[v][si]));
        b.table.addRow(row);
    }
    if (!gpuRows[0].empty()) {
        for (std::size_t k = 0; k < 2; ++k) {
            std::vector<std::string> row{k == 0 ? "sao, rotated grid (vulkan)" : "alchemy (vulkan)"};
            for (double v : gpuRows[k]) row.push_back(fmt::format("{:.2f}", v));
            b.table.addRow(row);
        }
        b.after = fmt::format(
            "The GPU passes (--backend vulkan) against the same truth: at most {:.4f} dB from the CPU's rows.", gpuGap);
        c.j["accuracy"]["gpu_max_abs_db_difference"] = gpuGap;
    }
    // The pictures: the room with every filter, the first rendered scene with the main three.
    for (const char* name :
         {"raytraced", "sao_rotated_grid", "sao_no_pyramid", "alchemy", "sao_min_diff", "sao_max_diff"})
        b.figures.push_back(aoFigure(fmt::format("ao_room_{}.png", name), fmt::format("room: {}", name)));
    if (entries.size() > 2)
        for (const char* name : {"raytraced", "sao_rotated_grid", "alchemy"})
            b.figures.push_back(aoFigure(fmt::format("ao_{}_{}.png", entries[2].name, name),
                                         fmt::format("{} (Vulkan): {}", entries[2].name, name)));
    return b;
}

// ---- Figure 5: AO pass time vs radius -----------------------------------------------
const std::vector<double> kFigure5Radii{0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0};  // m

// The sweep's table (`digits` decimals), its ratios in `j` and in the returned sentence:
// r = 4 m over r = 0.25 m for sao and alchemy, alchemy over sao at 1.5 m. `timing` is
// {alchemy, sao without the pyramid, sao}, each at kFigure5Radii.
std::string radiusTable(Block& b, const std::vector<Series>& timing, int digits, nlohmann::ordered_json& j) {
    b.table.header = {"method"};
    for (double r : kFigure5Radii) b.table.header.push_back(fmt::format("{} m", r));
    for (const auto& s : timing) {
        std::vector<std::string> row{s.name};
        for (double v : s.values) row.push_back(fmt::format("{:.{}f}", v, digits));
        b.table.addRow(row);
        j[s.name] = s.values;
    }
    const double saoFlat = timing[2].values[7] / timing[2].values[1];
    const double alchemyGrowth = timing[0].values[7] / timing[0].values[1];
    const double speedup = timing[0].values[4] / timing[2].values[4];
    j["radii_m"] = kFigure5Radii;
    j["sao_r4_over_r025"] = saoFlat;
    j["alchemy_r4_over_r025"] = alchemyGrowth;
    j["alchemy_over_sao_r15"] = speedup;
    return fmt::format(
        "Time at r = 4 m over r = 0.25 m: sao {:.2f}x, alchemy {:.2f}x. alchemy / sao at r = 1.5 m: {:.2f}x.", saoFlat,
        alchemyGrowth, speedup);
}

// The three methods of the sweep at radius r: AlchemyAO, SAO without and with the pyramid.
struct Figure5Params {
    ao::AlchemyParams alchemy;
    ao::SaoParams flat, sao;
};
Figure5Params figure5Params(double r) {
    Figure5Params p;
    p.alchemy.radius = p.flat.radius = p.sao.radius = float(r);
    p.flat.usePyramid = false;
    return p;
}

// Table 3's resolutions with the paper's guard bands (one small size with --quick).
struct Table3Size {
    int w, h, g;
};
std::vector<Table3Size> table3Sizes(bool quick) {
    if (quick) return {{320, 180, 32}};
    return {{1280, 720, 128}, {1920, 1080, 192}, {1920, 1200, 192}, {2560, 1600, 256}};
}

Block radiusScalingBlock(const Context& c, const scene::AnalyticScene& room, int reps) {
    const int fw = c.o.quick ? 320 : 2560, fh = c.o.quick ? 200 : 1600;
    c.say(fmt::format("ao: sample-pass time vs radius at {}x{} (Figure 5)", fw, fh));
    const std::vector<double>& radii = kFigure5Radii;
    std::vector<Series> timing{{"alchemy", {}}, {"sao, no pyramid", {}}, {"sao", {}}};
    const scene::GeometryBuffer g = scene::castGeometry(room, kCamera, fw, fh, c.o.exec);
    const Projection proj = ssfx::projection(kCamera, fw, fh);
    const ImageF z = ao::depthToZ(g.depth.view(), kCamera, c.o.exec);
    // The pyramid in one buffer, built once: each timing is the sample pass alone (every
    // method reads level 0 of the same buffer; "no pyramid" only ever reads level 0).
    ao::ZPyramid pyr;
    ao::zPyramid(z.view(), 5, ao::PyramidFilter::RotatedGrid, pyr, c.o.exec);
    const ao::Region all{0, 0, fw, fh};
    for (double r : radii) {
        const Figure5Params fp = figure5Params(r);
        const ao::AlchemyParams& ap = fp.alchemy;
        const ao::SaoParams &flat = fp.flat, &sp = fp.sao;
        timing[0].values.push_back(medianMs(reps, [&] { ao::alchemySamplePass(pyr, proj, all, ap, c.o.exec); }));
        timing[1].values.push_back(medianMs(reps, [&] { ao::saoSamplePass(pyr, proj, all, flat, c.o.exec); }));
        timing[2].values.push_back(medianMs(reps, [&] { ao::saoSamplePass(pyr, proj, all, sp, c.o.exec); }));
    }
    io::writePng((c.out / "plots" / "ao_radius_scaling.png").string(),
                 lineChart(radii, timing,
                           {880, 420, fmt::format("AO sample pass time vs radius, {}x{}", fw, fh),
                            "world-space radius (m)", "median time (ms)", false, true})
                     .view());
    Block b;
    b.heading = fmt::format("Sample-pass time vs radius (paper Figure 5), {}x{}, median of {} (ms)", fw, fh, reps);
    b.after = radiusTable(b, timing, 1, c.j["radius_scaling"]);
    b.figures.push_back({"plots/ao_radius_scaling.png", "AO time vs radius", Figure::Kind::Plot, 880, 420});
    return b;
}

// ---- Table 3: per-pass times with guard bands ---------------------------------------
Block passTimesBlock(const Context& c, const scene::AnalyticScene& room, int reps) {
    c.say("ao: per-pass times (Table 3)");
    const std::vector<Table3Size> sizes = table3Sizes(c.o.quick);
    Block b;
    b.heading = fmt::format("Per-pass times (paper Table 3), r = 1 m, median of {} runs (ms), {} threads", reps + 2,
                            resolvedThreads(c.o.exec));
    b.table.header = {"resolution", "guard band", "pixels incl. guard",  "z", "z pyramid", "AO samples + 2x2",
                      "blur",       "total",      "ns per visible pixel"};
    for (const Table3Size& r : sizes) {
        const int bw = r.w + 2 * r.g, bh = r.h + 2 * r.g;
        const scene::GeometryBuffer g = scene::castGeometry(room, kCamera, bw, bh, c.o.exec);
        ao::SaoParams p;
        p.guardBand = r.g;
        std::vector<ao::SaoTimings> runs;
        for (int k = 0; k < reps + 2; ++k) {
            ao::SaoTimings t{};
            ao::sao(g.depth.view(), kCamera, p, c.o.exec, &t);
            runs.push_back(t);
        }
        auto med = [&](double ao::SaoTimings::*f) {
            std::vector<double> v;
            for (const auto& t : runs) v.push_back(t.*f);
            return median(v);
        };
        const double total = med(&ao::SaoTimings::total);
        b.table.addRow(
            {fmt::format("{}x{}", r.w, r.h), std::to_string(r.g), std::to_string(std::int64_t{bw} * bh),
             fmt::format("{:.1f}", med(&ao::SaoTimings::z)), fmt::format("{:.1f}", med(&ao::SaoTimings::pyramid)),
             fmt::format("{:.1f}", med(&ao::SaoTimings::sample)), fmt::format("{:.1f}", med(&ao::SaoTimings::blur)),
             fmt::format("{:.1f}", total), fmt::format("{:.0f}", total * 1e6 / (double(r.w) * r.h))});
        c.j["pass_times"][fmt::format("{}x{}", r.w, r.h)] = {{"guard", r.g},
                                                             {"z_ms", med(&ao::SaoTimings::z)},
                                                             {"pyramid_ms", med(&ao::SaoTimings::pyramid)},
                                                             {"sample_ms", med(&ao::SaoTimings::sample)},
                                                             {"blur_ms", med(&ao::SaoTimings::blur)},
                                                             {"total_ms", total}};
    }
    return b;
}

#ifdef SSFX_HAVE_GPU
// ---- Figure 5 and Table 3 on the GPU: timestamps around each pass ------------------------
// A pass's time in one run of `pass` (0 when the stage did not run).
double stageMs(const gpu::AoPass& pass, const char* stage) {
    for (const auto& d : pass.lastDispatches())
        if (d.stage == stage) return d.milliseconds;
    return 0;
}

Block gpuRadiusScalingBlock(const Context& c, const scene::AnalyticScene& room, int reps) {
    const int fw = c.o.quick ? 320 : 2560, fh = c.o.quick ? 200 : 1600;
    c.say(fmt::format("ao: GPU sample-pass time vs radius at {}x{} (Figure 5, {})", fw, fh, c.gpu->info.name));
    const std::vector<double>& radii = kFigure5Radii;
    std::vector<Series> timing{{"alchemy", {}}, {"sao, no pyramid", {}}, {"sao", {}}};
    const scene::GeometryBuffer g = scene::castGeometry(room, kCamera, fw, fh, c.o.exec);
    // One pipeline per method and radius, made first; then interleaved rounds (every
    // pipeline once per round), so that a change of the device's clock hits all alike.
    std::vector<std::vector<std::unique_ptr<gpu::AoPass>>> passes(3);
    for (double r : radii) {
        const Figure5Params fp = figure5Params(r);
        passes[0].push_back(std::make_unique<gpu::AoPass>(c.gpu, "alchemy", fp.alchemy));
        passes[1].push_back(std::make_unique<gpu::AoPass>(c.gpu, "sao", fp.flat));
        passes[2].push_back(std::make_unique<gpu::AoPass>(c.gpu, "sao", fp.sao));
    }
    std::vector<std::vector<std::vector<double>>> ms(3, std::vector<std::vector<double>>(radii.size()));
    for (int round = -1; round < reps; ++round)  // round -1: warm-up
        for (std::size_t ri = 0; ri < radii.size(); ++ri)
            for (std::size_t m = 0; m < 3; ++m) {
                passes[m][ri]->run(g.depth.view(), kCamera);
                if (round >= 0) ms[m][ri].push_back(stageMs(*passes[m][ri], "sample"));
            }
    for (std::size_t m = 0; m < 3; ++m)
        for (std::size_t ri = 0; ri < radii.size(); ++ri) timing[m].values.push_back(median(ms[m][ri]));
    io::writePng((c.out / "plots" / "ao_radius_scaling_gpu.png").string(),
                 lineChart(radii, timing,
                           {880, 420, fmt::format("GPU AO sample pass time vs radius, {}x{}", fw, fh),
                            "world-space radius (m)", "median time (ms)", false, true})
                     .view());
    Block b;
    b.heading = fmt::format("GPU sample-pass time vs radius (paper Figure 5), {}x{}, {}, median of {} (ms)", fw, fh,
                            c.gpu->info.name, reps);
    b.after = "GPU timestamps around the sample pass, interleaved rounds. " +
              radiusTable(b, timing, 3, c.j["gpu"]["radius_scaling"]);
    b.figures.push_back({"plots/ao_radius_scaling_gpu.png", "GPU AO time vs radius", Figure::Kind::Plot, 880, 420});
    c.j["gpu"]["device"] = c.gpu->info.name;
    return b;
}

Block gpuPassTimesBlock(const Context& c, const scene::AnalyticScene& room, int reps) {
    c.say(fmt::format("ao: GPU per-pass times (Table 3, {})", c.gpu->info.name));
    const std::vector<Table3Size> sizes = table3Sizes(c.o.quick);
    Block b;
    b.heading = fmt::format("GPU per-pass times (paper Table 3), {}, r = 1 m, median of {} runs (ms)", c.gpu->info.name,
                            reps + 2);
    b.table.header = {"resolution", "guard band", "z",     "z pyramid",    "AO samples",
                      "2x2",        "blur",       "total", "alchemy total"};
    for (const Table3Size& r : sizes) {
        const int bw = r.w + 2 * r.g, bh = r.h + 2 * r.g;
        const scene::GeometryBuffer g = scene::castGeometry(room, kCamera, bw, bh, c.o.exec);
        ao::SaoParams p;
        p.guardBand = r.g;
        ao::AlchemyParams ap;
        ap.guardBand = r.g;
        gpu::Sao sao(c.gpu, p);
        gpu::Alchemy alchemy(c.gpu, ap);
        std::vector<double> z, pyr, sample, quad, blur, total, alchemyTotal;
        for (int k = -1; k < reps + 2; ++k) {  // k = -1: warm-up; the two methods interleaved
            sao.run(g.depth.view(), kCamera);
            alchemy.run(g.depth.view(), kCamera);
            if (k < 0) continue;
            z.push_back(stageMs(sao, "z")), pyr.push_back(stageMs(sao, "pyramid"));
            sample.push_back(stageMs(sao, "sample")), quad.push_back(stageMs(sao, "quad"));
            blur.push_back(stageMs(sao, "blur h") + stageMs(sao, "blur v"));
            total.push_back(sao.lastMilliseconds()), alchemyTotal.push_back(alchemy.lastMilliseconds());
        }
        auto f = [](const std::vector<double>& v) { return fmt::format("{:.3f}", median(v)); };
        b.table.addRow({fmt::format("{}x{}", r.w, r.h), std::to_string(r.g), f(z), f(pyr), f(sample), f(quad), f(blur),
                        f(total), f(alchemyTotal)});
        c.j["gpu"]["pass_times"][fmt::format("{}x{}", r.w, r.h)] = {{"guard", r.g},
                                                                    {"z_ms", median(z)},
                                                                    {"pyramid_ms", median(pyr)},
                                                                    {"sample_ms", median(sample)},
                                                                    {"quad_ms", median(quad)},
                                                                    {"blur_ms", median(blur)},
                                                                    {"total_ms", median(total)},
                                                                    {"alchemy_total_ms", median(alchemyTotal)}};
    }
    b.after =
        "GPU timestamps around each pass (the pyramid's levels together, both blur passes together) and around the "
        "whole pipeline (total, which also counts the barriers between the passes).";
    return b;
}
#endif

// ---- AlchemyAO, SAO and GTAO against two truths (issue: GTAO beside SAO) ---------------
// The contenders, each a registry method and preset at the comparison's radius.
struct Contender {
    std::string label, id, preset;
};
const std::vector<Contender> kContenders{
    {"alchemy", "alchemy", ""},      {"sao paper", "sao", "paper"},     {"sao released", "sao", "released"},
    {"gtao low", "gtao", "low"},     {"gtao medium", "gtao", "medium"}, {"gtao high", "gtao", "high"},
    {"gtao ultra", "gtao", "ultra"}, {"gtao ideal", "gtao", "ideal"},   {"gtao paper", "gtao", "paper"}};
const std::vector<float> kComparisonRadii{0.5f, 1.0f, 2.0f};  // m (the R)
constexpr const char* kTruthNames[] = {"obscurance", "binary"};

double meanAbsoluteError(const ImageF& a, const ImageF& b) {
    double s = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) s += std::abs(double(a.pixels()[i]) - b.pixels()[i]);
    return a.pixels().empty() ? 0.0 : s / double(a.pixels().size());
}

std::string fileName(std::string label) {
    std::replace(label.begin(), label.end(), ' ', '_');
    return label;
}

// PSNR and MAE of every contender against both ray-traced truths (one ray set per scene
// serves all radii and both definitions: ao::raytracedSet), at R = 0.5, 1 and 2 m; the
// images at R = 1 m with signed error images, one viewer per scene; a generated verdict.
std::vector<Block> methodComparison(const Context& c, const std::vector<AoRenderedScene>& entries, int aw, int ah,
                                    int guard, int rays) {
    const std::size_t nR = kComparisonRadii.size(), nM = kContenders.size();
    // psnr[t][m][s * nR + r], mae likewise: truth t, contender m, scene s, radius r.
    std::vector<std::vector<std::vector<double>>> psnr(2, std::vector<std::vector<double>>(nM)), mae = psnr;
    Block summary, detail[2];
    for (std::size_t si = 0; si < entries.size(); ++si) {
        const AoRenderedScene& e = entries[si];
        c.say(fmt::format("ao: {} ray-traced truths, obscurance and binary at r = 0.5, 1, 2 m ({} rays per pixel)",
                          e.name, rays));
        std::vector<ao::RaytracedParams> want;
        for (float r : kComparisonRadii)
            for (ao::Visibility v : {ao::Visibility::Obscurance, ao::Visibility::Binary}) {
                ao::RaytracedParams p;
                p.radius = r, p.raysPerPixel = rays, p.guardBand = guard, p.visibility = v;
                want.push_back(p);
            }
        const std::vector<ImageF> truths =
            ao::raytracedSet(*e.geometry, e.camera, aw + 2 * guard, ah + 2 * guard, want, c.o.exec);
        Viewer v;
        v.id = "ao_cmp_" + e.name;
        v.width = aw, v.height = ah;
        v.reference = "truth (binary)";
        v.initial = {"truth (binary)", "gtao high", "gtao high - binary"};
        for (int t = 0; t < 2; ++t) {
            const std::string file = fmt::format("ao_cmp_{}_truth_{}.png", e.name, kTruthNames[t]);
            io::writePng(c.image(file), grey(truths[2 + std::size_t(t)]).view());  // R = 1 m
            v.sources.emplace_back(fmt::format("truth ({})", kTruthNames[t]), "images/" + file);
        }
        for (std::size_t m = 0; m < nM; ++m) {
            const Contender& k = kContenders[m];
            const ao::AoMethodInfo& method = ao::aoMethodById(k.id);
            for (std::size_t r = 0; r < nR; ++r) {
                ao::AoParams p = method.defaults(k.preset);
                ao::setParam(method, p, "radius", kComparisonRadii[r]);
                ao::setParam(method, p, "guardBand", guard);
                ao::AoInput in;
                in.depth = e.depth.view(), in.camera = e.camera;
                const ImageF a = method.run(in, p, c.o.exec);
                for (std::size_t t = 0; t < 2; ++t) {
                    const ImageF& truth = truths[r * 2 + t];
                    psnr[t][m].push_back(psnrFromMse(mse(a.view(), truth.view())));
                    mae[t][m].push_back(meanAbsoluteError(a, truth));
                    c.j["comparison"][e.name][fmt::format("{:g}", kComparisonRadii[r])][k.label][kTruthNames[t]] = {
                        {"psnr", psnr[t][m].back()}, {"mae", mae[t][m].back()}};
                }
                if (r != 1) continue;  // the pictures at R = 1 m
                const std::string file = fmt::format("ao_cmp_{}_{}", e.name, fileName(k.label));
                io::writePng(c.image(file + ".png"), grey(a).view());
                v.sources.emplace_back(k.label, "images/" + file + ".png");
                for (std::size_t t = 0; t < 2; ++t) {
                    // Signed error x2 around grey: lighter where the method sees less occlusion.
                    const std::string err = fmt::format("{}_err_{}.png", file, kTruthNames[t]);
                    io::writePng(c.image(err), grey(difference(a, truths[2 + t]), 0.5f, 2.0f).view());
                    v.sources.emplace_back(fmt::format("{} - {}", k.label, kTruthNames[t]), "images/" + err);
                }
            }
        }
        summary.viewers.push_back(std::move(v));
    }
    // Detail tables: one per truth, a row per (contender, radius), "PSNR (MAE)" per scene.
    for (std::size_t t = 0; t < 2; ++t) {
        Block& b = detail[t];
        b.heading = fmt::format("Against the {} truth, per scene", kTruthNames[t]);
        b.text = fmt::format(
            "PSNR in dB (mean absolute error of A in parentheses) against the ray-traced {} ({} rays per pixel), "
            "per scene and radius; the best of each column and radius in bold.",
            t == 0 ? "obscurance (SAO's falloff weight)" : "binary visibility (GTAO's definition)", rays);
        b.table.header = {"method", "R (m)"};
        for (const auto& e : entries) b.table.header.push_back(e.name);
        for (std::size_t r = 0; r < nR; ++r)
            for (std::size_t m = 0; m < nM; ++m) {
                std::vector<std::string> row{kContenders[m].label, fmt::format("{:g}", kComparisonRadii[r])};
                std::vector<bool> best(2, false);
                for (std::size_t si = 0; si < entries.size(); ++si) {
                    const std::size_t i = si * nR + r;
                    row.push_back(fmt::format("{:.2f} ({:.4f})", psnr[t][m][i], mae[t][m][i]));
                    bool top = true;
                    for (std::size_t o = 0; o < nM; ++o) top = top && psnr[t][o][i] <= psnr[t][m][i];
                    best.push_back(top);
                }
                b.table.addRow(std::move(row));
                b.table.best.push_back(std::move(best));
            }
    }
    // Summary: the mean over scenes and radii per contender and truth, and the verdict.
    auto mean = [](const std::vector<double>& v) {
        double s = 0;
        for (double x : v) s += x;
        return v.empty() ? 0.0 : s / double(v.size());
    };
    summary.heading = "AlchemyAO, SAO and GTAO against two truths (spec gtao.md section 12)";
    summary.text = fmt::format(
        "Every method on the same depth buffer and camera at R = 0.5, 1 and 2 m, scored against two ray-traced "
        "truths from the real geometry: the obscurance (a hit at d < R takes away (1 - (d/R)^2)^3: SAO's and "
        "AlchemyAO's definition) and the binary visibility (a hit within R occludes fully: GTAO's). GTAO's presets "
        "run XeGTAO's defaults (radiusMultiplier 1.457, falloffRange 0.615, the 0.05 lift, finalValuePower 2.2); "
        "\"gtao ideal\" "
        "is the spec's definition-matching settings, \"gtao paper\" Jimenez et al.'s pipeline. Mean PSNR and MAE "
        "over the {} scenes and 3 radii at {}x{} (+{} px guard band). The viewers show R = 1 m: each method, and "
        "its signed error against either truth x2 around grey (lighter: too little occlusion).",
        entries.size(), aw, ah, guard);
    summary.table.header = {"method", "PSNR vs obscurance (dB)", "MAE vs obscurance", "PSNR vs binary (dB)",
                            "MAE vs binary"};
    std::vector<std::array<double, 2>> meanPsnr(nM);
    for (std::size_t m = 0; m < nM; ++m) {
        for (std::size_t t = 0; t < 2; ++t) meanPsnr[m][t] = mean(psnr[t][m]);
        summary.table.addRow({kContenders[m].label, fmt::format("{:.2f}", meanPsnr[m][0]),
                              fmt::format("{:.4f}", mean(mae[0][m])), fmt::format("{:.2f}", meanPsnr[m][1]),
                              fmt::format("{:.4f}", mean(mae[1][m]))});
        c.j["comparison_mean"][kContenders[m].label] = {{"psnr_obscurance", meanPsnr[m][0]},
                                                        {"mae_obscurance", mean(mae[0][m])},
                                                        {"psnr_binary", meanPsnr[m][1]},
                                                        {"mae_binary", mean(mae[1][m])}};
    }
    std::string verdict;
    for (std::size_t t = 0; t < 2; ++t) {
        std::vector<std::size_t> order(nM);
        for (std::size_t m = 0; m < nM; ++m) order[m] = m;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return meanPsnr[a][t] > meanPsnr[b][t]; });
        // The closest per radius, too: which method wins can change with R.
        std::string perRadius;
        for (std::size_t r = 0; r < nR; ++r) {
            std::size_t best = 0;
            double bestMean = -1e300;
            for (std::size_t m = 0; m < nM; ++m) {
                double s = 0;
                for (std::size_t si = 0; si < entries.size(); ++si) s += psnr[t][m][si * nR + r];
                if (s > bestMean) bestMean = s, best = m;
            }
            perRadius += fmt::format("{}{} at R = {:g} m", r ? (r + 1 == nR ? " and " : ", ") : "",
                                     kContenders[best].label, kComparisonRadii[r]);
        }
        verdict += fmt::format(
            "{}Against the {} truth the closest on average is {} ({:.2f} dB, {:.2f} dB ahead of {}; last: {} at "
            "{:.2f} dB); per radius the closest are {}.",
            t ? " " : "", kTruthNames[t], kContenders[order[0]].label, meanPsnr[order[0]][t],
            meanPsnr[order[0]][t] - meanPsnr[order[1]][t], kContenders[order[1]].label, kContenders[order.back()].label,
            meanPsnr[order.back()][t], perRadius);
    }
    const auto idx = [](const char* label) {
        return std::size_t(
            std::find_if(kContenders.begin(), kContenders.end(), [&](const Contender& k) { return k.label == label; }) -
            kContenders.begin());
    };
    const std::size_t high = idx("gtao high"), ideal = idx("gtao ideal"), sao = idx("sao paper");
    verdict += fmt::format(
        " GTAO high with XeGTAO's defaults against its own definition (binary): {:.2f} dB, {:+.2f} dB from the "
        "ideal settings; SAO (paper) against its own (obscurance): {:.2f} dB, and {:.2f} dB against GTAO's.",
        meanPsnr[high][1], meanPsnr[high][1] - meanPsnr[ideal][1], meanPsnr[sao][0], meanPsnr[sao][1]);
    summary.after = verdict;
    c.j["comparison_verdict"] = verdict;
    return {std::move(summary), std::move(detail[0]), std::move(detail[1])};
}

}  // namespace

Section runAoExperiments(const AoExperimentOptions& o) {
    if (o.outDir.empty()) throw Error("eval ao: no output directory");
    const fs::path out(o.outDir);
    for (const char* sub : {"images", "plots", "data"}) io::makeDirectories((out / sub).string());
    nlohmann::ordered_json j;
#ifdef SSFX_HAVE_GPU
    Context c{o, out, j, {}};
#else
    const Context c{o, out, j};
#endif
    if (o.backend != "cpu" && o.backend != "vulkan")
        throw Error(fmt::format("eval ao: backend '{}' (expected cpu or vulkan)", o.backend));
    if (o.backend == "vulkan") {
#ifdef SSFX_HAVE_GPU
        vkx::ContextOptions co;
        co.device = o.device;
        c.gpu = vkx::Context::create(co);
#else
        throw Error("eval ao --backend vulkan: this ssfx was built without the GPU backend");
#endif
    }
    const scene::AnalyticScene room = scene::roomScene();
    const int aw = o.quick ? 192 : 960, ah = o.quick ? 108 : 540, guard = o.quick ? 16 : 64;
    const int rays = o.quick ? 32 : 256, reps = o.quick ? 1 : 3;

    Section s;
    s.title = "Ambient obscurance (the SAO paper's experiments)";
    // The note is laid out in the report, whose root its links are relative to.
    s.note =
        "Scalable Ambient Obscurance ([doc](methods/sao.html)), the AlchemyAO baseline ([doc](methods/alchemy.html)) "
        "and ray-traced ground truth ([doc](methods/raytraced.html)) on analytic scenes rendered by exact ray "
        "casting and, in the accuracy table, on scenes rasterised by the Vulkan renderer (D32F depth) with Embree ray "
        "tracing their triangles for the truth. Data: [ao/data/ao.json](ao/data/ao.json).";
    if (!o.speedOnly) {
        s.blocks.push_back(zPrecisionBlock(c));
        s.blocks.push_back(normalPrecisionBlock(c, room));
        const std::vector<AoRenderedScene> entries = accuracyScenes(c, aw, ah, guard);
        s.blocks.push_back(accuracyBlock(c, entries, aw, ah, guard, rays));
        s.blocks.push_back(releasedComparison(c, entries, aw, ah, guard, rays));
        for (Block& b : methodComparison(c, entries, aw, ah, guard, rays)) s.blocks.push_back(std::move(b));
    }
    s.blocks.push_back(radiusScalingBlock(c, room, reps));
    s.blocks.push_back(passTimesBlock(c, room, reps));
#ifdef SSFX_HAVE_GPU
    if (c.gpu) {
        s.blocks.push_back(gpuRadiusScalingBlock(c, room, o.quick ? 1 : 5));
        s.blocks.push_back(gpuPassTimesBlock(c, room, o.quick ? 1 : 5));
    }
#endif

    io::writeTextAtomic((out / "data" / "ao.json").string(), j.dump(1) + "\n");
    io::writeTextAtomic((out / "data" / "ao.md").string(), markdown(s));
    return s;
}

}  // namespace ssfx::eval
