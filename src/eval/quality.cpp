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
    const auto bytes = io::readFile(path, io::kMaxImageFileBytes, "PNG", io::kPngMagic);
    return !io::isApng(bytes);
}

double meanOf(const std::vector<std::vector<double>>& v, std::size_t m) {
    double s = 0;
    int n = 0;
    for (const auto& row : v)
        if (!std::isnan(row[m])) s += row[m], ++n;
    return n ? s / n : kNaN;
}

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

double QualityTable::meanPsnr(std::size_t m) const { return meanOf(psnr, m); }
double QualityTable::meanSsim(std::size_t m) const { return meanOf(ssim, m); }

Score scoreAgainstX8(ImageView<const Rgba8> output1x, ImageView<const Rgba8> render8x, const Exec& exec) {
    if (std::int64_t{output1x.width()} * 8 != render8x.width() ||
        std::int64_t{output1x.height()} * 8 != render8x.height())
        throw Error(fmt::format("the x8 render is {}x{}, expected 8 times {}x{}", render8x.width(), render8x.height(),
                                output1x.width(), output1x.height()));
    const ImageRgba8 up = aa::upscaleMitchell(output1x, 8, {}, exec);
    return {psnr(up.view(), render8x, exec), ssim(up.view(), render8x, exec)};
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
    checkSettingsApply(t.methods, o.settings);
    auto say = [&](const std::string& s) {
        if (o.progress) o.progress({s});
    };
    for (const auto& name : t.images) {
        say(fmt::format("{}: loading renders", name));
        const ImageRgba8 x1 = io::readPng(renderSetPath(dir, name, 1));
        const ImageRgba8 x8 = io::readPng(renderSetPath(dir, name, 8));
        if (std::int64_t{x1.width()} * 8 != x8.width() || std::int64_t{x1.height()} * 8 != x8.height())
            throw Error(fmt::format("{}x8.png is {}x{}, expected 8 times {}.png ({}x{})", name, x8.width(), x8.height(),
                                    name, x1.width(), x1.height()));
        ImageRgba8 scaled[2];  // x2, x4, loaded when a method needs them
        auto& psnrRow = t.psnr.emplace_back(t.methods.size(), kNaN);
        auto& ssimRow = t.ssim.emplace_back(t.methods.size(), kNaN);
        for (std::size_t m = 0; m < t.methods.size(); ++m) {
            const MethodInfo& info = methodById(t.methods[m]);
            ImageRgba8 output;
            if (o.source == OutputSource::Given) {
                const std::string file = pathIn(dir, fmt::format("{}_{}.png", name, info.id));
                if (!fs::exists(file)) {
                    say(fmt::format("{} {}: no {}, skipped", name, info.id, file));
                    continue;
                }
                output = io::readPng(file);
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
                        s = io::readPng(file);
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
            const Score s = scoreAgainstX8(output.view(), x8.view(), o.exec);
            psnrRow[m] = s.psnr;
            ssimRow[m] = s.ssim;
            say(fmt::format("{} {}: PSNR {:.3f} dB, SSIM {:.4f}", name, info.id, s.psnr, s.ssim));
        }
    }
    return t;
}

std::string qualityJson(const QualityTable& t) {
    nlohmann::ordered_json j;
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
    for (const char* metric : {"psnr", "ssim"}) {
        const auto& values = std::string(metric) == "psnr" ? t.psnr : t.ssim;
        j[metric] = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < t.images.size(); ++i)
            for (std::size_t m = 0; m < t.methods.size(); ++m)
                if (!std::isnan(values[i][m])) j[metric][t.images[i]][t.methods[m]] = num(values[i][m]);
        for (std::size_t m = 0; m < t.methods.size(); ++m) {
            const double mean = std::string(metric) == "psnr" ? t.meanPsnr(m) : t.meanSsim(m);
            if (!std::isnan(mean)) j["mean"][metric][t.methods[m]] = num(mean);
        }
    }
    return j.dump(2) + "\n";
}

namespace {

std::string table(const QualityTable& t, bool markdown) {
    std::string s;
    for (int metric = 0; metric < 2; ++metric) {
        const auto& values = metric == 0 ? t.psnr : t.ssim;
        const int decimals = metric == 0 ? 3 : 4;
        s += metric == 0 ? (markdown ? "PSNR (dB, x8 upscale vs x8 render)\n\n" : "PSNR (dB)\n")
                         : (markdown ? "\nSSIM (8x8 windows, x8 upscale vs x8 render)\n\n" : "\nSSIM\n");
        std::vector<std::vector<std::string>> rows;
        std::vector<std::string> head{"image"};
        head.insert(head.end(), t.methods.begin(), t.methods.end());
        rows.push_back(head);
        for (std::size_t i = 0; i <= t.images.size(); ++i) {
            std::vector<std::string> r{i < t.images.size() ? t.images[i] : "mean"};
            for (std::size_t m = 0; m < t.methods.size(); ++m)
                r.push_back(
                    cell(i < t.images.size() ? values[i][m] : (metric == 0 ? t.meanPsnr(m) : t.meanSsim(m)), decimals));
            rows.push_back(r);
        }
        for (std::size_t ri = 0; ri < rows.size(); ++ri) {
            const auto& r = rows[ri];
            if (markdown) {
                s += "|";
                for (const auto& c : r) s += " " + c + " |";
                s += "\n";
                if (ri == 0) {
                    s += "|---|";
                    for (std::size_t c = 1; c < r.size(); ++c) s += "---:|";
                    s += "\n";
                }
            } else {
                s += fmt::format("{:<10}", r[0]);
                for (std::size_t c = 1; c < r.size(); ++c) s += fmt::format(" {:>8}", r[c]);
                s += "\n";
            }
        }
    }
    return s;
}

}  // namespace

std::string qualityMarkdown(const QualityTable& t) { return table(t, true); }
std::string qualityText(const QualityTable& t) { return table(t, false); }

}  // namespace ssfx::eval
