// The paper's quality protocol (see quality.hpp).
#include "ssfx/eval/quality.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::eval {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string pathIn(const std::string& dir, const std::string& file) { return (fs::path(dir) / file).string(); }

bool isStillPng(const std::string& path) {
    const auto bytes = io::readPngFile(path);
    return !io::isApng(bytes);
}

// A render or a given output: a still PNG. An APNG is refused by name rather than read as
// its first frame (animations are `ssfx eval temporal`'s).
ImageRgba8 readStill(const std::string& path) {
    const auto bytes = io::readPngFile(path);
    if (io::isApng(bytes))
        throw Error(
            fmt::format("{}: an animated PNG, where a still image is expected (animations: ssfx eval temporal)", path));
    return io::decodePng(bytes, path);
}

// `image` (read from `file`) must be `scale` times the 1x render's size.
void checkScaled(const ImageRgba8& image, const std::string& file, int scale, const ImageRgba8& x1,
                 const std::string& x1File) {
    if (std::int64_t{x1.width()} * scale == image.width() && std::int64_t{x1.height()} * scale == image.height())
        return;
    throw Error(fmt::format("{}: {}x{}, expected {}x{} ({} times {}, {}x{})", file, image.width(), image.height(),
                            std::int64_t{x1.width()} * scale, std::int64_t{x1.height()} * scale, scale, x1File,
                            x1.width(), x1.height()));
}

constexpr Scores kNoScores{kNaN, kNaN, kNaN, kNaN};

std::string cell(double v, int decimals) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return "inf";
    return fmt::format("{:.{}f}", v, decimals);
}

}  // namespace

std::vector<std::string> paperMethodOrder() {
    return {"ssaax4", "ssaax2", "blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p", "noaa"};
}

std::string renderSetFile(const std::string& name, int scale) {
    return scale == 1 ? name + ".png" : fmt::format("{}x{}.png", name, scale);
}

std::string renderSetPath(const std::string& dir, const std::string& name, int scale) {
    return (fs::path(dir) / renderSetFile(name, scale)).string();
}

std::vector<std::string> findRenderSets(const std::string& dir) {
    if (!fs::is_directory(dir)) throw Error(fmt::format("'{}' is not a directory", dir));
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const fs::path p = entry.path();
        if (p.extension() != ".png") continue;
        const std::string stem = p.stem().string();
        if (stem.find('_') != std::string::npos) continue;  // NAME_METHOD.png
        if (!fs::exists(renderSetPath(dir, stem, 8))) continue;
        if (!isStillPng(p.string())) continue;  // animations: see temporal.hpp
        names.push_back(stem);
    }
    auto rank = [](const std::string& n) {
        const auto all = testImages();
        for (std::size_t i = 0; i < all.size(); ++i)
            if (all[i].name == n) return int(i);
        return int(all.size());
    };
    std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
        return rank(a) != rank(b) ? rank(a) < rank(b) : a < b;
    });
    return names;
}

const char* protocolName(Protocol p) { return p == Protocol::Paper ? "paper" : "truth"; }

std::vector<Protocol> parseProtocols(const std::string& text) {
    if (text == "paper") return {Protocol::Paper};
    if (text == "truth") return {Protocol::Truth};
    if (text == "both") return {Protocol::Paper, Protocol::Truth};
    throw Error(fmt::format("unknown protocol '{}' (paper, truth or both)", text));
}

double value(const Scores& s, Metric m) {
    switch (m) {
        case Metric::Psnr: return s.psnr;
        case Metric::Ssim: return s.ssim;
        case Metric::MaxError: return s.maxError;
        case Metric::P99Error: return s.p99Error;
    }
    return kNaN;
}

const char* metricKey(Metric m) {
    constexpr const char* k[] = {"psnr", "ssim", "max_error", "p99_error"};
    return k[int(m)];
}

int metricDecimals(Metric m) { return m == Metric::Psnr ? 3 : m == Metric::Ssim ? 4 : 1; }

