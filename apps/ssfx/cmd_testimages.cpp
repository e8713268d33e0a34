// ssfx testimages: write the evaluation's test images (ssfx/eval/test_images.hpp) at scale
// 1, 2, 4 and 8: NAME.png, NAMEx2.png, NAMEx4.png, NAMEx8.png (animations as looping APNG).
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::cli {

void addTestimagesCommand(CLI::App& app) {
    struct Options {
        std::string out;
        std::vector<std::string> names;
        std::vector<int> scales{1, 2, 4, 8};
    };
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "testimages", "Draw the evaluation's test images (lines, circles, plot, animated) at 1x, 2x, 4x, 8x");
    cmd->add_option("--out", o->out, "Output directory (created if missing)")->required();
    cmd->add_option("--images", o->names, "Images to draw (default: all)")->delimiter(',');
    cmd->add_option("--scales", o->scales, "Scales to draw (default: 1,2,4,8)")
        ->delimiter(',')
        ->check(CLI::Range(1, 16));
    cmd->footer(
        "Files: NAME.png at scale 1 and NAMExS.png at scale S. 'animated' is written as a looping\n"
        "APNG (32 frames, 25 fps). Same geometry at every scale: the x8 render is the reference of\n"
        "'ssfx eval quality', the x2/x4 renders are the inputs of the resolves.");
    cmd->callback([o] {
        std::vector<std::string> names = o->names;
        if (names.empty())
            for (const auto& t : eval::testImages()) names.emplace_back(t.name);
        io::makeDirectories(o->out);
        io::OutputSet outputs;  // every image, or none
        for (const auto& name : names) {
            const eval::TestImageInfo& info = eval::testImageByName(name);
            for (int scale : o->scales) {
                const std::string file = eval::renderSetPath(o->out, name, scale);
                printNote("testimages", file);
                if (info.frames == 1) {
                    io::writePng(file, eval::drawTestImage(name, scale).view());
                    continue;
                }
                // Written a frame at a time: one frame in memory (the x8 'animated' is 92 MB a
                // frame, 3 GB whole).
                std::unique_ptr<io::ApngWriter> anim;
                for (int f = 0; f < info.frames; ++f) {
                    const ImageRgba8 frame = eval::drawTestImage(name, scale, f);
                    if (!anim)
                        anim = std::make_unique<io::ApngWriter>(file, frame.width(), frame.height(),
                                                                std::uint32_t(info.frames));
                    anim->add(frame.view(), 1, std::uint16_t(info.fps));
                }
                anim->commit();
            }
        }
        outputs.commit();
    });
}

}  // namespace ssfx::cli
