// The HTML report (see report.hpp). Runs the whole evaluation: draws the test images,
// scores every method (quality.hpp), measures flicker (temporal.hpp), speed (speed.hpp)
// and the kernel experiment (kernels.hpp), draws the charts (plot.hpp) and writes one
// static page with relative links only.
#include "ssfx/eval/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "report_assets.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/ao_experiments.hpp"
#include "ssfx/eval/kernels.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/speed.hpp"
#include "ssfx/eval/temporal.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/registry.hpp"

namespace ssfx::eval {

namespace detail {
const std::vector<std::pair<std::string_view, std::string_view>>& methodDocs();  // generated
}

namespace {

namespace fs = std::filesystem;

std::string esc(std::string_view s) {
    std::string o;
    for (char c : s) {
        switch (c) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            default: o += c;
        }
    }
    return o;
}

std::string fmtValue(double v, int decimals) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return "inf";
    return fmt::format("{:.{}f}", v, decimals);
}

// An HTML table of rows x methods; the best value of each row (higher or lower) in bold.
std::string htmlTable(const std::vector<std::string>& rowNames, const std::vector<std::string>& cols,
                      const std::vector<std::vector<double>>& values, int decimals, bool higherIsBetter,
                      const std::string& corner = "image") {
    std::string s = "<table><tr><th>" + esc(corner) + "</th>";
    for (const auto& c : cols) s += "<th>" + esc(c) + "</th>";
    s += "</tr>\n";
    for (std::size_t r = 0; r < rowNames.size(); ++r) {
        double best = higherIsBetter ? -INFINITY : INFINITY;
        for (double v : values[r])
            if (!std::isnan(v)) best = higherIsBetter ? std::max(best, v) : std::min(best, v);
        s += "<tr><td>" + esc(rowNames[r]) + "</td>";
        for (double v : values[r])
            s += fmt::format("<td{}>{}</td>", v == best ? " class=\"best\"" : "", fmtValue(v, decimals));
        s += "</tr>\n";
    }
    return s + "</table>\n";
}

std::vector<std::vector<double>> withMean(const QualityTable& t, bool psnr) {
    auto v = psnr ? t.psnr : t.ssim;
    std::vector<double> mean;
    for (std::size_t m = 0; m < t.methods.size(); ++m) mean.push_back(psnr ? t.meanPsnr(m) : t.meanSsim(m));
    v.push_back(mean);
    return v;
}

std::vector<std::string> rowsWithMean(std::vector<std::string> rows) {
    rows.push_back("mean");
    return rows;
}

std::string methodNote(const MethodInfo& m) {
    return fmt::format("<dt id=\"m-{0}\">{0}</dt><dd>{1} <em>{2}</em> (<a href=\"methods/{0}.html\">doc</a>)</dd>\n",
                       esc(m.id), esc(m.summary), esc(m.citation));
}

// A viewer section over `sources` (label -> relative URL), `initial` picked at first.
std::string viewer(const std::string& id, int w, int h, const std::vector<std::pair<std::string, std::string>>& sources,
                   const std::vector<std::string>& initial) {
    nlohmann::ordered_json src = nlohmann::ordered_json::object();
    for (const auto& [label, url] : sources) src[label] = url;
    const nlohmann::json init = initial;
    std::string s = fmt::format(
        "<section class=\"viewer\" id=\"viewer-{}\" data-width=\"{}\" data-height=\"{}\" data-pane-width=\"{}\" "
        "data-pane-height=\"{}\" data-sources=\"{}\" data-initial=\"{}\">\n<div class=\"controls\">"
        "<span>methods</span>",
        esc(id), w, h, 400, 400, esc(src.dump()), esc(init.dump()));
    for (const auto& [label, url] : sources) s += fmt::format("<button data-method=\"{0}\">{0}</button>", esc(label));
    s += "<span>mode</span><button data-mode=\"side\">side by side</button><button data-mode=\"flip\">flip</button>"
         "<button data-action=\"flip\" title=\"next picked method (key f)\">next</button>"
         "<button data-action=\"auto\">auto-flip</button><span>zoom</span>";
    for (int z : {1, 2, 4, 8, 16}) s += fmt::format("<button data-zoom=\"{0}\">{0}x</button>", z);
    s += "</div>\n<div class=\"panes\"></div>\n</section>\n";
    return s;
}

