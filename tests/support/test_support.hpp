// Helpers shared by the tests: ASCII micro-images, image comparison, the shared data dir.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ssfx/core/error.hpp"
#include "ssfx/core/image.hpp"

namespace ssfx {
struct MethodInfo;
//! gtest prints registry parameters by id (readable ctest names).
void PrintTo(const MethodInfo* m, std::ostream* os);
}  // namespace ssfx

namespace ssfx::test {

//! Builds an image from rows of characters: '.' = white, '#' = black, digits 0-9 = grey
//! levels 0, 28, ..., 252; other letters via `palette` pairs. All rows the same length.
ImageRgba8 ascii(const std::vector<std::string>& rows);

//! Solid image.
ImageRgba8 solid(int w, int h, Rgba8 c);

//! Deterministic pseudo-random image (xorshift), with varying alpha.
ImageRgba8 noise(int w, int h, unsigned seed);

//! Path of the shared folder, or nullopt when it (or the given subfolder) is absent.
std::optional<std::string> sharedDir(const std::string& sub = "");

//! Largest per-channel RGB difference.
int maxAbsDiff(const ImageRgba8& a, const ImageRgba8& b);

std::string outDir();  //!< a per-build folder for failure images

//! The message of the ssfx::Error that `f()` throws, or "(no error)".
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace ssfx::test
