// ssfx aa: apply an anti-aliasing method to a PNG (or every frame of an APNG).
#include <fmt/format.h>

#include <cstdio>

#include <charconv>

#include "apps/ssfx/commands.hpp"
#include "ssfx/aa/presets.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/registry.hpp"

namespace ssfx::cli {

std::pair<int, int> parseSize(const std::string& text, const std::string& option, int maxSide) {
    // WIDTHxHEIGHT, each a whole number in 1..maxSide: no sign, no overflow (4294967360x36
    // is refused, not read as 64x36).
    const auto bad = [&] {
        return Error(fmt::format("{} '{}' is not WIDTHxHEIGHT (1..{} each)", option, text, maxSide));
    };
    const auto x = text.find('x');
    if (x == std::string::npos) throw bad();
    auto side = [&](std::string_view s) {
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || s[0] == '-' || ec != std::errc() || end != s.data() + s.size() || v < 1 || v > maxSide)
            throw bad();
        return int(v);
    };
    const std::string_view t(text);
    return {side(t.substr(0, x)), side(t.substr(x + 1))};
}

std::pair<std::string, double> parseParam(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(fmt::format("parameter '{}' is not of the form NAME=VALUE", text));
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    if (value == "true") return {name, 1.0};
    if (value == "false") return {name, 0.0};
    double v = 0;
    // An explicit plus sign is a number too (from_chars takes only '-').
    const std::size_t skip = value.size() > 1 && value[0] == '+' && value[1] != '-' && value[1] != '+' ? 1 : 0;
    const auto [end, ec] = std::from_chars(value.data() + skip, value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size())
        throw Error(fmt::format("parameter {}: '{}' is not a number", name, value));
    return {name, v};
}

std::pair<std::string, double> parseParam(const std::string& text, std::span<const ParamInfo> table,
                                          std::string_view id) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(fmt::format("parameter '{}' is not of the form NAME=VALUE", text));
    const std::string name = text.substr(0, eq);
    return {name, parseParamValue(findParam(table, id, name), std::string_view(text).substr(eq + 1), id)};
}

namespace {

struct AaOptions {
    std::string method, input, output, preset, filtering = "gpu";
    std::vector<std::string> params;
    int threads = 0;
    bool listPresets = false;
};

void printPresets() {
    fmt::print(
        "Edge-threshold presets of fxaa3c, fxaa3d, ddaa1, ddaa2, ddaa2p: a pixel is left unchanged\n"
        "when its luma contrast < max(edgeThresholdMin, lumaMax * edgeThreshold).\n\n");
    fmt::print("{:<8} {:>16} {:>14}  {}\n", "preset", "edgeThresholdMin", "edgeThreshold", "");
    for (const auto& p : aa::kPresets)
        fmt::print("{:<8} {:>16} {:>14}  {}\n", p.name, p.thresholds.edgeThresholdMin, p.thresholds.edgeThreshold,
                   p.doc);
}

void run(const AaOptions& o) {
    if (o.listPresets) {
        printPresets();
        return;
    }
    if (o.method.empty()) throw Error("no method given (use -m METHOD; 'ssfx methods' lists them)");
    if (o.input.empty()) throw Error("no input file given");
    if (o.output.empty()) throw Error("no output file given (use -o FILE)");
    const MethodInfo& m = methodById(o.method);
    MethodSettings settings;
    if (!o.preset.empty()) {
        settings.preset = aa::parsePreset(o.preset);
        if (!settings.preset)
            throw Error(fmt::format("unknown preset '{}' (presets: low, medium, high, ultra, extreme)", o.preset));
    }
    for (const auto& p : o.params) settings.params.push_back(parseParam(p, methodById(o.method).params, o.method));
    if (o.filtering == "exact") settings.filtering = Filtering::Exact;
    const Exec exec{o.threads};

    const std::vector<std::uint8_t> bytes = io::readFile(o.input, io::kMaxImageFileBytes, "PNG", io::kPngMagic);
    if (io::isApng(bytes)) {
        io::Animation anim = io::decodeApng(bytes, o.input);
        for (std::size_t i = 0; i < anim.frames.size(); ++i) try {
                anim.frames[i].image = m.run(anim.frames[i].image.view(), settings, exec);
            } catch (const Error& e) {  // e.g. a resolve's size rule: say which file and frame
                throw Error(fmt::format("{} (frame {}): {}", o.input, i, e.what()));
            }
        io::writeApng(o.output, anim);
    } else {
        const ImageRgba8 in = io::decodePng(bytes, o.input);
        ImageRgba8 out;
        try {
            out = m.run(in.view(), settings, exec);
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}", o.input, e.what()));
        }
        io::writePng(o.output, out.view());
    }
}

}  // namespace

void addAaCommand(CLI::App& app) {
    auto opts = std::make_shared<AaOptions>();
    auto* cmd = app.add_subcommand(
        "aa", "Apply an anti-aliasing method to a PNG, or to every frame of an APNG (output is then APNG)");
    std::string methodList;
    for (const MethodInfo& mi : methods()) methodList += fmt::format("\n  {:<7} {}", mi.id, mi.summary);
    cmd->add_option("-m,--method", opts->method, "Method id:" + methodList);
    cmd->add_option("input", opts->input, "Input PNG/APNG (ssaax2/ddaa2p take the 2x render, ssaax4 the 4x)");
    cmd->add_option("-o,--output", opts->output, "Output PNG/APNG (written atomically)");
    cmd->add_option("--preset", opts->preset, "Edge-threshold preset: low, medium (default), high, ultra, extreme");
    cmd->add_option("-p,--param", opts->params, "Parameter override NAME=VALUE (repeatable; see 'ssfx methods')")
        ->allow_extra_args(false);
    cmd->add_option("--filtering", opts->filtering, "Bilinear model: gpu (default, matches GPUs) or exact (float)")
        ->check(CLI::IsMember({"gpu", "exact"}));
    cmd->add_option("--threads", opts->threads, "Worker threads (0 = all; the output bytes do not depend on it)")
        ->check(CLI::Range(0, 1024));
    cmd->add_flag("--list-presets", opts->listPresets, "Print the presets with their thresholds and exit");
    cmd->callback([opts] { run(*opts); });
}

}  // namespace ssfx::cli
