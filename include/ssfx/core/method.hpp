// What every registry entry says about its method, in every family (aa: registry.hpp;
// ao: ao/registry.hpp; deferred: deferred/registry.hpp). `ssfx methods`, --help, the docs'
// parameter lists and the property tests read these fields; each family's entry adds how
// its methods are run.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "ssfx/core/params.hpp"

namespace ssfx {

//! The backends a method can run on: "cpu", and "vulkan" for the aa methods when ssfx is built
//! with its GPU backend (SSFX_BUILD_GPU; ssfx/gpu/aa.hpp).
inline constexpr std::array<std::string_view, 1> kCpuBackend{"cpu"};
inline constexpr std::array<std::string_view, 2> kCpuVulkanBackends{"cpu", "vulkan"};

struct MethodDesc {
    std::string_view id;        //!< stable public name (CLI, files, reports, spec)
    std::string_view family;    //!< "aa", "ao" or "deferred"
    std::string_view summary;   //!< one line
    std::string_view citation;  //!< paper and section
    std::string_view inputs;    //!< what it reads, in words ("an RGBA8 image", "a depth buffer and its camera")
    std::span<const ParamInfo> params;
    std::span<const std::string_view> presets;  //!< named configurations, the default first; may be empty
    std::span<const std::string_view> backends = kCpuBackend;
};

//! "a, b, c": the ids of a registry, for the unknown-id messages.
template <class Entry>
std::string idList(std::span<const Entry> entries) {
    std::string s;
    for (const Entry& e : entries) {
        if (!s.empty()) s += ", ";
        s += e.id;
    }
    return s;
}

//! The struct a parameters variant holds, as the table functions take it (ParamInfo::get/set).
template <class... P>
void* paramsData(std::variant<P...>& params) {
    return std::visit([](auto& p) -> void* { return &p; }, params);
}

//! The family names, in the order `ssfx methods` lists them.
inline constexpr std::array<std::string_view, 3> kFamilies{"aa", "ao", "deferred"};

}  // namespace ssfx