const char* metricTitle(Metric m) {
    constexpr const char* k[] = {"PSNR (dB)", "SSIM", "max error (levels)", "99th-percentile error (levels)"};
    return k[int(m)];
}

bool QualityTable::has(Protocol p) const { return std::find(protocols.begin(), protocols.end(), p) != protocols.end(); }

const Scores& QualityTable::at(Protocol p, Region r, std::size_t i, std::size_t m) const {
    const auto it = std::find(protocols.begin(), protocols.end(), p);
    if (it == protocols.end()) throw Error(fmt::format("the {} protocol was not evaluated", protocolName(p)));
    return scores[std::size_t(it - protocols.begin())][std::size_t(r)].at(i).at(m);
}

double QualityTable::mean(Protocol p, Region r, Metric k, std::size_t m) const {
    double s = 0;
    int n = 0;
    for (std::size_t i = 0; i < images.size(); ++i)
        if (const double v = value(p, r, k, i, m); !std::isnan(v)) s += v, ++n;
    return n ? s / n : kNaN;
}

ImageRgba8 resolveTruth(ImageView<const Rgba8> render8x, const Exec& exec) {
    return aa::downscaleMitchell(render8x, 8, {}, exec);
}

Image<std::uint8_t> edgeMask(ImageView<const Rgba8> truth1x, ImageView<const Rgba8> render1x) {
    return differenceMask(truth1x, render1x);
}

namespace {

Scores scoresOf(ImageView<const Rgba8> a, ImageView<const Rgba8> b, const PixelMask& mask, const Exec& exec) {
    const ErrorStats e = errorStats(a, b, mask, exec);
    // SSIM needs one whole 8x8 window (images under 8 px have none).
    const double s = a.width() >= 8 && a.height() >= 8 ? ssim(a, b, mask, exec) : kNaN;
    return {e.psnr, e.pixels ? s : kNaN, e.maxError, e.p99Error};
}

}  // namespace

Scores scoreOutput(Protocol protocol, ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x,
                   ImageView<const Rgba8> truth1x, ImageView<const std::uint8_t> edges, const Exec& exec) {
    if (protocol == Protocol::Truth) return scoresOf(output1x, truth1x, {edges, 1}, exec);
    if (std::int64_t{output1x.width()} * 8 != render8x.width() ||
        std::int64_t{output1x.height()} * 8 != render8x.height())
        throw Error(fmt::format("the x8 render is {}x{}, expected 8 times {}x{}", render8x.width(), render8x.height(),
                                output1x.width(), output1x.height()));
    const ImageRgba8 up = aa::upscaleMitchell(output1x, 8, {}, exec);
    return scoresOf(up.view(), render8x, {edges, 8}, exec);
}

Score scoreAgainstX8(ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x, const Exec& exec) {
    const Scores s = scoreOutput(Protocol::Paper, output1x, render8x, {}, {}, exec);
    return {s.psnr, s.ssim};
}

MethodSettings settingsFor(const MethodInfo& m, const MethodSettings& s) {
    MethodSettings r;
    r.filtering = s.filtering;
    if (m.usesPresets) r.preset = s.preset;
    for (const auto& [name, value] : s.params)
        for (const ParamInfo& p : m.params)
            if (p.name == name) r.params.emplace_back(name, value);
    return r;
}

void checkSettingsApply(const std::vector<std::string>& methods, const MethodSettings& s) {
    for (const auto& [name, value] : s.params) {
        bool used = false;
        for (const auto& id : methods)
            for (const ParamInfo& p : methodById(id).params) used = used || p.name == name;
        if (!used) throw Error(fmt::format("no chosen method has a parameter '{}'", name));
    }
}

