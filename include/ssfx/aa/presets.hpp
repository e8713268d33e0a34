// Edge-threshold presets shared by fxaa3c, fxaa3d, ddaa1 and ddaa2 (spec ppaa.md section 1,
// after FXAA 3.11's FXAA_QUALITY__EDGE_THRESHOLD{,_MIN} presets). A pixel is left unchanged
// when lumaMax - lumaMin < max(edgeThresholdMin, lumaMax * edgeThreshold).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace ssfx::aa {

enum class Preset { Low, Medium, High, Ultra, Extreme };

struct EdgeThresholds {
    float edgeThresholdMin;  //!< absolute luma contrast below which nothing is done
    float edgeThreshold;     //!< contrast relative to the local maximum luma
};

struct PresetInfo {
    Preset preset;
    std::string_view name;
    EdgeThresholds thresholds;
    std::string_view doc;
};

//! The five presets with their numbers (also printed by `ssfx aa --list-presets`).
inline constexpr std::array<PresetInfo, 5> kPresets = {{
    {Preset::Low, "low", {0.0833f, 0.250f}, "fastest; skips soft edges"},
    {Preset::Medium, "medium", {0.0625f, 0.166f}, "default of FXAA 3.11 and DDAA"},
    {Preset::High, "high", {0.0312f, 0.125f}, "treats softer edges"},
    {Preset::Ultra, "ultra", {0.0156f, 0.063f}, "nearly every visible edge"},
    {Preset::Extreme, "extreme", {0.0078f, 0.031f}, "every edge; slowest"},
}};

//! The docs of the threshold parameters, shared by the four methods' tables.
inline constexpr std::string_view kEdgeThresholdMinDoc = "absolute luma contrast below which a pixel is left unchanged";
inline constexpr std::string_view kEdgeThresholdDoc = "contrast threshold relative to the local maximum luma";
inline constexpr std::string_view kChromaWeightDoc =
    "opt-in colour-aware contrast: luma + chromaWeight * (max - min of RGB); 0 = luma";
inline constexpr std::string_view kTextureDoc =
    "the input texture's format: unorm (rgba8unorm, the paper's) or srgb (rgba8unorm_srgb: every read decoded to "
    "linear light, filtered, the result encoded back with round-to-nearest; luma thresholds apply to the decoded "
    "values' luma). On the CPU blur and the luma methods run vectorised in both modes (srgb at most about 1.5x "
    "unorm's time, measured in docs/gpu.md), the resolves run the scalar kernel; on the vulkan backend it reads an "
    "sRGB view (docs/gpu.md)";

inline constexpr EdgeThresholds thresholdsFor(Preset p) {
    for (const auto& i : kPresets)
        if (i.preset == p) return i.thresholds;
    return kPresets[1].thresholds;
}
inline std::optional<Preset> parsePreset(std::string_view name) {
    for (const auto& i : kPresets)
        if (i.name == name) return i.preset;
    return std::nullopt;
}

}  // namespace ssfx::aa
