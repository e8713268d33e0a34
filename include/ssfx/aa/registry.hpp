// The explicit method registry (STYLE.md section 2): one table in src/aa/registry.cpp lists
// every method with its stable id, parameters and run functions. The CLI, benchmarks,
// evaluation and property tests iterate methods(); --help text is generated from the parameter tables
// (core/params.hpp).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/presets.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/method.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx {

//! How a method is configured at run time: a preset (threshold methods), then named overrides.
struct MethodSettings {
    std::optional<aa::Preset> preset;
    std::vector<std::pair<std::string, double>> params;  //!< name -> value, applied in order
    Filtering filtering = Filtering::Gpu;
};

using RunFn = ImageRgba8 (*)(ImageView<const Rgba8> input, const MethodSettings& settings, const Exec& exec);
//! Writes into `output`, which must be the input's size divided by inputScale (hot loops,
//! benchmarks: no allocation of the output).
using RunIntoFn = void (*)(ImageView<const Rgba8> input, ImageView<Rgba8> output, const MethodSettings& settings,
                           const Exec& exec);

//! The nine image-to-image methods: family "aa" (MethodDesc), kind "ppaa" (post-process
//! anti-aliasing) or "resolve" (supersampling resolves).
struct MethodInfo : MethodDesc {
    std::string_view kind;
    bool usesPresets;  //!< accepts the edge-threshold presets
    //! The input is the scene rendered at this scale (1; 2 for ssaax2/ddaa2p; 4 for ssaax4);
    //! the output is always at scale 1.
    int inputScale;
    RunFn run;          //!< the fast path (SIMD, threads), allocating its output
    RunIntoFn runInto;  //!< the fast path into a caller's output
    RunFn reference;    //!< the scalar oracle (ignores Exec)
};

//! A method's parameters as its CPU function takes them (the params struct), resolved from
//! settings exactly as run() resolves them: monostate for noaa, Ddaa2Params for ddaa2 and
//! ddaa2p. The GPU passes turn these into their shader constants (gpu/aa.hpp).
using AaParams = std::variant<std::monostate, aa::BlurParams, aa::Fxaa3cParams, aa::Fxaa3dParams, aa::Ddaa1Params,
                              aa::Ddaa2Params, aa::Ssaax2Params, aa::MitchellParams>;
AaParams resolveParams(std::string_view id, const MethodSettings& settings);

std::span<const MethodInfo> methods();
const MethodInfo* findMethod(std::string_view id);
//! Like findMethod, but throws ssfx::Error listing the known ids.
const MethodInfo& methodById(std::string_view id);

}  // namespace ssfx
