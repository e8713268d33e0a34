// ssfx: screen-space effects from the command line.
// Exit codes: 0 success, 2 bad input or usage (the message says what), 1 internal failure.
// Results go to stdout, diagnostics and progress to stderr (apps/ssfx/console.hpp).
#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/core/memory.hpp"
#include "ssfx/io/png.hpp"

int main(int argc, char** argv) {
    ssfx::tuneAllocatorForImages();  // frames and benchmark repetitions reuse their buffers
    CLI::App app{
        "ssfx: screen-space rendering effects (post-processing anti-aliasing, resolves, ambient obscurance)\n"
        "Run 'ssfx <command> --help' for the options of a command.",
        "ssfx"};
    app.require_subcommand(1);
    app.footer(
        "Output: results on stdout; diagnostics and progress on stderr (progress only on a terminal, or\n"
        "with --progress); -q prints errors only. Files are written whole or not at all.\n"
        "Exit status: 0 done, 2 bad input or usage (the message names the problem), 1 internal error.");
    app.set_version_flag("--version", "ssfx 0.1.0");
    // A batch user's lower pixel limit for every input (before the command: ssfx --max-pixels N aa ...).
    app.add_option_function<std::int64_t>(
           "--max-pixels", [](std::int64_t n) { ssfx::io::setMaxPixels(n); },
           "Refuse input images larger than N pixels from their header (default and most: 268435456 = 2^28)")
        ->trigger_on_parse();
    app.add_flag_function(
        "-q,--quiet", [](std::int64_t n) { ssfx::cli::setQuiet(n > 0); },
        "Print nothing but errors (and the outputs asked for on stdout: -o -, --json -)");
    app.add_flag_function(
        "--progress", [](std::int64_t n) { ssfx::cli::setForceProgress(n > 0); },
        "Draw progress lines even when stderr is not a terminal (by default only on a terminal)");
    app.fallthrough();  // ... or after it: ssfx aa --max-pixels N -q ...
    ssfx::cli::addAaCommand(app);
    ssfx::cli::addMethodsCommand(app);
    ssfx::cli::addBenchCommand(app);
    ssfx::cli::addTestsceneCommand(app);
    ssfx::cli::addTestimagesCommand(app);
    ssfx::cli::addAoCommand(app);
#ifdef SSFX_HAVE_RENDER
    ssfx::cli::addRenderCommand(app);
    ssfx::cli::addDeferredCommand(app);
    ssfx::cli::addDevicesCommand(app);
#endif
    ssfx::cli::addEvalCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    } catch (const ssfx::Error& e) {
        std::fprintf(stderr, "ssfx: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssfx: internal error: %s\n", e.what());
        return 1;
    }
    return 0;
}
