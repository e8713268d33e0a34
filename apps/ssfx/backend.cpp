// --backend cpu|vulkan (apps/ssfx/backend.hpp).
#include "apps/ssfx/backend.hpp"

#include <fmt/format.h>

#include <memory>
#include <mutex>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/error.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/gpu/aa.hpp"
#endif

namespace ssfx::cli {

void addBackendOptions(CLI::App* cmd, BackendOptions& o) {
    cmd->add_option("--backend", o.backend,
                    "cpu (default) or vulkan: the methods as Vulkan compute passes (-p sampling=model, the default, "
                    "gives the CPU's bytes; -p sampling=hardware uses the device's texture filtering and arithmetic; "
                    "-p edges=list|one-pass|segments chooses the edge-test methods' path, default auto)")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    cmd->add_option("--device", o.device,
                    "With --backend vulkan: a device index or part of its name ('ssfx devices' lists them; default: "
                    "a GPU, else lavapipe)");
}

void checkBackendOptions(const BackendOptions& o) {
    if (o.backend != "vulkan" && !o.device.empty()) throw Error("--device goes with --backend vulkan");
}

void takeSamplingParam(std::vector<std::string>& params, BackendOptions& o) {
    std::vector<std::string> rest;
    for (const auto& p : params) {
        if (p.rfind("sampling=", 0) == 0) {
            o.sampling = p.substr(9);
            if (o.backend != "vulkan")
                throw Error("-p sampling=... is a parameter of the vulkan backend (on the cpu: --filtering gpu|exact)");
            if (o.sampling != "model" && o.sampling != "hardware")
                throw Error(fmt::format("sampling '{}': expected model or hardware", o.sampling));
        } else if (p.rfind("edges=", 0) == 0) {
            o.edges = p.substr(6);
            if (o.backend != "vulkan") throw Error("-p edges=... is a parameter of the vulkan backend");
            if (o.edges != "auto" && o.edges != "list" && o.edges != "one-pass" && o.edges != "segments")
                throw Error(fmt::format("edges '{}': expected auto, list, one-pass or segments", o.edges));
        } else {
            rest.push_back(p);
        }
    }
    params = std::move(rest);
}

Applier makeApplier(const BackendOptions& o, const MethodInfo& m, const MethodSettings& settings, const Exec& exec) {
    checkBackendOptions(o);
    if (o.backend != "vulkan") {
        // The parameters checked now, not with the first frame: a bad value is the run's
        // error, not a frame's (the GPU pass checks them when it is made).
        resolveParams(m.id, settings);
        const MethodInfo* method = &m;
        return {[method, settings, exec](ImageView<const Rgba8> in) { return method->run(in, settings, exec); },
                [] { return -1.0; }, "cpu", ""};
    }
#ifdef SSFX_HAVE_GPU
    vkx::ContextOptions co;
    co.device = o.device;
    std::shared_ptr<vkx::Context> ctx;
    try {
        ctx = vkx::Context::create(co);
    } catch (const Error& e) {
        throw Error(fmt::format("--backend vulkan looked for a Vulkan 1.3 device with a compute queue{}: {}",
                                o.device.empty() ? "" : fmt::format(" matching '{}'", o.device), e.what()));
    }
    const gpu::Sampling sampling = o.sampling.empty() ? gpu::Sampling::Model : gpu::parseSampling(o.sampling);
    const gpu::EdgePath edges = o.edges.empty() ? gpu::EdgePath::Auto : gpu::parseEdgePath(o.edges);
    auto pass = std::make_shared<gpu::AaPass>(ctx, m.id, settings, sampling, edges);
    auto lock = std::make_shared<std::mutex>();
    const std::string device = ctx->info.name;
    Applier applier{[pass, lock](ImageView<const Rgba8> in) {
                        std::lock_guard guard(*lock);
                        return pass->run(in);
                    },
                    [pass, lock] {
                        std::lock_guard guard(*lock);
                        return pass->lastMilliseconds();
                    },
                    fmt::format("vulkan: {}, sampling={}, edges={}", device, gpu::samplingName(sampling),
                                gpu::edgePathName(pass->edgePath())),
                    device,
                    [pass, lock] {
                        std::lock_guard guard(*lock);
                        DispatchProfile p;
                        for (const auto& d : pass->lastDispatches()) p.dispatches.emplace_back(d.stage, d.milliseconds);
                        p.edgeShare = pass->lastEdgeShare();
                        return p;
                    }};
    applier.deviceDecode = pass->deviceDecode();
    applier.edgePath = gpu::edgePathName(pass->edgePath());
    return applier;
#else
    (void)settings;
    (void)exec;
    throw Error("this ssfx was built without the GPU backend (SSFX_BUILD_GPU=OFF): use --backend cpu");
#endif
}

}  // namespace ssfx::cli
