// Temporal stability (see temporal.hpp for the definitions).
#include "ssfx/eval/temporal.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cmath>
#include <nlohmann/json.hpp>

#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/quality.hpp"

namespace ssfx::eval {

TemporalResult temporalScore(const std::vector<ImageRgba8>& out, const std::vector<ImageRgba8>& ref,
                             const Exec& exec) {
    const std::size_t n = out.size();
    if (n < 2 || ref.size() != n) throw Error("temporal: need at least 2 frames and as many reference frames");
    for (std::size_t t = 0; t < n; ++t)
        if (out[t].width() != ref[0].width() || out[t].height() != ref[0].height() ||
            ref[t].width() != ref[0].width() || ref[t].height() != ref[0].height())
            throw Error(fmt::format("temporal: frame {} differs in size", t));
    const int w = ref[0].width(), h = ref[0].height();
    // Differences of differences are integers in [-510, 510]: exact sums.
    std::uint64_t flickerSum = 0;
    double mseSum = 0;
    for (std::size_t t = 0; t < n; ++t) {
        const std::size_t u = (t + 1) % n;
        std::atomic<std::uint64_t> s{0};
        parallelRows(h, exec, [&](int y0, int y1) {
            std::uint64_t local = 0;
            for (int y = y0; y < y1; ++y) {
                const Rgba8 *o0 = out[t].view().row(y), *o1 = out[u].view().row(y);
                const Rgba8 *r0 = ref[t].view().row(y), *r1 = ref[u].view().row(y);
                for (int x = 0; x < w; ++x) {
                    const int dr = (o1[x].r - o0[x].r) - (r1[x].r - r0[x].r);
                    const int dg = (o1[x].g - o0[x].g) - (r1[x].g - r0[x].g);
                    const int db = (o1[x].b - o0[x].b) - (r1[x].b - r0[x].b);
                    local += std::uint64_t(dr * dr + dg * dg + db * db);
                }
            }
            s += local;
        });
        flickerSum += s.load();
        mseSum += mse(out[t].view(), ref[t].view(), exec);
    }
    const double meanSq = double(flickerSum) / (255.0 * 255.0) / (double(w) * h * 3 * double(n));
    return {"", std::sqrt(meanSq) * 255.0, psnrFromMse(meanSq), psnrFromMse(mseSum / double(n))};
}

TemporalRun evaluateTemporal(int frames, const FrameFn& frame, const TemporalOptions& o) {
    if (frames < 2) throw Error(fmt::format("temporal: an animation of {} frame(s) has no motion", frames));
    const std::vector<std::string> ids = o.methods.empty() ? paperMethodOrder() : o.methods;
    std::vector<const MethodInfo*> ms;
    bool need[3] = {false, false, false};  // x2, x4 inputs
    for (const auto& id : ids) {
        ms.push_back(&methodById(id));
        if (ms.back()->inputScale == 2) need[0] = true;
        if (ms.back()->inputScale == 4) need[1] = true;
    }
    TemporalRun run;
    run.outputs.resize(ms.size());
    for (int t = 0; t < frames; ++t) {
        if (o.progress) o.progress(fmt::format("temporal: frame {}/{}", t + 1, frames));
        const ImageRgba8 x1 = frame(t, 1);
        ImageRgba8 x2 = need[0] ? frame(t, 2) : ImageRgba8{};
        ImageRgba8 x4 = need[1] ? frame(t, 4) : ImageRgba8{};
        {
            const ImageRgba8 x8 = frame(t, 8);
            if (x8.width() != 8 * x1.width() || x8.height() != 8 * x1.height())
                throw Error(fmt::format("temporal: the x8 frame {} is {}x{}, expected 8 times {}x{}", t, x8.width(),
                                        x8.height(), x1.width(), x1.height()));
            run.reference.push_back(aa::downscaleMitchell(x8.view(), 8, {}, o.exec));
        }
        for (std::size_t m = 0; m < ms.size(); ++m) {
            const ImageRgba8& in = ms[m]->inputScale == 4 ? x4 : ms[m]->inputScale == 2 ? x2 : x1;
            run.outputs[m].push_back(ms[m]->run(in.view(), o.settings, o.exec));
        }
    }
    for (std::size_t m = 0; m < ms.size(); ++m) {
        TemporalResult r = temporalScore(run.outputs[m], run.reference, o.exec);
        r.method = ids[m];
        run.results.push_back(r);
    }
    return run;
}

std::string temporalMarkdown(const std::vector<TemporalResult>& results) {
    std::string s = "| method | flicker (levels RMS) | tPSNR (dB) | PSNR (dB) |\n|---|---:|---:|---:|\n";
    for (const auto& r : results)
        s += fmt::format("| {} | {:.3f} | {:.3f} | {:.3f} |\n", r.method, r.flickerLevels, r.temporalPsnr, r.psnr);
    return s;
}

std::string temporalJson(const std::vector<TemporalResult>& results) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
    for (const auto& r : results)
        j[r.method] = {{"flicker_levels", num(r.flickerLevels)},
                       {"temporal_psnr", num(r.temporalPsnr)},
                       {"psnr", num(r.psnr)}};
    return j.dump(2) + "\n";
}

}  // namespace ssfx::eval
