// Subcommands of the ssfx tool. Each file registers one subcommand; no algorithm code here.
#pragma once

#include <CLI/CLI.hpp>

namespace ssfx::cli {

void addAaCommand(CLI::App& app);
void addMethodsCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addTestsceneCommand(CLI::App& app);
void addTestimagesCommand(CLI::App& app);
void addEvalCommand(CLI::App& app);

}  // namespace ssfx::cli
