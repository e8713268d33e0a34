// The one explicit table of methods (STYLE.md section 2). Adding a method: header, source,
// registry line here, doc note in docs/methods/<id>.md, unit test, golden, bench entry; the
// property tests and the CLI pick it up from this table.
#include "ssfx/aa/registry.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/resolve.hpp"

namespace ssfx {

namespace {

using namespace aa;

// A preset's params (or the defaults), then the named overrides through the method's table.
template <class P, std::size_t N>
P applySettings(std::string_view id, P params, const std::array<ParamInfo, N>& table, const MethodSettings& s) {
    for (const auto& [name, value] : s.params) setParam(table, &params, id, name, value);
    return params;
}

void rejectParams(std::string_view id, const MethodSettings& s) {
    if (!s.params.empty())
        throw Error(fmt::format("{}: unknown parameter '{}' (this method has none)", id, s.params[0].first));
}

void rejectPreset(std::string_view id, const MethodSettings& s) {
    if (s.preset) throw Error(fmt::format("{}: this method has no edge-threshold presets", id));
}

template <class P>
P withFiltering(P p, const MethodSettings& s) {
    p.filtering = s.filtering;
    return p;
}

// ---- run adapters: each method's `into` function; `run` allocates and calls it -----
template <RunIntoFn Into, int Scale>
ImageRgba8 allocating(ImageView<const Rgba8> in, const MethodSettings& s, const Exec& e) {
    checkDimensions(in.width(), in.height(), "input");
    if (in.width() % Scale != 0 || in.height() % Scale != 0)
        throw Error(fmt::format("input size {}x{} is not divisible by {} (the method takes the {}x render)", in.width(),
                                in.height(), Scale, Scale));
    ImageRgba8 out(in.width() / Scale, in.height() / Scale);
    Into(in, out.view(), s, e);
    return out;
}

void intoNoaa(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec&) {
    rejectPreset("noaa", s);
    rejectParams("noaa", s);
    checkDimensions(in.width(), in.height(), "noaa input");
    if (out.width() != in.width() || out.height() != in.height())
        throw Error(
            fmt::format("noaa: output is {}x{}, expected {}x{}", out.width(), out.height(), in.width(), in.height()));
    for (int y = 0; y < in.height(); ++y) std::copy(in.row(y), in.row(y) + in.width(), out.row(y));
}

BlurParams blurParams(const MethodSettings& s) {
    rejectPreset("blur", s);
    return applySettings("blur", BlurParams{}, kBlurParams, s);
}
void intoBlur(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    blur(in, out, blurParams(s), e);
}
ImageRgba8 refBlur(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return blurReference(in, blurParams(s));
}

Fxaa3cParams fxaa3cParams(const MethodSettings& s) {
    return applySettings("fxaa3c", withFiltering(fxaa3cParamsFor(s.preset.value_or(Preset::Medium)), s), kFxaa3cParams,
                         s);
}
void intoFxaa3c(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    fxaa3c(in, out, fxaa3cParams(s), e);
}
ImageRgba8 refFxaa3c(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return fxaa3cReference(in, fxaa3cParams(s));
}

Fxaa3dParams fxaa3dParams(const MethodSettings& s) {
    return applySettings("fxaa3d", withFiltering(fxaa3dParamsFor(s.preset.value_or(Preset::Medium)), s), kFxaa3dParams,
                         s);
}
void intoFxaa3d(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    fxaa3d(in, out, fxaa3dParams(s), e);
}
ImageRgba8 refFxaa3d(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return fxaa3dReference(in, fxaa3dParams(s));
}

Ddaa1Params ddaa1Params(const MethodSettings& s) {
    return applySettings("ddaa1", withFiltering(ddaa1ParamsFor(s.preset.value_or(Preset::Medium)), s), kDdaa1Params, s);
}
void intoDdaa1(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    ddaa1(in, out, ddaa1Params(s), e);
}
ImageRgba8 refDdaa1(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return ddaa1Reference(in, ddaa1Params(s));
}

Ddaa2Params ddaa2Params(std::string_view id, const MethodSettings& s) {
    return applySettings(id, withFiltering(ddaa2ParamsFor(s.preset.value_or(Preset::Medium)), s), kDdaa2Params, s);
}
void intoDdaa2(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    ddaa2(in, out, ddaa2Params("ddaa2", s), e);
}
ImageRgba8 refDdaa2(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return ddaa2Reference(in, ddaa2Params("ddaa2", s));
}
void intoDdaa2p(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    ddaa2p(in, out, ddaa2Params("ddaa2p", s), e);
}
// The resolves have no SIMD variant yet: their fast path is the threaded scalar code.
ImageRgba8 refDdaa2p(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    const ImageRgba8 aa = ddaa2Reference(in, ddaa2Params("ddaa2p", s));
    return ssaax2(aa.view(), s.filtering, Exec{1}, ddaa2Params("ddaa2p", s).texture);
}

void intoSsaax2(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    rejectPreset("ssaax2", s);
    ssaax2(in, out, s.filtering, e, applySettings("ssaax2", Ssaax2Params{}, kSsaax2Params, s).texture);
}
ImageRgba8 refSsaax2(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return allocating<intoSsaax2, 2>(in, s, Exec{1});
}
MitchellParams mitchellParams(const MethodSettings& s) {
    rejectPreset("ssaax4", s);
    return applySettings("ssaax4", MitchellParams{}, kMitchellParams, s);
}
void intoSsaax4(ImageView<const Rgba8> in, ImageView<Rgba8> out, const MethodSettings& s, const Exec& e) {
    ssaax4(in, out, mitchellParams(s), e);
}
ImageRgba8 refSsaax4(ImageView<const Rgba8> in, const MethodSettings& s, const Exec&) {
    return allocating<intoSsaax4, 4>(in, s, Exec{1});
}

constexpr std::string_view kDdaaCite = "A. Klein, Directional Diffusion Anti-Aliasing (DDAA), JCGT";
constexpr std::string_view kFxaaCite = "T. Lottes, FXAA 3.11, NVIDIA 2011 (as compared in the DDAA paper)";
constexpr std::string_view kMitchellCite = "Mitchell & Netravali, SIGGRAPH 1988; DDAA paper section 3";

// The preset names of the threshold methods, "medium" (the default) first.
constexpr std::array<std::string_view, 5> kThresholdPresets{"medium", "low", "high", "ultra", "extreme"};
constexpr std::string_view kImage = "an RGBA8 image";
constexpr std::string_view kImage2x = "an RGBA8 image: the scene rendered at 2x";
constexpr std::string_view kImage4x = "an RGBA8 image: the scene rendered at 4x";

struct Text {
    std::string_view id, summary, citation, inputs;
};
MethodInfo entry(Text t, std::span<const ParamInfo> params, std::string_view kind, bool presets, int scale, RunFn run,
                 RunIntoFn into, RunFn ref) {
    MethodInfo m{};
    m.id = t.id, m.family = "aa", m.summary = t.summary, m.citation = t.citation, m.inputs = t.inputs;
    m.params = params;
    if (presets) m.presets = kThresholdPresets;
#ifdef SSFX_HAVE_GPU
    m.backends = kCpuVulkanBackends;  // every aa method has a GPU pass (ssfx/gpu/aa.hpp)
#else
    m.backends = kCpuBackend;
#endif
    m.kind = kind, m.usesPresets = presets, m.inputScale = scale, m.run = run, m.runInto = into, m.reference = ref;
    return m;
}

const std::array<MethodInfo, 9> kMethods{{
    entry({"noaa", "no anti-aliasing: the input unchanged", "", kImage}, {}, "ppaa", false, 1, allocating<intoNoaa, 1>,
          intoNoaa, allocating<intoNoaa, 1>),
    entry({"blur", "3x3 truncated Gaussian (sigma 0.6), the quality and speed baseline", "DDAA paper section 3.1",
           kImage},
          kBlurParams, "ppaa", false, 1, allocating<intoBlur, 1>, intoBlur, refBlur),
    entry({"fxaa3c", "FXAA 3.11 console: direction from the diagonals, 4 taps, no edge search", kFxaaCite, kImage},
          kFxaa3cParams, "ppaa", true, 1, allocating<intoFxaa3c, 1>, intoFxaa3c, refFxaa3c),
    entry({"fxaa3d", "FXAA 3.11 desktop: 12-step edge search with pixel skipping", kFxaaCite, kImage}, kFxaa3dParams,
          "ppaa", true, 1, allocating<intoFxaa3d, 1>, intoFxaa3d, refFxaa3d),
    entry({"ddaa1", "DDAA 1: diffusion along the Scharr edge direction, no edge search", kDdaaCite, kImage},
          kDdaa1Params, "ppaa", true, 1, allocating<intoDdaa1, 1>, intoDdaa1, refDdaa1),
    entry({"ddaa2", "DDAA 2: diffusion plus a clean batched edge search (the proposed method)", kDdaaCite, kImage},
          kDdaa2Params, "ppaa", true, 1, allocating<intoDdaa2, 1>, intoDdaa2, refDdaa2),
    entry({"ssaax2", "2x supersampling resolve: Mitchell filter in 12 bilinear reads (input: 2x render)", kMitchellCite,
           kImage2x},
          kSsaax2Params, "resolve", false, 2, allocating<intoSsaax2, 2>, intoSsaax2, refSsaax2),
    entry({"ssaax4", "4x supersampling resolve: direct Mitchell taps (input: 4x render)", kMitchellCite, kImage4x},
          kMitchellParams, "resolve", false, 4, allocating<intoSsaax4, 4>, intoSsaax4, refSsaax4),
    entry({"ddaa2p", "ddaa2 on the 2x render, then the ssaax2 resolve (input: 2x render)", "DDAA paper section 4",
           kImage2x},
          kDdaa2Params, "ppaa", true, 2, allocating<intoDdaa2p, 2>, intoDdaa2p, refDdaa2p),
}};

}  // namespace

AaParams resolveParams(std::string_view id, const MethodSettings& s) {
    const MethodInfo& m = methodById(id);
    if (m.id == "noaa") {
        rejectPreset("noaa", s);
        rejectParams("noaa", s);
        return std::monostate{};
    }
    if (m.id == "blur") return blurParams(s);
    if (m.id == "fxaa3c") return fxaa3cParams(s);
    if (m.id == "fxaa3d") return fxaa3dParams(s);
    if (m.id == "ddaa1") return ddaa1Params(s);
    if (m.id == "ddaa2" || m.id == "ddaa2p") return ddaa2Params(m.id, s);
    if (m.id == "ssaax2") {
        rejectPreset("ssaax2", s);
        return applySettings("ssaax2", Ssaax2Params{}, kSsaax2Params, s);
    }
    return mitchellParams(s);  // ssaax4
}

std::span<const MethodInfo> methods() { return kMethods; }

const MethodInfo* findMethod(std::string_view id) {
    for (const MethodInfo& m : kMethods)
        if (m.id == id) return &m;
    return nullptr;
}

const MethodInfo& methodById(std::string_view id) {
    if (const MethodInfo* m = findMethod(id)) return *m;
    throw Error(fmt::format("unknown method '{}' (methods: {})", id, idList(methods())));
}

}  // namespace ssfx
