// The Vulkan devices of this machine and how a context chooses one. No Vulkan headers here:
// the renderer's and the GPU effects' public headers include this one.
//
// The module's namespace is ssfx::vkx, not ssfx::vk: inside namespace ssfx a nested `vk`
// would hide Vulkan-Hpp's ::vk from every file of the project.
#pragma once

#include <string>
#include <vector>

namespace ssfx::vkx {

struct DeviceInfo {
    int index = 0;                //!< position in the instance's enumeration
    std::string name;             //!< as the driver reports it, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string type;             //!< discrete, integrated, virtual, cpu, other
    std::string api;              //!< supported Vulkan version, e.g. "1.3.230"
    bool compute = false;         //!< Vulkan 1.3 with a compute queue: runs the GPU effects
    bool graphics = false;        //!< also a graphics queue and dynamic rendering: runs the renderer
    int maxImageDimension2D = 0;  //!< the largest image side it handles (VkPhysicalDeviceLimits)
};

struct ContextOptions {
    //! A device index or a (case-insensitive) part of its name; empty = the first discrete
    //! GPU, else integrated, virtual, then CPU (lavapipe).
    std::string device;
    //! VK_LAYER_KHRONOS_validation with synchronization validation, its messages collected
    //! (also: SSFX_VK_VALIDATION=1).
    bool validation = false;
    //! Ask for a graphics queue and dynamic rendering (the renderer); a compute queue always.
    bool graphics = false;
};

//! Every Vulkan device of this machine. Throws ssfx::Error when there is no Vulkan loader.
std::vector<DeviceInfo> listDevices();

}  // namespace ssfx::vkx
