// The HTML report (see report.hpp). Runs the whole evaluation: draws the test images,
// scores every method (quality.hpp), measures flicker (temporal.hpp), speed (speed.hpp)
// and the kernel experiment (kernels.hpp), draws the charts (plot.hpp) and writes one
// static page with relative links only.
#include "ssfx/eval/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "src/eval/report_html.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/ao_experiments.hpp"
#include "ssfx/eval/kernels.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/section.hpp"
#include "ssfx/eval/speed.hpp"
#include "ssfx/eval/temporal.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::eval {

namespace detail {
const std::vector<std::pair<std::string_view, std::string_view>>& methodDocs();  // generated
}

namespace {

namespace fs = std::filesystem;

// What every section of one report run shares.
struct Run {
    const ReportOptions& o;
    fs::path out;
    std::vector<std::string> methodIds;
    nlohmann::ordered_json all;

    void say(const std::string& s) const {
        if (o.progress) o.progress({s});
    }
    std::string images() const { return (out / "images").string(); }
    std::string path(const char* sub, const std::string& file) const { return (out / sub / file).string(); }
    // data/NAME.json (and .md), and the same JSON under `key` in data/all.json.
    void data(const std::string& key, const std::string& name, const std::string& json, const std::string& md = {}) {
        io::writeTextAtomic(path("data", name + ".json"), json);
        if (!md.empty()) io::writeTextAtomic(path("data", name + ".md"), md);
        if (!key.empty()) all[key] = nlohmann::ordered_json::parse(json);
    }
};

Figure plot(const std::string& file, const std::string& alt, int width, int height) {
    return Figure{"plots/" + file, alt, Figure::Kind::Plot, width, height};
}

// ---- the render sets: test images at 1x..8x, the x8 render resolved to 1x (the truth the
// viewer shows beside the outputs), and render sets from elsewhere (3-D scenes) with theirs ---------------------
void writeTruth(const Run& r, const std::string& name, const ImageRgba8& x8) {
    io::writePng(r.path("images", name + "_truth.png"), aa::downscaleMitchell(x8.view(), 8, {}, r.o.exec).view());
}

void drawTestImageSets(const Run& r) {
    for (const auto& t : testImages()) {
        if (t.frames != 1) continue;
        r.say(fmt::format("report: drawing {}", t.name));
        for (int s : {1, 2, 4, 8}) {
            const ImageRgba8 img = drawTestImage(t.name, s);
            io::writePng(r.path("images", renderSetFile(std::string(t.name), s)), img.view());
            if (s == 8) writeTruth(r, std::string(t.name), img);
        }
    }
}

std::map<std::string, std::string> addRenderSets(const Run& r) {
    std::map<std::string, std::string> extra;  // name -> description
    if (!r.o.addRenderSets) return extra;
    for (const auto& [name, description] : r.o.addRenderSets(r.images())) {
        extra[name] = description;
        writeTruth(r, name, io::readPng(renderSetPath(r.images(), name, 8)));
    }
    return extra;
}

// ---- Quality under both protocols on our images, writing every output for the viewer ------------
QualityTable runQuality(Run& r) {
    QualityOptions qo;
    qo.methods = r.methodIds;
    qo.outputsDir = r.images();
    qo.exec = r.o.exec;
    qo.progress = r.o.progress;
    const QualityTable quality = evaluateQuality(r.images(), qo);
    r.data("quality", "quality", qualityJson(quality), qualityMarkdown(quality));
    return quality;
}

// Image rows plus a mean row of one metric; best per row marked.
Table withMeanTable(const QualityTable& t, Protocol p, Region region, Metric k) {
    std::vector<std::vector<double>> values(t.images.size() + 1);
    for (std::size_t i = 0; i <= t.images.size(); ++i)
        for (std::size_t m = 0; m < t.methods.size(); ++m)
            values[i].push_back(i < t.images.size() ? t.value(p, region, k, i, m) : t.mean(p, region, k, m));
    std::vector<std::string> rows = t.images;
    rows.push_back("mean");
    return numericTable("image", rows, t.methods, values, metricDecimals(k), k == Metric::Psnr || k == Metric::Ssim);
}

// A grouped bar chart of one metric per image and method, written to plots/FILE.
Figure metricChart(const Run& r, const QualityTable& t, Protocol p, Region region, Metric k, const std::string& file,
                   const std::string& title) {
    std::vector<Series> series;
    for (std::size_t m = 0; m < t.methods.size(); ++m) {
        Series s{t.methods[m], {}};
        for (std::size_t i = 0; i < t.images.size(); ++i) s.values.push_back(t.value(p, region, k, i, m));
        series.push_back(std::move(s));
    }
    const std::string axis = k == Metric::Ssim ? "SSIM (unitless, 1 = identical)" : metricTitle(k);
    io::writePng(r.path("plots", file),
                 groupedBarChart(t.images, series, {880, 400, title, "image", axis, false, false}).view());
    return plot(file, title, 880, 400);
}

// A block of one metric's table (image rows and a mean row), with its chart when `chart` is set.
Block metricBlock(const Run& r, const QualityTable& t, Protocol p, Region region, Metric k, std::string heading,
                  std::string text, const std::string& chart = "", const std::string& chartTitle = "") {
    Block b;
    b.heading = std::move(heading);
    b.text = std::move(text);
    b.table = withMeanTable(t, p, region, k);
    if (!chart.empty()) b.figures.push_back(metricChart(r, t, p, region, k, chart, chartTitle));
    return b;
}

Section qualitySection(const Run& r, const QualityTable& quality) {
    const Protocol p = Protocol::Paper;
    Section s;
    s.title = "Quality (the paper's Table 2 protocol)";
    s.note =
        "Each method's 1x output (ssaax2 and ddaa2p from the x2 render, ssaax4 from the x4 render) is upscaled x8 "
        "with the Mitchell filter and compared with the x8 render. PSNR over RGB in [0,1]; SSIM on non-overlapping "
        "8x8 windows (one window per 1x pixel). Best per row in bold. `noaa` is the aliased input itself. The x8 "
        "render is aliased too, so this protocol rewards staying sharp: see the next section for the truth protocol.";
    Block psnr = metricBlock(r, quality, p, Region::All, Metric::Psnr, "PSNR (dB)", "", "psnr.png",
                             "PSNR per image and method, paper protocol (higher is better)");
    Block ssim = metricBlock(r, quality, p, Region::All, Metric::Ssim, "SSIM", "", "ssim.png",
                             "SSIM per image and method, paper protocol (8x8 windows)");
    s.blocks = {psnr, ssim};
    return s;
}

// Per image and protocol: each method's PSNR minus noaa's (positive: it beats the aliased input).
Block beatsNoaaBlock(const QualityTable& t) {
    Block b;
    b.heading = "Which methods beat noaa";
    const auto noaa = std::find(t.methods.begin(), t.methods.end(), "noaa");
    if (noaa == t.methods.end()) return b;
    const std::size_t n = std::size_t(noaa - t.methods.begin());
    std::vector<std::string> rows, columns;
    for (std::size_t m = 0; m < t.methods.size(); ++m)
        if (m != n) columns.push_back(t.methods[m]);
    std::vector<std::vector<double>> values;
    std::string summary;
    for (const Protocol p : t.protocols)
        for (std::size_t i = 0; i <= t.images.size(); ++i) {
            const bool mean = i == t.images.size();
            rows.push_back(fmt::format("{} ({})", mean ? "mean" : t.images[i], protocolName(p)));
            auto psnrOf = [&](std::size_t m) {
                return mean ? t.mean(p, Region::All, Metric::Psnr, m) : t.value(p, Region::All, Metric::Psnr, i, m);
            };
            std::vector<double> row;
            std::vector<std::string> winners;
            for (std::size_t m = 0; m < t.methods.size(); ++m) {
                if (m == n) continue;
                row.push_back(psnrOf(m) - psnrOf(n));
                if (row.back() > 0) winners.push_back(fmt::format("{} (+{:.2f})", t.methods[m], row.back()));
            }
            values.push_back(std::move(row));
            if (mean) continue;
            summary +=
                fmt::format("{} `{}`, {} protocol: {}. ", summary.empty() ? "" : "\n", t.images[i], protocolName(p),
                            winners.empty() ? "no method beats noaa" : fmt::format("{}", fmt::join(winners, ", ")));
        }
    b.text =
        "PSNR of each method minus that of `noaa` (the aliased input), in dB, per image, under each protocol: "
        "positive where the method is closer to the reference than doing nothing. Best per row in bold.";
    b.table = numericTable("image (protocol)", rows, columns, values, 2, true);
    b.after = summary;
    return b;
}

// "`lines` 71361 of 360000 pixels (19.8 %), ...": the edge masks' sizes, for the texts.
std::string edgeMaskSizes(const QualityTable& t, bool percent) {
    std::string sizes;
    for (std::size_t i = 0; i < t.images.size(); ++i) {
        sizes += fmt::format("{}`{}` {} of {} pixels", i ? ", " : "", t.images[i], t.edgePixels[i], t.pixels[i]);
        if (percent) sizes += fmt::format(" ({:.1f} %)", 100.0 * double(t.edgePixels[i]) / double(t.pixels[i]));
    }
    return sizes;
}

Section truthSection(const Run& r, const QualityTable& quality) {
    const Protocol p = Protocol::Truth;
    Section s;
    s.title = "Quality against the anti-aliased truth";
    s.note =
        "Each method's 1x output against the truth: the x8 render resolved to 1x with the Mitchell filter (the "
        "`truth` of the viewers; for the rendered atrium, its 8x8 supersampled render resolved the same way). PSNR "
        "and SSIM (8x8 windows) at 1x, and the per-pixel error e = max(|dR|, |dG|, |dB|) in 8-bit levels: its "
        "largest value and its 99th percentile. Edge scores count only the pixels where the truth differs from the "
        "aliased input (docs/evaluation.md).";
    const std::string sizes = edgeMaskSizes(quality, true);
    Block psnr = metricBlock(r, quality, p, Region::All, Metric::Psnr, "PSNR (dB)", "", "truth_psnr.png",
                             "PSNR per image and method against the truth (higher is better)");
    Block ssim = metricBlock(r, quality, p, Region::All, Metric::Ssim, "SSIM", "", "truth_ssim.png",
                             "SSIM per image and method against the truth (8x8 windows at 1x)");
    Block worst = metricBlock(r, quality, p, Region::All, Metric::MaxError, "Largest per-pixel error (levels)",
                              "Lowest per row in bold.");
    Block p99 = metricBlock(r, quality, p, Region::All, Metric::P99Error, "99th-percentile per-pixel error (levels)",
                            "Lowest per row in bold.");
    Block edges =
        metricBlock(r, quality, p, Region::Edges, Metric::Psnr, "Edge pixels only: PSNR (dB) against the truth",
                    "The mask: the pixels where the truth differs from the aliased 1x render: " + sizes + ".",
                    "truth_edges_psnr.png", "PSNR on the edge pixels against the truth (higher is better)");
    Block edgesSsim =
        metricBlock(r, quality, p, Region::Edges, Metric::Ssim, "Edge pixels only: SSIM against the truth",
                    "The mean over the 8x8 windows that hold an edge pixel.");
    s.blocks = {psnr, ssim, worst, p99, edges, edgesSsim};
    if (quality.has(Protocol::Paper)) {
        Block paperEdges = metricBlock(r, quality, Protocol::Paper, Region::Edges, Metric::Psnr,
                                       "Edge pixels only: PSNR (dB) under the paper's protocol",
                                       "The same mask, each edge pixel selecting its 8x8 block of the x8 images.");
        s.blocks.push_back(std::move(paperEdges));
    }
    s.blocks.push_back(beatsNoaaBlock(quality));
    return s;
}

// The truth protocol on the author's images: PSNR over the whole image and over the edge
// pixels, for the author's GPU outputs and for ssfx's on the same inputs.
Block truthRowsBlock(const QualityTable& given, const QualityTable& ours) {
    std::vector<std::string> rows;
    std::vector<std::vector<double>> vals;
    for (const Region region : {Region::All, Region::Edges})
        for (std::size_t i = 0; i < given.images.size(); ++i)
            for (const QualityTable* t : {&given, &ours}) {
                rows.push_back(fmt::format("{}{} ({})", given.images[i], region == Region::Edges ? ", edges" : "",
                                           t == &given ? "author's outputs" : "ssfx"));
                vals.emplace_back();
                for (std::size_t m = 0; m < t->methods.size(); ++m)
                    vals.back().push_back(t->value(Protocol::Truth, region, Metric::Psnr, i, m));
            }
    const std::string sizes = edgeMaskSizes(given, false);
    Block b;
    b.heading = "The author's images against the truth";
    b.text =
        "PSNR (dB) under the truth protocol of the DDAA author's GPU outputs and of ssfx's, over the whole "
        "image and over the edge pixels (" +
        sizes + "). Best per row in bold.";
    b.table = numericTable("image", rows, given.methods, vals, 3, true);
    return b;
}

// ---- The paper's rows from the DDAA author's data, when present, and the same images under
// the truth protocol ----------------------
struct AuthorBlocks {
    Block paperRows, truthRows;
};
std::optional<AuthorBlocks> authorRowsBlock(Run& r) {
    const ReportOptions& o = r.o;
    if (o.authorDataDir.empty() || !fs::is_directory(o.authorDataDir) || o.quick) return std::nullopt;
    QualityOptions ro;
    ro.methods = {"ssaax4", "ssaax2", "blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p"};
    ro.exec = o.exec;
    ro.progress = o.progress;
    ro.source = OutputSource::Given;
    const QualityTable given = evaluateQuality(o.authorDataDir, ro);
    ro.source = OutputSource::Compute;
    const QualityTable ours = evaluateQuality(o.authorDataDir, ro);
    r.data("", "author_given", qualityJson(given));
    r.data("", "author_ours", qualityJson(ours));
    r.all["author_data"] = {{"given", nlohmann::ordered_json::parse(qualityJson(given))},
                            {"ours", nlohmann::ordered_json::parse(qualityJson(ours))}};
    // The paper's published (rounded) values for its two images (spec ppaa.md section 3).
    const std::vector<std::vector<double>> published{{17.3, 17.2, 16.2, 16.2, 16.0, 17.1, 16.9, NAN},
                                                     {22.5, 22.4, 21.3, 21.6, 21.8, 22.3, 22.2, NAN}};
    std::vector<std::string> rows;
    std::vector<std::vector<double>> vals;
    for (std::size_t i = 0; i < given.images.size(); ++i) {
        if (given.images[i] == "lines" || given.images[i] == "circles") {
            rows.push_back(given.images[i] + " (paper)");
            vals.push_back(published[given.images[i] == "lines" ? 0 : 1]);
        }
        rows.push_back(given.images[i] + " (author's outputs)");
        vals.emplace_back();
        for (std::size_t m = 0; m < given.methods.size(); ++m) vals.back().push_back(given.psnr(i, m));
        rows.push_back(given.images[i] + " (ssfx)");
        vals.emplace_back();
        for (std::size_t m = 0; m < ours.methods.size(); ++m) vals.back().push_back(ours.psnr(i, m));
    }
    Block b;
    b.heading = "The paper's rows, reproduced on the author's images";
    b.text =
        "PSNR (dB) of the DDAA author's GPU outputs (`--source given`) and of ssfx's outputs on the same inputs, "
        "with the paper's published (rounded) values. Source: the author's ppaa-experiments repository (see "
        "`../shared/reference/README.md`).";
    b.table = numericTable("image", rows, given.methods, vals, 3, true);
    return AuthorBlocks{std::move(b), truthRowsBlock(given, ours)};
}

ImageRgba8 crop(const ImageRgba8& img, int x0, int y0, int w, int h) {
    ImageRgba8 c(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) c(x, y) = img(x0 + x, y0 + y);
    return c;
}

// ---- The opt-in colour-aware contrast (spec section 4) on every image, and up close on
// the green-on-grey rings of `circles` (the cell at (80, 320), 80 x 80 px) --------------
Section colourAwareSection(Run& r, const QualityTable& quality) {
    r.say("report: colour-aware contrast");
    constexpr double kChroma = 0.5;
    const ReportOptions& o = r.o;
    std::vector<std::string> lumaIds;
    for (const auto& id : r.methodIds)
        for (const ParamInfo& p : methodById(id).params)
            if (p.name == "chromaWeight") lumaIds.push_back(id);
    QualityOptions co;
    co.methods = lumaIds;
    co.exec = o.exec;
    co.settings.params = {{"chromaWeight", kChroma}};
    co.protocols = {Protocol::Paper};
    const QualityTable colour = evaluateQuality(r.images(), co);
    r.data("", "quality_colour_aware", qualityJson(colour));
    r.all["colour_aware"] = {{"chromaWeight", kChroma},
                             {"quality", nlohmann::ordered_json::parse(qualityJson(colour))}};
    std::vector<std::string> rows;
    std::vector<std::vector<double>> delta;
    for (std::size_t i = 0; i < colour.images.size(); ++i) {
        rows.push_back(colour.images[i]);
        delta.emplace_back();
        for (std::size_t m = 0; m < lumaIds.size(); ++m) {
            const auto it = std::find(quality.methods.begin(), quality.methods.end(), lumaIds[m]);
            delta.back().push_back(colour.psnr(i, m) - quality.psnr(i, std::size_t(it - quality.methods.begin())));
        }
    }
    // Close-up: PSNR of the cell alone (x8 upscale of the crop vs the x8 render's crop).
    const ImageRgba8 x1 = io::readPng(renderSetPath(r.images(), "circles", 1));
    const ImageRgba8 x2 = io::readPng(renderSetPath(r.images(), "circles", 2));
    const ImageRgba8 x8 = io::readPng(renderSetPath(r.images(), "circles", 8));
    const ImageRgba8 ref8 = crop(x8, 640, 2560, 640, 640);
    const ImageRgba8 truth = crop(io::readPng(r.path("images", "circles_truth.png")), 80, 320, 80, 80);
    io::writePng(r.path("images", "green_on_grey_truth.png"), truth.view());
    io::writePng(r.path("images", "green_on_grey_noaa.png"), crop(x1, 80, 320, 80, 80).view());
    Block b;
    b.figures = {{"images/green_on_grey_noaa.png", "input", Figure::Kind::Crop, 0, 0},
                 {"images/green_on_grey_truth.png", "truth (x8 resolved)", Figure::Kind::Crop, 0, 0}};
    std::vector<double> cellDefault, cellColour, cellDefault1x, cellColour1x;
    for (const auto& id : lumaIds) {
        const MethodInfo& m = methodById(id);
        const ImageRgba8& in = m.inputScale == 2 ? x2 : x1;
        MethodSettings on;
        on.params = {{"chromaWeight", kChroma}};
        const ImageRgba8 a = crop(m.run(in.view(), {}, o.exec), 80, 320, 80, 80);
        const ImageRgba8 c = crop(m.run(in.view(), on, o.exec), 80, 320, 80, 80);
        cellDefault.push_back(scoreAgainstX8(a.view(), ref8.view(), o.exec).psnr);
        cellColour.push_back(scoreAgainstX8(c.view(), ref8.view(), o.exec).psnr);
        cellDefault1x.push_back(psnr(a.view(), truth.view(), o.exec));
        cellColour1x.push_back(psnr(c.view(), truth.view(), o.exec));
        io::writePng(r.path("images", fmt::format("green_on_grey_{}.png", id)), a.view());
        io::writePng(r.path("images", fmt::format("green_on_grey_{}_colour.png", id)), c.view());
        b.figures.push_back({fmt::format("images/green_on_grey_{}.png", id), id, Figure::Kind::Crop, 0, 0});
        b.figures.push_back({fmt::format("images/green_on_grey_{}_colour.png", id),
                             fmt::format("{}, chromaWeight {}", id, kChroma), Figure::Kind::Crop, 0, 0});
    }
    rows.push_back("circles, green-on-grey cell: default");
    delta.push_back(cellDefault);
    rows.push_back(fmt::format("circles, green-on-grey cell: chromaWeight {}", kChroma));
    delta.push_back(cellColour);
    rows.push_back("same cell vs the x8 render resolved to 1x: default");
    delta.push_back(cellDefault1x);
    rows.push_back(fmt::format("same cell vs the x8 render resolved to 1x: chromaWeight {}", kChroma));
    delta.push_back(cellColour1x);
    b.table = numericTable("image", rows, lumaIds, delta, 3, true);
    Section s;
    s.title = "Colour-aware contrast (opt-in)";
    s.note = fmt::format(
        "All luma-based methods miss edges between colours of nearly equal luma (spec section 4; the green ring on the "
        "grey quadrant of `circles`, whose luma is within 0.001 of the background's). With `-p chromaWeight=K` they "
        "find edges on luma + K * (max - min of RGB) instead (`ssfx::edgeLuma`); greys keep their luma, and K = 0 (the "
        "default) leaves every output unchanged. First rows: PSNR change (dB) on each whole image with K = {0} (the "
        "paper's protocol); then the PSNR (dB) of the green-on-grey cell alone, by the paper's protocol (x8 upscale vs "
        "x8 render) and against the x8 render resolved to 1x (as in the temporal section).",
        kChroma);
    s.blocks.push_back(std::move(b));
    return s;
}

// ---- The sRGB-texture mode (-p texture=srgb) beside the default on every render set:
// each mode against the x8 render resolved the same way (unorm, as the paper; or in linear
// light, as an sRGB pipeline resolves), and up close on `lines` ------------------------------
Section srgbSection(Run& r, const QualityTable& quality) {
    r.say("report: sRGB textures");
    const ReportOptions& o = r.o;
    std::vector<std::string> ids;  // the methods with the mode, in the report's order
    for (const auto& id : r.methodIds)
        for (const ParamInfo& p : methodById(id).params)
            if (p.name == "texture") ids.push_back(id);
    MethodSettings on;
    on.params = {{"texture", 1.0}};
    aa::MitchellParams linear;
    linear.texture = TextureFormat::Srgb;
    std::vector<std::string> columns{"noaa"};
    columns.insert(columns.end(), ids.begin(), ids.end());
    std::vector<std::vector<double>> psnrDefault, psnrSrgb, ssimDefault, ssimSrgb;
    nlohmann::ordered_json j;
    constexpr int kCx = 120, kCy = 120, kCw = 80;  // the close-up: a fan of lines in `lines`
    Block close;
    for (const auto& name : quality.images) {
        const ImageRgba8 x1 = io::readPng(renderSetPath(r.images(), name, 1));
        const ImageRgba8 x8 = io::readPng(renderSetPath(r.images(), name, 8));
        const ImageRgba8 truthUnorm = io::readPng(r.path("images", name + "_truth.png"));
        const ImageRgba8 truthLinear = aa::downscaleMitchell(x8.view(), 8, linear, o.exec);
        io::writePng(r.path("images", name + "_truth_linear.png"), truthLinear.view());
        std::map<int, ImageRgba8> inputs{{1, x1}};
        psnrDefault.emplace_back(), psnrSrgb.emplace_back(), ssimDefault.emplace_back(), ssimSrgb.emplace_back();
        auto score = [&](const std::string& id, const ImageRgba8& a, const ImageRgba8& b) {
            psnrDefault.back().push_back(psnr(a.view(), truthUnorm.view(), o.exec));
            psnrSrgb.back().push_back(psnr(b.view(), truthLinear.view(), o.exec));
            ssimDefault.back().push_back(ssim(a.view(), truthUnorm.view(), o.exec));
            ssimSrgb.back().push_back(ssim(b.view(), truthLinear.view(), o.exec));
            j[name][id] = {{"psnr_unorm_vs_unorm_truth", psnrDefault.back().back()},
                           {"psnr_srgb_vs_linear_truth", psnrSrgb.back().back()},
                           {"ssim_unorm_vs_unorm_truth", ssimDefault.back().back()},
                           {"ssim_srgb_vs_linear_truth", ssimSrgb.back().back()}};
        };
        score("noaa", x1, x1);
        const bool closeUp = name == "lines" && x1.width() >= kCx + kCw && x1.height() >= kCy + kCw;
        if (closeUp) {
            io::writePng(r.path("images", "srgb_input.png"), crop(x1, kCx, kCy, kCw, kCw).view());
            io::writePng(r.path("images", "srgb_truth.png"), crop(truthUnorm, kCx, kCy, kCw, kCw).view());
            io::writePng(r.path("images", "srgb_truth_linear.png"), crop(truthLinear, kCx, kCy, kCw, kCw).view());
            close.figures = {
                {"images/srgb_input.png", "input", Figure::Kind::Crop, 0, 0},
                {"images/srgb_truth.png", "truth resolved in unorm", Figure::Kind::Crop, 0, 0},
                {"images/srgb_truth_linear.png", "truth resolved in linear light", Figure::Kind::Crop, 0, 0}};
        }
        for (const auto& id : ids) {
            const MethodInfo& m = methodById(id);
            if (!inputs.count(m.inputScale)) {
                const std::string path = renderSetPath(r.images(), name, m.inputScale);
                if (!fs::exists(path)) {  // a render set without this scale: no value
                    for (auto* t : {&psnrDefault, &psnrSrgb, &ssimDefault, &ssimSrgb}) t->back().push_back(NAN);
                    continue;
                }
                inputs[m.inputScale] = io::readPng(path);
            }
            const ImageRgba8& in = inputs[m.inputScale];
            const ImageRgba8 a = m.run(in.view(), {}, o.exec), b = m.run(in.view(), on, o.exec);
            score(id, a, b);
            if (closeUp && (id == "ddaa2" || id == "fxaa3d" || id == "ssaax4")) {
                io::writePng(r.path("images", fmt::format("srgb_{}.png", id)), crop(a, kCx, kCy, kCw, kCw).view());
                io::writePng(r.path("images", fmt::format("srgb_{}_srgb.png", id)), crop(b, kCx, kCy, kCw, kCw).view());
                close.figures.push_back({fmt::format("images/srgb_{}.png", id), id, Figure::Kind::Crop, 0, 0});
                close.figures.push_back(
                    {fmt::format("images/srgb_{}_srgb.png", id), id + ", texture=srgb", Figure::Kind::Crop, 0, 0});
            }
        }
    }
    r.all["srgb_texture"] = j;
    io::writeTextAtomic(r.path("data", "srgb_texture.json"), j.dump(1) + "\n");
    auto withMean = [&](std::vector<std::vector<double>> v) {
        std::vector<double> mean(columns.size(), 0.0);
        for (std::size_t c = 0; c < columns.size(); ++c) {
            int n = 0;
            for (const auto& row : v)
                if (!std::isnan(row[c])) mean[c] += row[c], ++n;
            mean[c] = n ? mean[c] / n : NAN;
        }
        v.push_back(mean);
        return v;
    };
    std::vector<std::string> rows = quality.images;
    rows.push_back("mean");
    Section s;
    s.title = "sRGB textures (opt-in)";
    s.note =
        "GPU plotting renderers run their post-process on an `rgba8unorm_srgb` texture: every read is decoded to "
        "linear light before filtering, and the result is encoded back (round to nearest). `-p texture=srgb` "
        "models that for every method that reads a texture; the luma thresholds then apply to the luma of the decoded "
        "values, as a shader on such a texture computes it (so dark, low-contrast edges fall below them). Each mode is "
        "scored against the x8 render resolved to 1x the same way: in unorm (the paper's protocol, as everywhere "
        "else on this page) or in linear light (what an sRGB pipeline's resolve gives). PSNR in dB, SSIM on 8x8 "
        "windows; data in [data/srgb_texture.json](data/srgb_texture.json).";
    Block a, b, c, d;
    a.heading = "PSNR: the default (unorm texture) against the truth resolved in unorm";
    a.table = numericTable("image", rows, columns, withMean(psnrDefault), 3, true);
    b.heading = "PSNR: texture=srgb against the truth resolved in linear light";
    b.table = numericTable("image", rows, columns, withMean(psnrSrgb), 3, true);
    c.heading = "SSIM: the default against the unorm truth";
    c.table = numericTable("image", rows, columns, withMean(ssimDefault), 4, true);
    d.heading = "SSIM: texture=srgb against the linear-light truth";
    d.table = numericTable("image", rows, columns, withMean(ssimSrgb), 4, true);
    s.blocks = {std::move(a), std::move(b), std::move(c), std::move(d)};
    if (!close.figures.empty()) {
        close.heading = "Up close: lines, 80 x 80 px";
        s.blocks.push_back(std::move(close));
    }
    return s;
}

// ---- The image viewers: every output of every render set ------------------------------
Section viewersSection(const Run& r, const QualityTable& quality, const std::map<std::string, std::string>& extraSets) {
    Section s;
    s.title = "Compare the outputs";
    s.note =
        "Pick one or more methods; \"side by side\" shows them together, \"flip\" shows one at a time (button "
        "\"next\" or key `f`, or auto-flip), \"wipe\" the first two picked on either side of the slider, "
        "\"difference\" |method - truth| (the largest of R, G and B, times the gain) through the colour scale "
        "shown above the panes. Zoom is nearest-neighbour; drag or scroll to pan (all panes move together). Under "
        "the cursor, the readout gives the RGB of the truth and of each shown method, and each one's error e. The "
        "address bar keeps the view (image, methods, mode, zoom, pan): copy it to link this view. "
        "`truth` is the x8 render resolved to 1x with the Mitchell filter.";
    for (const auto& name : quality.images) {
        Viewer v;
        v.id = name;
        std::string description;
        if (auto e = extraSets.find(name); e != extraSets.end()) {
            description = e->second;
            const ImageRgba8 img = io::readPng(r.path("images", name + ".png"));
            v.width = img.width();
            v.height = img.height();
        } else {
            const TestImageInfo& info = testImageByName(name);
            description = info.description;
            v.width = info.width;
            v.height = info.height;
        }
        v.sources = {{"truth", "images/" + name + "_truth.png"}};
        for (const auto& id : r.methodIds) v.sources.emplace_back(id, fmt::format("images/{}_{}.png", name, id));
        v.initial = {"noaa", "ddaa2"};
        std::vector<std::pair<std::string, std::string>> pngs;
        for (const auto& [label, file] : v.sources) {
            const auto bytes = io::readPngFile((r.out / file).string());
            pngs.emplace_back(label, std::string(bytes.begin(), bytes.end()));
        }
        v.pixels = "images/" + name + "_pixels.js";
        io::writeTextAtomic((r.out / v.pixels).string(), html::pixelScript(name, pngs));
        Block b;
        b.heading = name;
        b.text = description;
        b.viewers.push_back(std::move(v));
        s.blocks.push_back(std::move(b));
    }
    return s;
}

Table temporalTable(const std::vector<TemporalResult>& results) {
    std::vector<std::vector<double>> rows;
    std::vector<std::string> names;
    for (const auto& t : results) {
        names.push_back(t.method);
        rows.push_back({t.flickerLevels, t.temporalPsnr, t.psnr, t.mean.ssim, t.mean.maxError, t.mean.p99Error});
    }
    // (Best per row is meaningless across different metrics: no marks.)
    Table table = numericTable("method", names,
                               {"flicker (levels)", "tPSNR (dB)", "PSNR (dB)", "mean SSIM", "mean max error (levels)",
                                "mean p99 error (levels)"},
                               rows, 3, false);
    table.best.clear();
    return table;
}

// The author's animation, when the author's data has it (animatedx8.png and
// animated_METHOD.png): the given outputs and ssfx's on the same frames, streamed.
std::optional<Block> authorAnimationBlock(Run& r, const TemporalOptions& to) {
    const ReportOptions& o = r.o;
    if (o.authorDataDir.empty() || o.quick || !fs::exists(renderSetPath(o.authorDataDir, "animated", 8)))
        return std::nullopt;
    std::vector<std::pair<std::string, std::string>> given;
    for (const auto& id : r.methodIds) {
        const fs::path file = fs::path(o.authorDataDir) / fmt::format("animated_{}.png", id);
        if (fs::exists(file)) given.emplace_back(id, file.string());
    }
    if (given.empty()) return std::nullopt;
    TemporalOptions go = to;
    go.keepOutputs = false;
    go.methods.clear();
    for (const auto& g : given) go.methods.push_back(g.first);
    const TemporalRun g = evaluateTemporalGiven(*apngFrames(o.authorDataDir, "animated"), given, go);
    const TemporalRun ours = evaluateTemporal(*apngFrames(o.authorDataDir, "animated"), go);
    r.all["temporal_author"] = {{"given", nlohmann::ordered_json::parse(temporalJson(g.results))},
                                {"ours", nlohmann::ordered_json::parse(temporalJson(ours.results))}};
    std::vector<TemporalResult> rows;
    for (std::size_t m = 0; m < g.results.size(); ++m) {
        rows.push_back(g.results[m]);
        rows.back().method += " (author's outputs)";
        rows.push_back(ours.results[m]);
        rows.back().method += " (ssfx)";
    }
    Block b;
    b.heading = "The author's animation: given outputs and ssfx's";
    b.text =
        "The DDAA author's `animated` frames (the x8 frames resolved as the truth), scored from the author's GPU "
        "outputs "
        "(`ssfx eval temporal --source given`) and from ssfx's outputs on the same inputs; frames are streamed, one "
        "x8 frame in memory at a time.";
    b.table = temporalTable(rows);
    return b;
}

// ---- Temporal stability on the animation ------------------------------------------
Section temporalSection(Run& r) {
    const ReportOptions& o = r.o;
    const TestImageInfo& anim = testImageByName("animated");
    const int stride = o.quick ? 4 : 1, frames = anim.frames / stride;
    TemporalOptions to;
    to.methods = r.methodIds;
    to.exec = o.exec;
    to.progress = o.progress;
    const TemporalRun temporal = evaluateTemporal(
        frames, [&](int t, int s) { return drawTestImage(anim.name, s, t * stride); }, to);
    auto saveAnim = [&](const std::string& suffix, const std::vector<ImageRgba8>& images) {
        io::Animation a;
        for (const auto& img : images) a.frames.push_back({img, std::uint16_t(stride), std::uint16_t(anim.fps)});
        io::writeApng(r.path("anim", fmt::format("{}_{}.png", anim.name, suffix)), a);
    };
    saveAnim("truth", temporal.truth);
    for (std::size_t m = 0; m < r.methodIds.size(); ++m) saveAnim(r.methodIds[m], temporal.outputs[m]);
    r.data("temporal", "temporal", temporalJson(temporal.results), temporalMarkdown(temporal.results));

    Section s;
    s.title = "Temporal stability";
    s.note = fmt::format(
        "Each method applied to every frame of `animated` ({} frames{}); the truth is the x8 animation resolved to "
        "1x. Flicker is the RMS error of the method's frame-to-frame differences against the truth's (around the "
        "loop), in 8-bit levels; tPSNR is the same as a PSNR; PSNR compares the frames with the truth's (from the "
        "whole sequence's MSE); the means of the truth protocol's per-frame SSIM and errors follow, and the chart "
        "shows each frame's PSNR (docs/evaluation.md).",
        frames, o.quick ? ", every 4th frame" : "");
    Block table;
    table.table = temporalTable(temporal.results);
    s.blocks.push_back(std::move(table));
    if (auto author = authorAnimationBlock(r, to)) s.blocks.push_back(std::move(*author));

    std::vector<Series> flicker;
    for (const auto& t : temporal.results) flicker.push_back({t.method, std::vector<double>{t.flickerLevels}});
    io::writePng(r.path("plots", "flicker.png"),
                 groupedBarChart({std::string(anim.name)}, flicker,
                                 {880, 360, "Flicker: RMS error of frame-to-frame differences (lower is steadier)",
                                  "animation", "flicker (8-bit levels)", false, true})
                     .view());
    // The truth protocol per frame: PSNR of O_t against R_t.
    std::vector<double> frameAxis;
    for (int t = 0; t < frames; ++t) frameAxis.push_back(t * stride);
    std::vector<Series> perFrame;
    for (const auto& t : temporal.results) {
        perFrame.push_back({t.method, {}});
        for (const Scores& f : t.frames) perFrame.back().values.push_back(f.psnr);
    }
    io::writePng(r.path("plots", "temporal_psnr.png"),
                 lineChart(frameAxis, perFrame,
                           {880, 400, "PSNR of each frame against the truth (higher is better)", "frame (number)",
                            "PSNR (dB)", false, false})
                     .view());
    Block pictures;
    pictures.figures = {plot("flicker.png", "flicker per method", 880, 360),
                        plot("temporal_psnr.png", "PSNR per frame and method", 880, 400),
                        {"anim/animated_truth.png", "truth (x8 resolved)", Figure::Kind::Animation, 0, 0}};
    for (const auto& t : temporal.results)
        pictures.figures.push_back({fmt::format("anim/animated_{}.png", t.method),
                                    fmt::format("{}: flicker {:.2f}", t.method, t.flickerLevels),
                                    Figure::Kind::Animation, 0, 0});
    s.blocks.push_back(std::move(pictures));
    Block zoomable;
    zoomable.heading = "Animation, zoomable";
    Viewer v;  // APNGs: no pixel script (no difference mode or readout)
    v.id = "animated";
    v.width = anim.width;
    v.height = anim.height;
    v.sources = {{"truth", "anim/animated_truth.png"}};
    v.initial = {"noaa", "ddaa2"};
    for (const auto& id : r.methodIds) v.sources.emplace_back(id, fmt::format("anim/animated_{}.png", id));
    zoomable.viewers.push_back(std::move(v));
    s.blocks.push_back(std::move(zoomable));
    return s;
}

// ---- Speed (Table 3 layout) ----------------------------------------------------------
Section speedSection(Run& r) {
    const ReportOptions& o = r.o;
    SpeedOptions so;
    so.methods = r.methodIds;
    so.repetitions = o.quick ? 4 : o.speedRepetitions;
    so.warmup = o.quick ? 1 : 3;
    so.exec = o.exec;
    so.progress = o.progress;
    const SpeedTable speed = measureSpeed(r.images(), so);
    r.data("speed", "speed", speedJson(speed), speedMarkdown(speed));

    std::vector<Series> sp;
    for (std::size_t m = 0; m < speed.methods.size(); ++m) {
        Series s{speed.methods[m], {}};
        for (std::size_t i = 0; i < speed.images.size(); ++i) s.values.push_back(speed.results[i][m].relative);
        sp.push_back(s);
    }
    io::writePng(r.path("plots", "speed.png"),
                 groupedBarChart(speed.images, sp,
                                 {880, 400, "Time relative to blur = 100 (log scale, lower is faster)", "image",
                                  "time (% of blur)", true, true})
                     .view());
    std::vector<std::vector<double>> rel, med;
    for (const auto& row : speed.results) {
        rel.emplace_back();
        med.emplace_back();
        for (const auto& t : row) rel.back().push_back(t.relative), med.back().push_back(t.medianMs);
    }
    const MachineInfo& mi = speed.machine;
    Section s;
    s.title = "Speed (the paper's Table 3 layout)";
    s.note = fmt::format(
        "Machine: {}, {} of {} threads, SIMD target {}. Each method timed {} times per image, interleaved "
        "with the others; the fastest and slowest quarter dropped; relative to blur = 100 from the same "
        "run. The paper's GPU figures: fxaa3c 81-105, ddaa1 94-150, fxaa3d 160-352, ddaa2 175-255, "
        "ssaax2 71-94.",
        mi.cpu, mi.threads, mi.hardwareThreads, mi.simdTarget, speed.repetitions);
    Block relative{"Relative to blur = 100",
                   "",
                   {},
                   numericTable("image", speed.images, speed.methods, rel, 0, false),
                   "",
                   {},
                   {}};
    Block median{"Median (ms)",
                 "",
                 {},
                 numericTable("image", speed.images, speed.methods, med, 3, false),
                 "",
                 {plot("speed.png", "speed relative to blur", 880, 400)},
                 {}};
    s.blocks = {relative, median};
    return s;
}

// ---- Kernel experiment, aliased (the PPAA case) and with 4x4 coverage (for contrast) --
Section kernelSection(Run& r) {
    r.say("report: kernel experiment");
    KernelExperimentOptions ko;
    if (r.o.quick) ko.stepDegrees = 2;
    const KernelExperiment kernels = runKernelExperiment(ko);
    ko.supersample = 4;
    const KernelExperiment kernelsAa = runKernelExperiment(ko);
    r.data("kernels", "kernels", kernelJson(kernels));
    io::writeTextAtomic(r.path("data", "kernels_supersampled.json"), kernelJson(kernelsAa));
    std::vector<Series> ks;
    for (std::size_t k = 0; k < kernels.kernels.size(); ++k) ks.push_back({kernels.kernels[k], kernels.errorAt[k]});
    io::writePng(r.path("plots", "kernels.png"),
                 lineChart(kernels.angles, ks,
                           {880, 400, "Angle error on aliased lines (mean over widths 1, 2, 4 px)",
                            "line angle (degrees)", "error (degrees)", false, true})
                     .view());
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < kernels.kernels.size(); ++k)
        rows.push_back({kernels.meanError[k], kernels.maxError[k], kernelsAa.meanError[k]});
    Section s;
    s.title = "Kernel experiment (the paper's Figure 3)";
    s.note =
        "Angle of aliased lines (widths 1, 2 and 4 px, 0 to 90 degrees) estimated from the gradient at the pixels a "
        "PPAA method processes; error in degrees (docs/evaluation.md). Right column: the same lines with 4x4 "
        "coverage (antialiased) for contrast.";
    Block b;
    b.table = numericTable("kernel", kernels.kernels,
                           {"mean error, aliased", "max per-angle mean, aliased", "mean error, 4x4 coverage"}, rows, 3,
                           false);
    b.figures = {plot("kernels.png", "angle error per kernel", 880, 400)};
    s.blocks.push_back(std::move(b));
    return s;
}

