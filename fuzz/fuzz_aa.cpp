// Fuzzes what `ssfx aa` does with arbitrary bytes: decode (PNG or APNG), then run a method
// chosen by the first byte, with a parameter override from the next bytes.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 6) return 0;
    const auto all = ssfx::methods();
    const ssfx::MethodInfo& m = all[data[0] % all.size()];
    ssfx::MethodSettings s;
    if (!m.params.empty() && (data[1] & 1)) {
        float v;
        std::memcpy(&v, data + 2, 4);
        s.params.push_back({std::string(m.params[data[1] % m.params.size()].name), double(v)});
    }
    try {
        auto anim = ssfx::io::decodeApng({data + 6, size - 6}, "fuzz");
        for (auto& f : anim.frames) {
            if (f.image.pixelCount() > 1 << 16) return 0;  // keep each input fast
            f.image = m.run(f.image.view(), s, ssfx::Exec{1});
        }
    } catch (const ssfx::Error&) {
    }
    return 0;
}
