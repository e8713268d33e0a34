#include "ssfx/eval/machine.hpp"

#include <hwy/highway.h>
#include <hwy/targets.h>

#include <fstream>
#include <thread>

namespace ssfx::eval {

MachineInfo machineInfo(int threadsUsed) {
    MachineInfo m;
    m.cpu = "unknown";
    std::ifstream f("/proc/cpuinfo");
    for (std::string line; std::getline(f, line);) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) m.cpu = line.substr(colon + 2);
            break;
        }
    }
    m.hardwareThreads = int(std::thread::hardware_concurrency());
    m.threads = threadsUsed;
    const std::int64_t targets = hwy::SupportedTargets();
    m.simdTarget = hwy::TargetName(targets & -targets);  // lowest bit = best target
    return m;
}

}  // namespace ssfx::eval
