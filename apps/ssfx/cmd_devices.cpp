// ssfx devices: the Vulkan devices of this machine and what each can run (the renderer
// needs graphics; the GPU effects need compute). One listing for every Vulkan user.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "apps/ssfx/commands.hpp"
#include "ssfx/vk/device.hpp"

namespace ssfx::cli {

namespace {

const char* capability(const vkx::DeviceInfo& d) {
    return d.graphics  ? "renders and computes"
           : d.compute ? "computes only (no graphics queue or dynamic rendering)"
                       : "unsuitable (needs Vulkan 1.3)";
}

}  // namespace

void addDevicesCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("devices", "List the Vulkan devices (lavapipe without a GPU) and what each can run");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "Print JSON: index, name, type, api, compute, graphics, maxImageDimension2D");
    cmd->footer(
        "A device is chosen with --device N (its index) or --device NAME (part of its name, any case);\n"
        "without --device: the first discrete GPU, else integrated, virtual, then CPU. The renderer needs\n"
        "Vulkan 1.3 with a graphics queue and dynamic rendering, compute passes a compute queue.");
    cmd->callback([json] {
        const std::vector<vkx::DeviceInfo> devices = vkx::listDevices();
        if (*json) {
            nlohmann::ordered_json all = nlohmann::ordered_json::array();
            for (const auto& d : devices)
                all.push_back({{"index", d.index},
                               {"name", d.name},
                               {"type", d.type},
                               {"api", d.api},
                               {"compute", d.compute},
                               {"graphics", d.graphics},
                               {"maxImageDimension2D", d.maxImageDimension2D}});
            fmt::print("{}\n", all.dump(2));
            return;
        }
        if (devices.empty()) fmt::print("no Vulkan device (mesa-vulkan-drivers gives lavapipe, a CPU device)\n");
        for (const auto& d : devices)
            fmt::print("{}: {} ({}, Vulkan {}, images up to {} px): {}\n", d.index, d.name, d.type, d.api,
                       d.maxImageDimension2D, capability(d));
    });
}

}  // namespace ssfx::cli
