// The AO registry (registry.hpp). Adding an AO method: its params struct and table, its
// source, one row here, docs/methods/<id>.md, tests; the CLI, `ssfx methods` and the
// property tests pick it up from this table.
#include "ssfx/ao/registry.hpp"

#include <fmt/format.h>

#include <array>

#include "ssfx/core/error.hpp"

namespace ssfx::ao {

namespace {

template <class P>
const P& as(const AoParams& p, std::string_view id) {
    if (const P* v = std::get_if<P>(&p)) return *v;
    throw Error(fmt::format("{}: the parameters are another method's", id));
}

void noPreset(std::string_view id, std::string_view preset) {
    if (!preset.empty()) throw Error(fmt::format("{}: no presets (preset '{}')", id, preset));
}

constexpr std::array<std::string_view, 2> kSaoPresets{"paper", "released"};
constexpr std::string_view kDepthInput = "a depth buffer in [0, 1] and its camera (a guard band around the output)";

struct Text {
    std::string_view id, summary, citation, inputs;
};
AoMethodInfo entry(Text t, std::span<const ParamInfo> params, std::span<const std::string_view> presets, bool geometry,
                   bool normals, AoParams (*defaults)(std::string_view), void (*check)(const AoParams&),
                   ImageF (*run)(const AoInput&, const AoParams&, const Exec&)) {
    AoMethodInfo m{};
    m.id = t.id, m.family = "ao", m.summary = t.summary, m.citation = t.citation, m.inputs = t.inputs;
    m.params = params, m.presets = presets, m.backends = kCpuBackend;
    m.needsGeometry = geometry, m.takesNormals = normals, m.defaults = defaults, m.validate = check, m.run = run;
    return m;
}

const std::array<AoMethodInfo, 4> kAoMethods{{
    entry(
        {"sao", "Scalable Ambient Obscurance: z pyramid, spiral taps, bilateral reconstruction",
         "McGuire, Mara, Luebke, Scalable Ambient Obscurance, HPG 2012", kDepthInput},
        kSaoParams, kSaoPresets, false, false,
        [](std::string_view preset) -> AoParams {
            return preset.empty() ? SaoParams{} : saoPreset(std::string(preset));
        },
        [](const AoParams& p) { validate(as<SaoParams>(p, "sao")); },
        [](const AoInput& in, const AoParams& p, const Exec& e) {
            return sao(in.depth, in.camera, as<SaoParams>(p, "sao"), e);
        }),
    entry(
        {"alchemy", "AlchemyAO, the baseline SAO improves on: 12 taps at level 0, the same reconstruction",
         "McGuire et al., The Alchemy Screen-Space Ambient Obscurance Algorithm, HPG 2011; SAO paper section 3",
         kDepthInput},
        kAlchemyParams, {}, false, false,
        [](std::string_view preset) -> AoParams {
            noPreset("alchemy", preset);
            return AlchemyParams{};
        },
        [](const AoParams& p) { validate(as<AlchemyParams>(p, "alchemy")); },
        [](const AoInput& in, const AoParams& p, const Exec& e) {
            return alchemy(in.depth, in.camera, as<AlchemyParams>(p, "alchemy"), e);
        }),
    entry(
        {"gtao",
         "Ground-Truth AO (XeGTAO's form): slices of horizon search through a depth chain, cosine-weighted "
         "visible fraction, edge-aware denoiser",
         "Jimenez, Wu, Pesce, Jarabo, Practical Realtime Strategies for Accurate Indirect Occlusion, SIGGRAPH 2016 "
         "course; Intel XeGTAO",
         "a depth buffer in [0, 1] and its camera (a guard band around the output); optionally camera-space normals"},
        kGtaoParams, kGtaoPresets, false, true,
        [](std::string_view preset) -> AoParams {
            return preset.empty() ? GtaoParams{} : gtaoPreset(std::string(preset));
        },
        [](const AoParams& p) { validate(as<GtaoParams>(p, "gtao")); },
        [](const AoInput& in, const AoParams& p, const Exec& e) {
            return gtao(in.depth, in.camera, as<GtaoParams>(p, "gtao"), e, GtaoBuffers{in.normals, nullptr});
        }),
    entry(
        {"raytraced", "ground truth: cosine-weighted rays against the scene's geometry, SAO's falloff radius",
         "SAO paper section 3 (the ray-traced comparison)", "the scene's geometry and the camera of a depth buffer"},
        kRaytracedParams, {}, true, false,
        [](std::string_view preset) -> AoParams {
            noPreset("raytraced", preset);
            return RaytracedParams{};
        },
        [](const AoParams& p) { validate(as<RaytracedParams>(p, "raytraced")); },
        [](const AoInput& in, const AoParams& p, const Exec& e) {
            if (!in.geometry) throw Error("raytraced needs the scene's geometry (a depth buffer is not enough)");
            return raytraced(*in.geometry, in.camera, in.depth.width(), in.depth.height(),
                             as<RaytracedParams>(p, "raytraced"), e, in.progress);
        }),
}};

}  // namespace

std::span<const AoMethodInfo> aoMethods() { return kAoMethods; }

const AoMethodInfo& aoMethodById(std::string_view id) {
    for (const AoMethodInfo& m : kAoMethods)
        if (m.id == id) return m;
    throw Error(fmt::format("unknown AO method '{}' ({})", id, idList(aoMethods())));
}

void setParam(const AoMethodInfo& method, AoParams& params, std::string_view name, double value) {
    if (method.defaults("").index() != params.index())
        throw Error(fmt::format("{}: the parameters are another method's", method.id));
    ssfx::setParam(method.params, paramsData(params), method.id, name, value);
}

int guardBandOf(const AoParams& params) {
    return std::visit([](const auto& p) { return p.guardBand; }, params);
}

}  // namespace ssfx::ao
