// Running a third-party parser where its crash cannot take ssfx down with it.
//
// Model files are parsed by Assimp, whose importers (Debian's 5.2.5) read past the end of
// some malformed files or dereference null on them: the fuzz targets fuzz_obj and fuzz_gltf
// find such files within seconds. ssfx cannot mend another library, but it can keep its
// promise that bad input gives a clear error: such work runs in a child process (fork) and
// hands its result back as bytes; a child that dies becomes an ssfx::Error.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ssfx {

//! Runs `work` in a forked child and returns the bytes it returned. An ssfx::Error (or any
//! std::exception) thrown by `work` is rethrown here as ssfx::Error with the same message; a
//! child that stops in any other way (a signal, a sanitizer report, running out of memory)
//! throws ssfx::Error "WHAT: the PARSER stopped abnormally (...)". `work` must not use the
//! parent's threads (oneTBB) or locks: only the calling thread exists in the child.
std::vector<std::uint8_t> runIsolated(const std::function<std::vector<std::uint8_t>()>& work, const std::string& what,
                                      const std::string& parser);

}  // namespace ssfx
