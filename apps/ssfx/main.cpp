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
    ssfx::cli::guardStdout();
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
    app.add_option_function<std::string>(
           "--max-pixels", [](const std::string& text) { ssfx::io::setMaxPixels(ssfx::cli::parseMaxPixels(text)); },
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
    ssfx::cli::addFrameCommand(app);
#endif
    ssfx::cli::addEvalCommand(app);
    int status = 0;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        status = app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        status = app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        status = app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        status = 2;
    } catch (const ssfx::Error& e) {
        status = ssfx::cli::reportError(e.what());
    } catch (const std::exception& e) {
        // A result that could not be written (fmt throws on a failed write to stdout) is a
        // problem of the output, not of ssfx.
        if (std::ferror(stdout)) {
            status = 2;  // finishStdout() below says why
        } else {
            std::fprintf(stderr, "ssfx: internal error: %s\n", e.what());
            status = 1;
        }
    }
    // Every command's results reach stdout here at the latest: a full disk, a closed or
    // broken stdout is an error (exit 2), never a silent loss of the table or the help.
    if (!ssfx::cli::finishStdout()) status = status == 0 ? 2 : status;
    return status;
}