QualityTable evaluateQuality(const std::string& dir, const QualityOptions& o) {
    QualityTable t;
    t.images = o.images.empty() ? findRenderSets(dir) : o.images;
    if (t.images.empty()) throw Error(fmt::format("no renders in '{}' (need NAME.png and NAMEx8.png)", dir));
    t.methods = o.methods.empty() ? paperMethodOrder() : o.methods;
    for (const auto& id : t.methods) methodById(id);  // unknown ids fail before any work
    if (o.protocols.empty()) throw Error("no protocol to evaluate");
    t.protocols = o.protocols;
    t.scores.resize(t.protocols.size());
    checkSettingsApply(t.methods, o.settings);
    auto say = [&](const std::string& s) {
        if (o.progress) o.progress({s});
    };
    for (const auto& name : t.images) {
        say(fmt::format("{}: loading renders", name));
        const std::string x1File = renderSetPath(dir, name, 1), x8File = renderSetPath(dir, name, 8);
        const ImageRgba8 x1 = readStill(x1File);
        const ImageRgba8 x8 = readStill(x8File);
        checkScaled(x8, x8File, 8, x1, x1File);
        const ImageRgba8 truth = resolveTruth(x8.view(), o.exec);
        const Image<std::uint8_t> edges = edgeMask(truth.view(), x1.view());
        t.pixels.push_back(x1.pixelCount());
        t.edgePixels.push_back(std::count(edges.pixels().begin(), edges.pixels().end(), std::uint8_t{1}));
        for (auto& grids : t.scores)
            for (auto& grid : grids) grid.emplace_back(t.methods.size(), kNoScores);
        ImageRgba8 scaled[2];  // x2, x4, loaded when a method needs them
        for (std::size_t m = 0; m < t.methods.size(); ++m) {
            const MethodInfo& info = methodById(t.methods[m]);
            ImageRgba8 output;
            if (o.source == OutputSource::Given) {
                const std::string file = pathIn(dir, fmt::format("{}_{}.png", name, info.id));
                if (!fs::exists(file)) {
                    say(fmt::format("{} {}: no {}, skipped", name, info.id, file));
                    continue;
                }
                output = readStill(file);
                checkScaled(output, file, 1, x1, x1File);
            } else {
                const ImageRgba8* input = &x1;
                if (info.inputScale != 1) {
                    ImageRgba8& s = scaled[info.inputScale == 4 ? 1 : 0];
                    const std::string file = renderSetPath(dir, name, info.inputScale);
                    if (s.empty()) {
                        if (!fs::exists(file)) {
                            say(fmt::format("{} {}: no {}, skipped", name, info.id, file));
                            continue;
                        }
                        s = readStill(file);
                        checkScaled(s, file, info.inputScale, x1, x1File);
                    }
                    input = &s;
                }
                output = info.run(input->view(), settingsFor(info, o.settings), o.exec);
                if (!o.outputsDir.empty())
                    io::writePng(pathIn(o.outputsDir, fmt::format("{}_{}.png", name, info.id)), output.view());
            }
            if (output.width() != x1.width() || output.height() != x1.height())
                throw Error(fmt::format("{} output of {} is {}x{}, expected {}x{}", name, info.id, output.width(),
                                        output.height(), x1.width(), x1.height()));
            std::string line = fmt::format("{} {}:", name, info.id);
            for (std::size_t p = 0; p < t.protocols.size(); ++p) {
                for (const Region r : {Region::All, Region::Edges})
                    t.scores[p][std::size_t(r)].back()[m] =
                        scoreOutput(t.protocols[p], output.view(), x8.view(), truth.view(),
                                    r == Region::Edges ? edges.view() : ImageView<const std::uint8_t>{}, o.exec);
                const Scores& all = t.scores[p][0].back()[m];
                line +=
                    fmt::format(" {} PSNR {:.3f} dB, SSIM {:.4f};", protocolName(t.protocols[p]), all.psnr, all.ssim);
            }
            line.pop_back();
            say(line);
        }
    }
    return t;
}

