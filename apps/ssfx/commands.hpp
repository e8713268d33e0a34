// Subcommands of the ssfx tool. Each file registers one subcommand; no algorithm code here.
#pragma once

#include <CLI/CLI.hpp>

#include "ssfx/core/params.hpp"
#ifdef SSFX_HAVE_RENDER
#include "ssfx/deferred/adaptive.hpp"
#endif

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ssfx::cli {

//! Parses NAME=VALUE (VALUE a number, true or false) of -p options; throws ssfx::Error.
std::pair<std::string, double> parseParam(const std::string& text);
//! The same for one method's table: the name must be one of its rows, a Choice's value may be
//! a name (sampling=hardware), a Boolean's true/false. Throws ssfx::Error naming `id`.
std::pair<std::string, double> parseParam(const std::string& text, std::span<const ParamInfo> table,
                                          std::string_view id);
//! Parses WIDTHxHEIGHT with both in [1, maxSide]; throws ssfx::Error naming `option`.
//! --max-pixels N: a whole number in [1, kMaxPixels], echoed as given when it is not.
std::int64_t parseMaxPixels(const std::string& text);
std::pair<int, int> parseSize(const std::string& text, const std::string& option = "--size", int maxSide = 16384);
#ifdef SSFX_HAVE_RENDER
//! The adaptive shading's params (deferred registry): the defaults, the stall, then the -p
//! NAME=VALUE overrides, validated (ssfx deferred and ssfx frame). Throws ssfx::Error.
deferred::AdaptiveParams adaptiveParams(const std::vector<std::string>& params, int stall);
#endif

void addAaCommand(CLI::App& app);
void addMethodsCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addTestsceneCommand(CLI::App& app);
void addTestimagesCommand(CLI::App& app);
void addEvalCommand(CLI::App& app);
void addAoCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addDeferredCommand(CLI::App& app);
void addDevicesCommand(CLI::App& app);
void addFrameCommand(CLI::App& app);

}  // namespace ssfx::cli