Section methodsSection(const Run& r) {
    Section s;
    s.title = "Methods";
    Block b;
    for (const auto& id : r.methodIds) {
        const MethodInfo& m = methodById(id);
        b.definitions.push_back(
            {std::string(m.id), std::string(m.summary), std::string(m.citation), fmt::format("methods/{}.html", m.id)});
    }
    s.blocks.push_back(std::move(b));
    return s;
}

Section aoSection(const Run& r) {
    AoExperimentOptions ao;
    ao.outDir = (r.out / "ao").string();
    ao.quick = r.o.quick;
    ao.exec = r.o.exec;
    ao.progress = r.o.progress;
    ao.renderedScenes = r.o.renderedScenes;
    ao.backend = r.o.aoBackend;
    ao.device = r.o.aoDevice;
    Section s = runAoExperiments(ao);
    prefixPaths(s, "ao");
    return s;
}

}  // namespace

void writeReport(const ReportOptions& o) {
    if (o.outDir.empty()) throw Error("report: no output directory");
    Run r{o, fs::path(o.outDir), o.methods.empty() ? paperMethodOrder() : o.methods, {}};
    for (const char* sub : {"images", "anim", "plots", "data", "methods"}) io::makeDirectories((r.out / sub).string());
    for (const auto& id : r.methodIds) methodById(id);

    drawTestImageSets(r);
    const std::map<std::string, std::string> extraSets = addRenderSets(r);
    const QualityTable quality = runQuality(r);
    Section qualityPart = qualitySection(r, quality);
    Section truth = truthSection(r, quality);
    if (auto author = authorRowsBlock(r)) {
        qualityPart.blocks.push_back(std::move(author->paperRows));
        truth.blocks.push_back(std::move(author->truthRows));
    }
    const Section colour = colourAwareSection(r, quality);
    const Section srgb = srgbSection(r, quality);
    const Section temporal = temporalSection(r);
    const Section speed = speedSection(r);
    const Section kernels = kernelSection(r);
    std::vector<Section> sections{
        methodsSection(r), qualityPart, truth,  colour, viewersSection(r, quality, extraSets), srgb,
        temporal,          speed,       kernels};
    if (o.ambientObscurance) sections.push_back(aoSection(r));
    if (o.deferredExperiment) {  // the caller runs it: it needs the renderer
        Section d = o.deferredExperiment((r.out / "deferred").string());
        prefixPaths(d, "deferred");
        sections.push_back(std::move(d));
    }
    if (o.frameExperiment) {  // the caller runs it: it needs the GPU backend
        Section f = o.frameExperiment((r.out / "frame").string());
        prefixPaths(f, "frame");
        sections.push_back(std::move(f));
    }

    for (const auto& [id, text] : detail::methodDocs())
        io::writeTextAtomic(r.path("methods", std::string(id) + ".html"), html::docPage(id, text));
    io::writeTextAtomic(r.path("data", "all.json"), r.all.dump(1) + "\n");

    r.say("report: index.html");
    const Section intro{
        "ssfx: post-processing anti-aliasing, evaluated",
        "The DDAA paper's evaluation (spec `ppaa.md` section 3) on ssfx's own test images, drawn with "
        "Cairo without antialiasing at 1x, 2x, 4x and 8x. Every number on this page was computed by the "
        "run that wrote it; the data is in [data/all.json](data/all.json).",
        {}};
    io::writeTextAtomic((r.out / "index.html").string(),
                        html::page(intro, sections,
                                   "Written by ssfx 0.1.0. Tables as Markdown: [quality](data/quality.md), "
                                   "[temporal](data/temporal.md), [speed](data/speed.md)."));
}

}  // namespace ssfx::eval
