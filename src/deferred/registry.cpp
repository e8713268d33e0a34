// The deferred registry (registry.hpp). Adding a method: its params table, its source, one
// row here, docs/methods/<id>.md, tests.
#include "ssfx/deferred/registry.hpp"

#include <fmt/format.h>

#include <array>

#include "ssfx/core/error.hpp"

namespace ssfx::deferred {

namespace {

template <class P>
const P& as(const DeferredParams& p, std::string_view id) {
    if (const P* v = std::get_if<P>(&p)) return *v;
    throw Error(fmt::format("{}: the parameters are another method's", id));
}

struct Text {
    std::string_view id, summary, citation, inputs;
};
DeferredMethodInfo entry(Text t, std::span<const ParamInfo> params, DeferredParams (*defaults)(),
                         void (*check)(const DeferredParams&),
                         DeferredResult (*run)(const scene::Scene&, const scene::GBuffer&, const DeferredParams&,
                                               const Exec&)) {
    DeferredMethodInfo m{};
    m.id = t.id, m.family = "deferred", m.summary = t.summary, m.citation = t.citation, m.inputs = t.inputs;
    m.params = params, m.presets = {}, m.backends = kCpuBackend;
    m.defaults = defaults, m.validate = check, m.run = run;
    return m;
}

constexpr std::string_view kCite =
    "Hollander, Boubekeur, Eisemann, Adaptive Supersampling for Deferred Anti-Aliasing, JCGT 2013";
constexpr std::string_view kInput = "an m x m supersampled G-buffer and its scene (materials, textures, lights)";

const std::array<DeferredMethodInfo, 2> kDeferredMethods{{
    entry(
        {"adaptive", "shade one sample per pixel, then as many more as depth, normal and shading metrics ask", kCite,
         kInput},
        kAdaptiveParams, [] { return DeferredParams{AdaptiveParams{}}; },
        [](const DeferredParams& p) { validate(as<AdaptiveParams>(p, "adaptive")); },
        [](const scene::Scene& s, const scene::GBuffer& g, const DeferredParams& p, const Exec& e) {
            return adaptiveSupersampling(s, g, as<AdaptiveParams>(p, "adaptive"), e);
        }),
    entry(
        {"brute-force", "every G-buffer sample shaded and averaged (brute-force supersampling)", kCite, kInput},
        kShadingParams, [] { return DeferredParams{ShadingParams{}}; },
        [](const DeferredParams& p) { validate(as<ShadingParams>(p, "brute-force")); },
        [](const scene::Scene& s, const scene::GBuffer& g, const DeferredParams& p, const Exec& e) {
            return bruteForceSupersampling(s, g, as<ShadingParams>(p, "brute-force"), e);
        }),
}};

}  // namespace

std::span<const DeferredMethodInfo> deferredMethods() { return kDeferredMethods; }

const DeferredMethodInfo& deferredMethodById(std::string_view id) {
    for (const DeferredMethodInfo& m : kDeferredMethods)
        if (m.id == id) return m;
    throw Error(fmt::format("unknown deferred method '{}' ({})", id, idList(deferredMethods())));
}

void setParam(const DeferredMethodInfo& method, DeferredParams& params, std::string_view name, double value) {
    if (method.defaults().index() != params.index())
        throw Error(fmt::format("{}: the parameters are another method's", method.id));
    ssfx::setParam(method.params, paramsData(params), method.id, name, value);
}

}  // namespace ssfx::deferred