// The small Markdown subset our own tables use: "### " headings, pipe tables (second row
// the separator), paragraphs; `code` spans. Text is escaped.
std::string markdownToHtml(const std::string& md) {
    std::string html, line;
    std::vector<std::string> lines;
    for (std::size_t p = 0; p <= md.size();) {
        const std::size_t e = std::min(md.find('\n', p), md.size());
        lines.push_back(md.substr(p, e - p));
        p = e + 1;
    }
    auto inline_ = [](const std::string& s) {
        std::string o, t = esc(s);
        bool code = false;
        for (char c : t) {
            if (c == '`') {
                o += code ? "</code>" : "<code>";
                code = !code;
            } else {
                o += c;
            }
        }
        return o + (code ? "</code>" : "");
    };
    auto cells = [](const std::string& row) {
        std::vector<std::string> c;
        std::size_t p = row.find('|') + 1;
        while (true) {
            const std::size_t e = row.find('|', p);
            if (e == std::string::npos) break;
            std::string cell = row.substr(p, e - p);
            const auto b = cell.find_first_not_of(' '), f = cell.find_last_not_of(' ');
            c.push_back(b == std::string::npos ? "" : cell.substr(b, f - b + 1));
            p = e + 1;
        }
        return c;
    };
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        if (l.empty()) continue;
        if (l.rfind("### ", 0) == 0) {
            html += "<h3>" + inline_(l.substr(4)) + "</h3>\n";
        } else if (l[0] == '|') {
            html += "<table>";
            bool head = true;
            for (; i < lines.size() && !lines[i].empty() && lines[i][0] == '|'; ++i) {
                if (lines[i].rfind("|---", 0) == 0) continue;
                html += "<tr>";
                for (const auto& c : cells(lines[i])) html += (head ? "<th>" : "<td>") + inline_(c) + (head ? "</th>" : "</td>");
                html += "</tr>\n";
                head = false;
            }
            html += "</table>\n";
        } else {
            html += "<p class=\"note\">" + inline_(l) + "</p>\n";
        }
    }
    return html;
}

}  // namespace

