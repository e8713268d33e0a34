// Describes the machine a timing was taken on (STYLE.md section 6: timings name the machine).
#pragma once

#include <string>

namespace ssfx::eval {

struct MachineInfo {
    std::string cpu;          //!< model name from /proc/cpuinfo ("unknown" elsewhere)
    int hardwareThreads = 0;  //!< std::thread::hardware_concurrency
    int threads = 0;          //!< threads the measurement used
    std::string simdTarget;   //!< the Highway target runtime dispatch uses here (e.g. AVX2)
};

MachineInfo machineInfo(int threadsUsed);

}  // namespace ssfx::eval
