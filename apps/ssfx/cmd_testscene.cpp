// ssfx testscene: write the synthetic aliased drawing at 1x, 2x and 4x (scene.png,
// scenex2.png, scenex4.png), the inputs of the demo and of the resolves.
#include <fmt/format.h>

#include <filesystem>

#include "apps/ssfx/commands.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::cli {

void addTestsceneCommand(CLI::App& app) {
    struct Options {
        std::string out;
        int width = 1920, height = 1080;
    };
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand("testscene", "Write the synthetic test drawing at 1x, 2x and 4x");
    cmd->add_option("--out", o->out, "Output directory (created if missing)")->required();
    cmd->add_option("--width", o->width, "Width at 1x (default 1920)")->check(CLI::Range(1, 8192));
    cmd->add_option("--height", o->height, "Height at 1x (default 1080)")->check(CLI::Range(1, 8192));
    cmd->callback([o] {
        // The largest image first (refused before any file is drawn), and all three or none.
        checkDimensions(std::int64_t(o->width) * 4, std::int64_t(o->height) * 4, "the 4x drawing (scenex4.png)");
        io::makeDirectories(o->out);
        io::OutputSet outputs;
        for (int scale : {1, 2, 4}) {
            io::writePng(eval::renderSetPath(o->out, "scene", scale),
                         eval::syntheticScene(o->width, o->height, scale).view());
        }
        outputs.commit();
    });
}

}  // namespace ssfx::cli