void writeReport(const ReportOptions& o) {
    if (o.outDir.empty()) throw Error("report: no output directory");
    auto say = [&](const std::string& s) {
        if (o.progress) o.progress(s);
    };
    const fs::path out(o.outDir);
    for (const char* sub : {"images", "anim", "plots", "data", "methods"}) io::makeDirectories((out / sub).string());
    const std::vector<std::string> methodIds = o.methods.empty() ? paperMethodOrder() : o.methods;
    for (const auto& id : methodIds) methodById(id);
    nlohmann::ordered_json all;

    // 1. Test images at 1x..8x, and the x8 render resolved to 1x (the viewer's reference).
    std::vector<std::string> stills;
    for (const auto& t : testImages()) {
        if (t.frames != 1) continue;
        stills.emplace_back(t.name);
        say(fmt::format("report: drawing {}", t.name));
        for (int s : {1, 2, 4, 8}) {
            const ImageRgba8 img = drawTestImage(t.name, s);
            const std::string file = renderSetFile(std::string(t.name), s);
            io::writePng((out / "images" / file).string(), img.view());
            if (s == 8)
                io::writePng((out / "images" / (std::string(t.name) + "_reference.png")).string(),
                             aa::downscaleMitchell(img.view(), 8, {}, o.exec).view());
        }
    }

    // 1b. Render sets from elsewhere (3-D scenes), with their references.
    std::map<std::string, std::string> extraSets;  // name -> description
    if (o.addRenderSets)
        for (const auto& [name, description] : o.addRenderSets((out / "images").string())) {
            extraSets[name] = description;
            const ImageRgba8 x8 = io::readPng(renderSetPath((out / "images").string(), name, 8));
            io::writePng((out / "images" / (name + "_reference.png")).string(),
                         aa::downscaleMitchell(x8.view(), 8, {}, o.exec).view());
        }

    // 2. Quality (Table 2) on our images, writing every output for the viewer.
    QualityOptions qo;
    qo.methods = methodIds;
    qo.outputsDir = (out / "images").string();
    qo.exec = o.exec;
    qo.progress = o.progress;
    const QualityTable quality = evaluateQuality((out / "images").string(), qo);
    io::writeTextAtomic((out / "data" / "quality.json").string(), qualityJson(quality));
    io::writeTextAtomic((out / "data" / "quality.md").string(), qualityMarkdown(quality));
    all["quality"] = nlohmann::ordered_json::parse(qualityJson(quality));

    // 3a. The opt-in colour-aware contrast (spec section 4) on every image, and up close on
    // the green-on-grey rings of `circles` (the cell at (80, 320), 80 x 80 px).
    std::string colourSection;
    {
        say("report: colour-aware contrast");
        constexpr double kChroma = 0.5;
        std::vector<std::string> lumaIds;
        for (const auto& id : methodIds)
            for (const ParamInfo& p : methodById(id).params)
                if (p.name == "chromaWeight") lumaIds.push_back(id);
        QualityOptions co;
        co.methods = lumaIds;
        co.exec = o.exec;
        co.settings.params = {{"chromaWeight", kChroma}};
        const QualityTable colour = evaluateQuality((out / "images").string(), co);
        io::writeTextAtomic((out / "data" / "quality_colour_aware.json").string(), qualityJson(colour));
        all["colour_aware"] = {{"chromaWeight", kChroma},
                               {"quality", nlohmann::ordered_json::parse(qualityJson(colour))}};
        std::vector<std::string> rows;
        std::vector<std::vector<double>> delta;
        for (std::size_t i = 0; i < colour.images.size(); ++i) {
            rows.push_back(colour.images[i]);
            delta.emplace_back();
            for (std::size_t m = 0; m < lumaIds.size(); ++m) {
                const auto it = std::find(quality.methods.begin(), quality.methods.end(), lumaIds[m]);
                delta.back().push_back(colour.psnr[i][m] - quality.psnr[i][std::size_t(it - quality.methods.begin())]);
            }
        }
        // Close-up: PSNR of the cell alone (x8 upscale of the crop vs the x8 render's crop).
        const std::string images = (out / "images").string();
        const ImageRgba8 x1 = io::readPng(renderSetPath(images, "circles", 1));
        const ImageRgba8 x2 = io::readPng(renderSetPath(images, "circles", 2));
        const ImageRgba8 x8 = io::readPng(renderSetPath(images, "circles", 8));
        auto crop = [](const ImageRgba8& img, int x0, int y0, int w, int h) {
            ImageRgba8 c(w, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) c(x, y) = img(x0 + x, y0 + y);
            return c;
        };
        const ImageRgba8 ref8 = crop(x8, 640, 2560, 640, 640);
        const ImageRgba8 reference = crop(io::readPng((out / "images" / "circles_reference.png").string()), 80, 320, 80, 80);
        io::writePng((out / "images" / "green_on_grey_reference.png").string(), reference.view());
        io::writePng((out / "images" / "green_on_grey_noaa.png").string(), crop(x1, 80, 320, 80, 80).view());
        std::vector<double> cellDefault, cellColour, cellDefault1x, cellColour1x;
        std::string figures;
        for (const auto& id : lumaIds) {
            const MethodInfo& m = methodById(id);
            const ImageRgba8& in = m.inputScale == 2 ? x2 : x1;
            MethodSettings on;
            on.params = {{"chromaWeight", kChroma}};
            const ImageRgba8 a = crop(m.run(in.view(), {}, o.exec), 80, 320, 80, 80);
            const ImageRgba8 b = crop(m.run(in.view(), on, o.exec), 80, 320, 80, 80);
            cellDefault.push_back(scoreAgainstX8(a.view(), ref8.view(), o.exec).psnr);
            cellColour.push_back(scoreAgainstX8(b.view(), ref8.view(), o.exec).psnr);
            cellDefault1x.push_back(psnr(a.view(), reference.view(), o.exec));
            cellColour1x.push_back(psnr(b.view(), reference.view(), o.exec));
            io::writePng((out / "images" / fmt::format("green_on_grey_{}.png", id)).string(), a.view());
            io::writePng((out / "images" / fmt::format("green_on_grey_{}_colour.png", id)).string(), b.view());
            figures += fmt::format("<figure><img class=\"crop\" src=\"images/green_on_grey_{0}.png\" alt=\"{0}\">"
                                   "<figcaption>{0}</figcaption></figure><figure><img class=\"crop\" "
                                   "src=\"images/green_on_grey_{0}_colour.png\" alt=\"{0} colour-aware\">"
                                   "<figcaption>{0}, chromaWeight {1}</figcaption></figure>\n",
                                   esc(id), kChroma);
        }
        rows.push_back("circles, green-on-grey cell: default");
        delta.push_back(cellDefault);
        rows.push_back("circles, green-on-grey cell: chromaWeight " + fmt::format("{}", kChroma));
        delta.push_back(cellColour);
        rows.push_back("same cell vs the resolved x8 reference at 1x: default");
        delta.push_back(cellDefault1x);
        rows.push_back("same cell vs the resolved x8 reference at 1x: chromaWeight " + fmt::format("{}", kChroma));
        delta.push_back(cellColour1x);
        colourSection = fmt::format(
            "<h2>Colour-aware contrast (opt-in)</h2>\n<p class=\"note\">All luma-based methods miss edges between "
            "colours of nearly equal luma (spec section 4; the green ring on the grey quadrant of <code>circles</code>, "
            "whose luma is within 0.001 of the background's). With <code>-p chromaWeight=K</code> they find edges on "
            "luma + K * (max - min of RGB) instead (<code>ssfx::edgeLuma</code>); greys keep their luma, and K = 0 (the "
            "default) leaves every output unchanged. First rows: PSNR change (dB) on each whole image with K = {0} "
            "(the paper's protocol); then the PSNR (dB) of the green-on-grey cell alone, by the paper's protocol "
            "(x8 upscale vs x8 render) and against the x8 render resolved to 1x (as in the temporal section).</p>\n",
            kChroma);
        colourSection += htmlTable(rows, lumaIds, delta, 3, true);
        colourSection += "<div class=\"anims\"><figure><img class=\"crop\" src=\"images/green_on_grey_noaa.png\" "
                         "alt=\"input\"><figcaption>input</figcaption></figure><figure><img class=\"crop\" "
                         "src=\"images/green_on_grey_reference.png\" alt=\"reference\"><figcaption>reference"
                         "</figcaption></figure>\n" + figures + "</div>\n";
    }

    // 3b. The paper's rows from the author's data, when present.
    std::string reproduction;
    if (!o.referenceDir.empty() && fs::is_directory(o.referenceDir) && !o.quick) {
        QualityOptions ro;
        ro.methods = {"ssaax4", "ssaax2", "blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p"};
        ro.exec = o.exec;
        ro.progress = o.progress;
        ro.source = OutputSource::Given;
        const QualityTable given = evaluateQuality(o.referenceDir, ro);
        ro.source = OutputSource::Compute;
        const QualityTable ours = evaluateQuality(o.referenceDir, ro);
        io::writeTextAtomic((out / "data" / "reference_given.json").string(), qualityJson(given));
        io::writeTextAtomic((out / "data" / "reference_ours.json").string(), qualityJson(ours));
        all["reference"] = {{"given", nlohmann::ordered_json::parse(qualityJson(given))},
                            {"ours", nlohmann::ordered_json::parse(qualityJson(ours))}};
        reproduction =
            "<h3>The paper's rows, reproduced on the author's images</h3>\n<p class=\"note\">PSNR (dB) of the "
            "DDAA author's GPU outputs (<code>--source given</code>) and of ssfx's outputs on the same inputs, "
            "with the paper's published (rounded) values. Source: the author's ppaa-experiments repository "
            "(see <code>../shared/reference/README.md</code>).</p>\n";
        const std::vector<std::vector<double>> published{{17.3, 17.2, 16.2, 16.2, 16.0, 17.1, 16.9, NAN},
                                                         {22.5, 22.4, 21.3, 21.6, 21.8, 22.3, 22.2, NAN}};
        std::vector<std::string> rows;
        std::vector<std::vector<double>> vals;
        for (std::size_t i = 0; i < given.images.size(); ++i) {
            const bool known = given.images[i] == "lines" || given.images[i] == "circles";
            if (known) {
                rows.push_back(given.images[i] + " (paper)");
                vals.push_back(published[given.images[i] == "lines" ? 0 : 1]);
            }
            rows.push_back(given.images[i] + " (author's outputs)");
            vals.push_back(given.psnr[i]);
            rows.push_back(given.images[i] + " (ssfx)");
            vals.push_back(ours.psnr[i]);
        }
        reproduction += htmlTable(rows, given.methods, vals, 3, true);
    }

    // 4. Temporal stability on the animation.
    const TestImageInfo& anim = testImageByName("animated");
    const int stride = o.quick ? 4 : 1, frames = anim.frames / stride;
    TemporalOptions to;
    to.methods = methodIds;
    to.exec = o.exec;
    to.progress = o.progress;
    const TemporalRun temporal = evaluateTemporal(
        frames, [&](int t, int s) { return drawTestImage(anim.name, s, t * stride); }, to);
    auto saveAnim = [&](const std::string& suffix, const std::vector<ImageRgba8>& images) {
        io::Animation a;
        for (const auto& img : images) a.frames.push_back({img, std::uint16_t(stride), std::uint16_t(anim.fps)});
        io::writeApng((out / "anim" / fmt::format("{}_{}.png", anim.name, suffix)).string(), a);
    };
    saveAnim("reference", temporal.reference);
    for (std::size_t m = 0; m < methodIds.size(); ++m) saveAnim(methodIds[m], temporal.outputs[m]);
    io::writeTextAtomic((out / "data" / "temporal.json").string(), temporalJson(temporal.results));
    io::writeTextAtomic((out / "data" / "temporal.md").string(), temporalMarkdown(temporal.results));
    all["temporal"] = nlohmann::ordered_json::parse(temporalJson(temporal.results));

    // 4b. The author's animation, when the reference data has it (animatedx8.png and
    // animated_METHOD.png): the given outputs and ssfx's on the same frames, streamed.
    std::string temporalReference;
    if (!o.referenceDir.empty() && !o.quick && fs::exists(renderSetPath(o.referenceDir, "animated", 8))) {
        std::vector<std::pair<std::string, std::string>> given;
        for (const auto& id : methodIds) {
            const fs::path file = fs::path(o.referenceDir) / fmt::format("animated_{}.png", id);
            if (fs::exists(file)) given.emplace_back(id, file.string());
        }
        if (!given.empty()) {
            TemporalOptions go = to;
            go.keepOutputs = false;
            go.methods.clear();
            for (const auto& g : given) go.methods.push_back(g.first);
            const TemporalRun g = evaluateTemporalGiven(*apngFrames(o.referenceDir, "animated"), given, go);
            const TemporalRun ours = evaluateTemporal(*apngFrames(o.referenceDir, "animated"), go);
            all["temporal_reference"] = {{"given", nlohmann::ordered_json::parse(temporalJson(g.results))},
                                         {"ours", nlohmann::ordered_json::parse(temporalJson(ours.results))}};
            std::vector<std::string> rows;
            std::vector<std::vector<double>> vals;
            for (std::size_t m = 0; m < g.results.size(); ++m) {
                rows.push_back(g.results[m].method + " (author's outputs)");
                vals.push_back({g.results[m].flickerLevels, g.results[m].temporalPsnr, g.results[m].psnr});
                rows.push_back(g.results[m].method + " (ssfx)");
                vals.push_back({ours.results[m].flickerLevels, ours.results[m].temporalPsnr, ours.results[m].psnr});
            }
            temporalReference = "<h3>The author's animation: given outputs and ssfx's</h3>\n<p class=\"note\">The DDAA "
                                "author's <code>animated</code> frames (x8 resolved as the reference), scored from the "
                                "author's GPU outputs (<code>ssfx eval temporal --source given</code>) and from ssfx's "
                                "outputs on the same inputs; frames are streamed, one x8 frame in memory at a time.</p>\n" +
                                htmlTable(rows, {"flicker (levels)", "tPSNR (dB)", "PSNR (dB)"}, vals, 3, false, "method");
        }
    }

    // 5. Speed (Table 3 layout).
    SpeedOptions so;
    so.methods = methodIds;
    so.repetitions = o.quick ? 4 : o.speedRepetitions;
    so.warmup = o.quick ? 1 : 3;
    so.exec = o.exec;
    so.progress = o.progress;
    const SpeedTable speed = measureSpeed((out / "images").string(), so);
    io::writeTextAtomic((out / "data" / "speed.json").string(), speedJson(speed));
    io::writeTextAtomic((out / "data" / "speed.md").string(), speedMarkdown(speed));
    all["speed"] = nlohmann::ordered_json::parse(speedJson(speed));

    // 6. Kernel experiment, aliased (the PPAA case) and with 4x4 coverage (for contrast).
    say("report: kernel experiment");
    KernelExperimentOptions ko;
    if (o.quick) ko.stepDegrees = 2;
    const KernelExperiment kernels = runKernelExperiment(ko);
    ko.supersample = 4;
    const KernelExperiment kernelsAa = runKernelExperiment(ko);
    io::writeTextAtomic((out / "data" / "kernels.json").string(), kernelJson(kernels));
    io::writeTextAtomic((out / "data" / "kernels_supersampled.json").string(), kernelJson(kernelsAa));
    all["kernels"] = nlohmann::ordered_json::parse(kernelJson(kernels));

    // 7. Charts.
    say("report: charts");
    {
        std::vector<Series> ps, ss;
        for (std::size_t m = 0; m < quality.methods.size(); ++m) {
            Series p{quality.methods[m], {}}, s{quality.methods[m], {}};
            for (std::size_t i = 0; i < quality.images.size(); ++i) {
                p.values.push_back(quality.psnr[i][m]);
                s.values.push_back(quality.ssim[i][m]);
            }
            ps.push_back(p);
            ss.push_back(s);
        }
        io::writePng((out / "plots" / "psnr.png").string(),
                     groupedBarChart(quality.images, ps, {880, 400, "PSNR per image and method (higher is better)",
                                                          "", "PSNR (dB)", false, false})
                         .view());
        io::writePng((out / "plots" / "ssim.png").string(),
                     groupedBarChart(quality.images, ss,
                                     {880, 400, "SSIM per image and method (8x8 windows)", "", "SSIM", false, false})
                         .view());
        std::vector<Series> sp;
        for (std::size_t m = 0; m < speed.methods.size(); ++m) {
            Series s{speed.methods[m], {}};
            for (std::size_t i = 0; i < speed.images.size(); ++i) s.values.push_back(speed.results[i][m].relative);
            sp.push_back(s);
        }
        io::writePng((out / "plots" / "speed.png").string(),
                     groupedBarChart(speed.images, sp,
                                     {880, 400, "Time relative to blur = 100 (log scale, lower is faster)", "",
                                      "% of blur", true, true})
                         .view());
        Series fl{"flicker", {}};
        std::vector<std::string> ids;
        for (const auto& r : temporal.results) fl.values.push_back(r.flickerLevels), ids.push_back(r.method);
        std::vector<Series> flv;
        for (std::size_t m = 0; m < ids.size(); ++m) {
            Series s{ids[m], std::vector<double>{fl.values[m]}};
            flv.push_back(s);
        }
        io::writePng((out / "plots" / "flicker.png").string(),
                     groupedBarChart({std::string(anim.name)}, flv,
                                     {880, 360, "Flicker: RMS error of frame-to-frame differences (lower is steadier)",
                                      "", "8-bit levels", false, true})
                         .view());
        std::vector<Series> ks;
        for (std::size_t k = 0; k < kernels.kernels.size(); ++k) ks.push_back({kernels.kernels[k], kernels.errorAt[k]});
        io::writePng((out / "plots" / "kernels.png").string(),
                     lineChart(kernels.angles, ks,
                               {880, 400, "Angle error on aliased lines (mean over widths 1, 2, 4 px)",
                                "line angle (degrees)", "error (degrees)", false, true})
                         .view());
    }

    // 7b. Ambient obscurance: the SAO paper's experiments on analytic scenes.
    std::string aoSection;
    if (o.ambientObscurance) {
        AoExperimentOptions ao;
        ao.outDir = (out / "ao").string();
        ao.quick = o.quick;
        ao.exec = o.exec;
        ao.progress = o.progress;
        ao.renderedScenes = o.renderedScenes;
        const std::string md = runAoExperiments(ao);
        aoSection = "<h2>Ambient obscurance (the SAO paper's experiments)</h2>\n<p class=\"note\">Scalable Ambient "
                    "Obscurance (<a href=\"methods/sao.html\">doc</a>), the AlchemyAO baseline (<a "
                    "href=\"methods/alchemy.html\">doc</a>) and ray-traced ground truth (<a "
                    "href=\"methods/raytraced.html\">doc</a>) on analytic scenes rendered by exact ray casting "
                    "and, in the accuracy table, on scenes rasterised by the Vulkan renderer (D32F depth) with "
                    "Embree ray tracing their triangles for the truth. Data: <a href=\"ao/data/ao.json\">ao/data/ao.json</a>."
                    "</p>\n";
        aoSection += markdownToHtml(md);
        aoSection += "<div class=\"anims\">\n";
        for (const char* name : {"raytraced", "sao_rotated_grid", "sao_no_pyramid", "alchemy", "sao_min_diff",
                                 "sao_max_diff"})
            aoSection += fmt::format("<figure><img class=\"aoimg\" src=\"ao/images/ao_room_{0}.png\" alt=\"room "
                                     "{0}\"><figcaption>room: {0}</figcaption></figure>\n",
                                     name);
        aoSection += "</div>\n<div class=\"anims\">\n";
        if (fs::exists(out / "ao" / "images" / "ao_atrium_raytraced.png"))
            for (const char* name : {"raytraced", "sao_rotated_grid", "alchemy"})
                aoSection += fmt::format("<figure><img class=\"aoimg\" src=\"ao/images/ao_atrium_{0}.png\" alt=\"atrium "
                                         "{0}\"><figcaption>atrium (Vulkan): {0}</figcaption></figure>\n",
                                         name);
        // The paper's configuration beside the released shaders' (sao.md "released").
        aoSection += "</div>\n<div class=\"anims\">\n";
        for (const char* scene : {"room", "atrium"})
            for (const char* name : {"paper", "released", "released_blur"})
                if (fs::exists(out / "ao" / "images" / fmt::format("ao_{}_{}.png", scene, name)))
                    aoSection += fmt::format("<figure><img class=\"aoimg\" src=\"ao/images/ao_{0}_{1}.png\" alt=\"{0} "
                                             "{1}\"><figcaption>{0}: {1}</figcaption></figure>\n",
                                             scene, name);
        aoSection += "</div>\n<img class=\"plot\" width=\"880\" height=\"420\" src=\"ao/plots/ao_radius_scaling.png\" "
                     "alt=\"AO time vs radius\">\n<img class=\"plot\" width=\"880\" height=\"420\" "
                     "src=\"ao/plots/ao_z_precision.png\" alt=\"z precision\">\n";
    }

    // 7c. Adaptive supersampling for deferred shading (the caller runs it: it needs the renderer).
    std::string deferredSection;
    if (o.deferredExperiment) {
        const std::string md = o.deferredExperiment((out / "deferred").string());
        deferredSection = "<h2>Adaptive supersampling for deferred shading (the paper's Table 1)</h2>\n<p class=\"note\">"
                          "The method (<a href=\"methods/adaptive.html\">doc</a>) against brute-force supersampling "
                          "on the atrium's G-buffer from the Vulkan renderer. Images at 4x4: the reference, ours, the "
                          "per-pixel sample count (blue 1 .. red 16), the absolute error (0 .. 0.05) and each "
                          "metric's k (paper Figure 8). Data: <a href=\"deferred/data/deferred.json\">"
                          "deferred/data/deferred.json</a>.</p>\n";
        deferredSection += markdownToHtml(md);
        deferredSection += "<div class=\"anims\">\n";
        for (const char* name : {"reference", "ours", "samples", "error", "k_depth", "k_normal", "k_shading"})
            deferredSection += fmt::format("<figure><img class=\"aoimg\" src=\"deferred/images/deferred_m4_{0}.png\" "
                                           "alt=\"4x4 {0}\"><figcaption>4x4: {0}</figcaption></figure>\n",
                                           name);
        deferredSection += "</div>\n";
    }

    // 8. Method docs.
    for (const auto& [id, text] : detail::methodDocs()) {
        io::writeTextAtomic((out / "methods" / (std::string(id) + ".html")).string(),
                  fmt::format("<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>ssfx: {0}</title>"
                              "<style>{1}</style></head><body><p><a href=\"../index.html\">back to the report</a></p>"
                              "<pre class=\"doc\">{2}</pre></body></html>\n",
                              esc(id), detail::kReportCss, esc(text)));
    }
    io::writeTextAtomic((out / "data" / "all.json").string(), all.dump(1) + "\n");

    // 9. The page.
    say("report: index.html");
    const MachineInfo& mi = speed.machine;
    std::string h = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
        "<title>ssfx evaluation report</title><link rel=\"icon\" href=\"data:,\"><style>{}</style></head><body>\n",
        detail::kReportCss);
    h += "<h1>ssfx: post-processing anti-aliasing, evaluated</h1>\n<p class=\"note\">The DDAA paper's evaluation "
         "(spec <code>ppaa.md</code> section 3) on ssfx's own test images, drawn with Cairo without antialiasing at 1x, "
         "2x, 4x and 8x. Every number on this page was computed by the run that wrote it; the data is in "
         "<a href=\"data/all.json\">data/all.json</a>.</p>\n";
    h += "<h2>Methods</h2>\n<dl class=\"methods\">\n";
    for (const auto& id : methodIds) h += methodNote(methodById(id));
    h += "</dl>\n";

    h += "<h2>Quality (the paper's Table 2 protocol)</h2>\n<p class=\"note\">Each method's 1x output (ssaax2 and "
         "ddaa2p from the x2 render, ssaax4 from the x4 render) is upscaled x8 with the Mitchell filter and compared "
         "with the x8 render. PSNR over RGB in [0,1]; SSIM on non-overlapping 8x8 windows (one window per 1x pixel). "
         "Best per row in bold. <code>noaa</code> is the aliased input itself.</p>\n";
    h += "<h3>PSNR (dB)</h3>\n" + htmlTable(rowsWithMean(quality.images), quality.methods, withMean(quality, true), 3, true);
    h += "<img class=\"plot\" width=\"880\" height=\"400\" src=\"plots/psnr.png\" alt=\"PSNR per image and method\">\n";
    h += "<h3>SSIM</h3>\n" + htmlTable(rowsWithMean(quality.images), quality.methods, withMean(quality, false), 4, true);
    h += "<img class=\"plot\" width=\"880\" height=\"400\" src=\"plots/ssim.png\" alt=\"SSIM per image and method\">\n";
    h += reproduction;
    h += colourSection;

    h += "<h2>Compare the outputs</h2>\n<p class=\"note\">Pick one or more methods; <em>side by side</em> shows them "
         "together, <em>flip</em> shows one at a time (button <em>next</em> or key <kbd>f</kbd>, or auto-flip). Zoom "
         "is nearest-neighbour; drag or scroll to pan (all panes move together). <code>reference</code> is the x8 "
         "render resolved to 1x with the Mitchell filter.</p>\n";
    for (const auto& name : quality.images) {
        std::string description;
        int width = 0, height = 0;
        if (auto e = extraSets.find(name); e != extraSets.end()) {
            description = e->second;
            const ImageRgba8 img = io::readPng((out / "images" / (name + ".png")).string());
            width = img.width();
            height = img.height();
        } else {
            const TestImageInfo& info = testImageByName(name);
            description = info.description;
            width = info.width;
            height = info.height;
        }
        std::vector<std::pair<std::string, std::string>> src{{"reference", "images/" + name + "_reference.png"}};
        for (const auto& id : methodIds) src.emplace_back(id, fmt::format("images/{}_{}.png", name, id));
        h += fmt::format("<h3>{}</h3><p class=\"note\">{}</p>\n", esc(name), esc(description));
        h += viewer(name, width, height, src, {"noaa", "ddaa2"});
    }

    h += "<h2>Temporal stability</h2>\n<p class=\"note\">Each method applied to every frame of <code>animated</code>"
         " (" + std::to_string(frames) + " frames" + (o.quick ? ", every 4th frame" : "") +
         "); the reference is the x8 animation resolved to 1x. Flicker is the RMS error of the method's "
         "frame-to-frame differences against the reference's (around the loop), in 8-bit levels; tPSNR is the same "
         "as a PSNR; PSNR compares each frame with the reference frame (docs/evaluation.md).</p>\n";
    {
        std::vector<std::vector<double>> rows;
        std::vector<std::string> names;
        for (const auto& r : temporal.results) {
            names.push_back(r.method);
            rows.push_back({r.flickerLevels, r.temporalPsnr, r.psnr});
        }
        h += htmlTable(names, {"flicker (levels)", "tPSNR (dB)", "PSNR (dB)"}, rows, 3, false, "method");
    }
    h += temporalReference;
    h += "<img class=\"plot\" width=\"880\" height=\"360\" src=\"plots/flicker.png\" alt=\"flicker per method\">\n<div class=\"anims\">\n";
    h += "<figure><img src=\"anim/animated_reference.png\" alt=\"reference animation\"><figcaption>reference (x8 "
         "resolved)</figcaption></figure>\n";
    for (const auto& r : temporal.results)
        h += fmt::format("<figure><img src=\"anim/animated_{0}.png\" alt=\"{0} animation\"><figcaption>{0}: flicker "
                         "{1:.2f}</figcaption></figure>\n",
                         esc(r.method), r.flickerLevels);
    h += "</div>\n<h3>Animation, zoomable</h3>\n";
    {
        std::vector<std::pair<std::string, std::string>> src{{"reference", "anim/animated_reference.png"}};
        for (const auto& id : methodIds) src.emplace_back(id, fmt::format("anim/animated_{}.png", id));
        h += viewer("animated", anim.width, anim.height, src, {"noaa", "ddaa2"});
    }

    h += "<h2>Speed (the paper's Table 3 layout)</h2>\n";
    h += fmt::format("<p class=\"note\">Machine: {}, {} of {} threads, SIMD target {}. Each method timed {} times per "
                     "image, interleaved with the others; the fastest and slowest quarter dropped; relative to blur = "
                     "100 from the same run. The paper's GPU figures: fxaa3c 81-105, ddaa1 94-150, fxaa3d 160-352, "
                     "ddaa2 175-255, ssaax2 71-94.</p>\n",
                     esc(mi.cpu), mi.threads, mi.hardwareThreads, esc(mi.simdTarget), speed.repetitions);
    {
        std::vector<std::vector<double>> rel, med;
        for (const auto& row : speed.results) {
            rel.emplace_back();
            med.emplace_back();
            for (const auto& r : row) rel.back().push_back(r.relative), med.back().push_back(r.medianMs);
        }
        h += "<h3>Relative to blur = 100</h3>\n" + htmlTable(speed.images, speed.methods, rel, 0, false);
        h += "<h3>Median (ms)</h3>\n" + htmlTable(speed.images, speed.methods, med, 3, false);
    }
    h += "<img class=\"plot\" width=\"880\" height=\"400\" src=\"plots/speed.png\" alt=\"speed relative to blur\">\n";

    h += "<h2>Kernel experiment (the paper's Figure 3)</h2>\n<p class=\"note\">Angle of aliased lines (widths 1, 2 "
         "and 4 px, 0 to 90 degrees) estimated from the gradient at the pixels a PPAA method processes; error in "
         "degrees (docs/evaluation.md). Right column: the same lines with 4x4 coverage (antialiased) for "
         "contrast.</p>\n";
    {
        std::vector<std::vector<double>> rows;
        for (std::size_t k = 0; k < kernels.kernels.size(); ++k)
            rows.push_back({kernels.meanError[k], kernels.maxError[k], kernelsAa.meanError[k]});
        h += htmlTable(kernels.kernels, {"mean error, aliased", "max per-angle mean, aliased", "mean error, 4x4 coverage"},
                       rows, 3, false, "kernel");
    }
    h += "<img class=\"plot\" width=\"880\" height=\"400\" src=\"plots/kernels.png\" alt=\"angle error per kernel\">\n";
    h += aoSection;
    h += deferredSection;
    h += fmt::format("<p class=\"note\">Written by ssfx 0.1.0. Tables as Markdown: <a href=\"data/quality.md\">quality"
                     "</a>, <a href=\"data/temporal.md\">temporal</a>, <a href=\"data/speed.md\">speed</a>.</p>\n");
    h += "<script>" + std::string(detail::kReportJs) + "</script>\n</body></html>\n";
    io::writeTextAtomic((out / "index.html").string(), h);
}

}  // namespace ssfx::eval
