// ssfx eval: the evaluation harness (ssfx/eval/*.hpp). Subcommands:
//   quality   the paper's PSNR protocol (Table 2) plus SSIM, on a directory of renders
// Long runs print progress on stderr.
#include <fmt/format.h>

#include <filesystem>

#include "commands.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::cli {

namespace {

void writeText(const std::string& path, const std::string& text) {
    io::writeFileAtomic(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void progressLine(const std::string& s) { std::fprintf(stderr, "eval: %s\n", s.c_str()); }

void addQuality(CLI::App& eval) {
    struct Options {
        std::string dir, json, markdown, source = "compute", outputs;
        std::vector<std::string> methods, images;
        int threads = 0;
    };
    auto o = std::make_shared<Options>();
    auto* cmd = eval.add_subcommand("quality", "PSNR and SSIM of every method against the x8 render (paper's Table 2)");
    cmd->add_option("dir", o->dir, "Directory with NAME.png, NAMEx2/x4/x8.png (e.g. from 'ssfx testimages')")
        ->required();
    cmd->add_option("--json", o->json, "Also write the tables as JSON");
    cmd->add_option("--md", o->markdown, "Also write the tables as Markdown");
    cmd->add_option("--source", o->source,
                    "compute: run each method on the renders; given: score the NAME_METHOD.png files in DIR")
        ->check(CLI::IsMember({"compute", "given"}));
    cmd->add_option("--outputs", o->outputs, "With --source compute: also write NAME_METHOD.png to this directory");
    cmd->add_option("--methods", o->methods, "Method columns (default: ssaax4,ssaax2,blur,fxaa3c,fxaa3d,ddaa1,ddaa2,"
                                             "ddaa2p,noaa)")
        ->delimiter(',');
    cmd->add_option("--images", o->images, "Image rows (default: every NAME with NAMEx8.png in DIR)")->delimiter(',');
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->footer("Each method's 1x output (x2 render for ssaax2/ddaa2p, x4 for ssaax4) is upscaled x8 with the\n"
                "Mitchell filter and compared with NAMEx8.png: PSNR = 10 log10(1 / MSE) over RGB in [0,1];\n"
                "SSIM on non-overlapping 8x8 windows (docs/evaluation.md).");
    cmd->callback([o] {
        eval::QualityOptions q;
        q.methods = o->methods;
        q.images = o->images;
        q.source = o->source == "given" ? eval::OutputSource::Given : eval::OutputSource::Compute;
        q.outputsDir = o->outputs;
        if (!q.outputsDir.empty()) std::filesystem::create_directories(q.outputsDir);
        q.exec = Exec{o->threads};
        q.progress = progressLine;
        const eval::QualityTable t = eval::evaluateQuality(o->dir, q);
        fmt::print("{}", eval::qualityText(t));
        if (!o->json.empty()) writeText(o->json, eval::qualityJson(t));
        if (!o->markdown.empty()) writeText(o->markdown, eval::qualityMarkdown(t));
    });
}

}  // namespace

void addEvalCommand(CLI::App& app) {
    auto* eval = app.add_subcommand("eval", "Evaluation harness: quality, temporal stability, speed, kernels, report");
    eval->require_subcommand(1);
    addQuality(*eval);
}

}  // namespace ssfx::cli
