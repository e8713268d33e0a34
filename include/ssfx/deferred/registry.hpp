// The deferred family's registry: adaptive (the paper's method) and brute-force (every
// sample shaded, brute force, which it is measured against). MethodDesc plus how each is run.
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "ssfx/core/method.hpp"
#include "ssfx/deferred/adaptive.hpp"

namespace ssfx::deferred {

//! One method's parameters: adaptive's AdaptiveParams, brute-force's ShadingParams.
using DeferredParams = std::variant<AdaptiveParams, ShadingParams>;

struct DeferredMethodInfo : MethodDesc {
    DeferredParams (*defaults)();
    //! Throws ssfx::Error for a parameter outside its table's range.
    void (*validate)(const DeferredParams& params);
    DeferredResult (*run)(const scene::Scene& scene, const scene::GBuffer& gbuffer, const DeferredParams& params,
                          const Exec& exec);
};

std::span<const DeferredMethodInfo> deferredMethods();
//! Throws ssfx::Error listing the ids for an unknown one.
const DeferredMethodInfo& deferredMethodById(std::string_view id);
//! Sets a parameter by name, checked by the method's table.
void setParam(const DeferredMethodInfo& method, DeferredParams& params, std::string_view name, double value);

}  // namespace ssfx::deferred
