#include "ssfx/eval/machine.hpp"

#include <hwy/highway.h>
#include <hwy/targets.h>

#include <fstream>
#include <thread>
#include <vector>

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
    // The target runtime dispatch picks: the best one both compiled in and supported.
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    m.simdTarget = targets.empty() ? "none" : hwy::TargetName(targets.front());
    return m;
}

}  // namespace ssfx::eval