std::string qualityJson(const QualityTable& t) {
    using Json = nlohmann::ordered_json;
    Json j;
    auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(); };
    j["protocols"] = Json::array();
    for (const Protocol p : t.protocols) j["protocols"].push_back(protocolName(p));
    for (std::size_t i = 0; i < t.images.size(); ++i) {
        j["pixels"][t.images[i]] = t.pixels[i];
        j["edge_pixels"][t.images[i]] = t.edgePixels[i];
    }
    for (const Protocol p : t.protocols)
        for (const Region r : {Region::All, Region::Edges}) {
            Json& g = j[protocolName(p)][r == Region::All ? "all" : "edges"];
            for (const Metric k : kMetrics) {
                g[metricKey(k)] = Json::object();
                for (std::size_t i = 0; i < t.images.size(); ++i)
                    for (std::size_t m = 0; m < t.methods.size(); ++m)
                        if (const double v = t.value(p, r, k, i, m); !std::isnan(v))
                            g[metricKey(k)][t.images[i]][t.methods[m]] = num(v);
            }
            g["mean"] = Json::object();
            for (const Metric k : kMetrics)
                for (std::size_t m = 0; m < t.methods.size(); ++m)
                    if (const double v = t.mean(p, r, k, m); !std::isnan(v))
                        g["mean"][metricKey(k)][t.methods[m]] = num(v);
        }
    return j.dump(2) + "\n";
}

namespace {

std::string regionTitle(Protocol p, Region r) {
    const char* what = p == Protocol::Paper ? "x8 upscale vs x8 render" : "1x output vs the truth (x8 resolved to 1x)";
    return fmt::format("{} protocol ({}){}", protocolName(p), what, r == Region::Edges ? ", edge pixels only" : "");
}

// One metric's table: image rows plus a mean row.
std::string metricTable(const QualityTable& t, Protocol p, Region r, Metric k, bool markdown) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> head{"image"};
    head.insert(head.end(), t.methods.begin(), t.methods.end());
    rows.push_back(head);
    for (std::size_t i = 0; i <= t.images.size(); ++i) {
        std::vector<std::string> row{i < t.images.size() ? t.images[i] : "mean"};
        for (std::size_t m = 0; m < t.methods.size(); ++m)
            row.push_back(cell(i < t.images.size() ? t.value(p, r, k, i, m) : t.mean(p, r, k, m), metricDecimals(k)));
        rows.push_back(row);
    }
    std::string s;
    for (std::size_t ri = 0; ri < rows.size(); ++ri) {
        const auto& row = rows[ri];
        if (markdown) {
            s += "|";
            for (const auto& c : row) s += " " + c + " |";
            s += "\n";
            if (ri == 0) {
                s += "|---|";
                for (std::size_t c = 1; c < row.size(); ++c) s += "---:|";
                s += "\n";
            }
        } else {
            s += fmt::format("{:<10}", row[0]);
            for (std::size_t c = 1; c < row.size(); ++c) s += fmt::format(" {:>8}", row[c]);
            s += "\n";
        }
    }
    return s;
}

std::string maskSizes(const QualityTable& t) {
    std::string s = "Edge pixels (where the truth differs from the aliased 1x render):";
    for (std::size_t i = 0; i < t.images.size(); ++i)
        s += fmt::format("{} {} {} of {} ({:.1f} %)", i ? "," : "", t.images[i], t.edgePixels[i], t.pixels[i],
                         100.0 * double(t.edgePixels[i]) / double(t.pixels[i]));
    return s + ".\n";
}

}  // namespace

std::string qualityMarkdown(const QualityTable& t) {
    std::string s;
    for (const Protocol p : t.protocols)
        for (const Region r : {Region::All, Region::Edges})
            for (const Metric k : kMetrics)
                s += fmt::format("{}{}, {}\n\n{}", s.empty() ? "" : "\n", metricTitle(k), regionTitle(p, r),
                                 metricTable(t, p, r, k, true));
    return s + "\n" + maskSizes(t);
}

std::string qualityText(const QualityTable& t) {
    std::string s;
    for (const Protocol p : t.protocols)
        for (const Region r : {Region::All, Region::Edges})
            for (const Metric k : {Metric::Psnr, Metric::Ssim})
                s += fmt::format("{}{}, {}\n{}", s.empty() ? "" : "\n", metricTitle(k), regionTitle(p, r),
                                 metricTable(t, p, r, k, false));
    return s + "\n" + maskSizes(t);
}

}  // namespace ssfx::eval
