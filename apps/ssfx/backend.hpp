// --backend cpu|vulkan and --device for the commands that run anti-aliasing methods (aa,
// bench): one place that turns them into a function applying a method to an image.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"

namespace ssfx::cli {

struct BackendOptions {
    std::string backend = "cpu";
    std::string device;    //!< vulkan: an index or part of a name
    std::string sampling;  //!< vulkan: model (default) or hardware, from -p sampling=...
    std::string edges;     //!< vulkan: auto (default), list, one-pass or segments, from -p edges=...
};

//! Adds --backend and --device to `cmd`.
void addBackendOptions(CLI::App* cmd, BackendOptions& o);

//! Refuses what the backend choice would silently ignore: --device without --backend
//! vulkan. (A blank --device is refused where devices are chosen, vkx::Context.)
void checkBackendOptions(const BackendOptions& o);

//! Takes -p sampling=model|hardware and -p edges=auto|list|one-pass|segments out of `params` into
//! o.sampling and o.edges (an error with the cpu backend, where the sampling model is
//! --filtering and the edge path does not exist).
void takeSamplingParam(std::vector<std::string>& params, BackendOptions& o);

//! A method applied to whole images on the chosen backend; `name` says where it ran
//! ("cpu", or "vulkan: DEVICE, sampling=MODE"). Safe to call from several threads (the GPU
//! runs one image at a time). Throws ssfx::Error: no Vulkan device (naming what was looked
//! for), a setting the GPU passes lack, a build without the GPU backend.
//! The last GPU apply()'s dispatches (stage, milliseconds) and the share of pixels its
//! classify dispatch listed (-1: no list); see gpu::AaPass::lastDispatches().
struct DispatchProfile {
    std::vector<std::pair<std::string, double>> dispatches;
    double edgeShare = -1;
};

struct Applier {
    std::function<ImageRgba8(ImageView<const Rgba8>)> apply;
    //! GPU milliseconds of the last apply() (timestamps), or a negative value on the cpu backend.
    std::function<double()> lastGpuMs;
    std::string name, device;
    //! vulkan: the last apply()'s profile; cpu: an empty one.
    std::function<DispatchProfile()> lastProfile = [] { return DispatchProfile{}; };
    //! vulkan, model: the device's unorm decode was probed exact and is used (gpu::AaPass::deviceDecode).
    bool deviceDecode = false;
    //! vulkan: the pass's path (gpu::edgePathName of gpu::AaPass::edgePath); cpu: empty.
    std::string edgePath{};
};
Applier makeApplier(const BackendOptions& o, const MethodInfo& m, const MethodSettings& settings, const Exec& exec);

}  // namespace ssfx::cli
