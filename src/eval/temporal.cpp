// Temporal stability (see temporal.hpp for the definitions).
#include "ssfx/eval/temporal.hpp"

#include <fmt/format.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::eval {

namespace {

// Sum over pixels and RGB of ((a1 - a0) - (b1 - b0))^2: integers in [-510, 510], exact.
std::uint64_t flickerSum(ImageView<const Rgba8> o0, ImageView<const Rgba8> o1, ImageView<const Rgba8> r0,
                         ImageView<const Rgba8> r1, const Exec& exec) {
    std::atomic<std::uint64_t> s{0};
    parallelRows(r0.height(), exec, [&](int y0, int y1) {
        std::uint64_t local = 0;
        for (int y = y0; y < y1; ++y) {
            const Rgba8 *a0 = o0.row(y), *a1 = o1.row(y), *b0 = r0.row(y), *b1 = r1.row(y);
            for (int x = 0; x < r0.width(); ++x) {
                const int dr = (a1[x].r - a0[x].r) - (b1[x].r - b0[x].r);
                const int dg = (a1[x].g - a0[x].g) - (b1[x].g - b0[x].g);
                const int db = (a1[x].b - a0[x].b) - (b1[x].b - b0[x].b);
                local += std::uint64_t(dr * dr + dg * dg + db * db);
            }
        }
        s += local;
    });
    return s.load();
}

class DrawnFrames : public FrameSource {
public:
    DrawnFrames(int frames, FrameFn fn) : frames_(frames), fn_(std::move(fn)) {}
    int frames() const override { return frames_; }
    ImageView<const Rgba8> frame(int t, int scale) override {
        ImageRgba8& slot = last_[scaleIndex(scale)];
        slot = ImageRgba8();  // the previous frame goes before the next is drawn
        slot = fn_(t, scale);
        return slot.view();
    }

private:
    static std::size_t scaleIndex(int scale) {
        switch (scale) {
            case 1: return 0;
            case 2: return 1;
            case 4: return 2;
            case 8: return 3;
            default: throw Error(fmt::format("temporal: no x{} frames (1, 2, 4, 8)", scale));
        }
    }
    int frames_;
    FrameFn fn_;
    ImageRgba8 last_[4];
};

class ApngFrames : public FrameSource {
public:
    ApngFrames(std::string dir, std::string name) : dir_(std::move(dir)), name_(std::move(name)) {
        frames_ = int(reader(8).frameCount());
    }
    int frames() const override { return frames_; }
    ImageView<const Rgba8> frame(int t, int scale) override {
        Stream& s = stream(scale);
        if (t != s.next) throw Error(fmt::format("temporal: frames of {} asked for out of order", s.path));
        const io::Frame* f = s.reader->next();
        if (!f) throw Error(fmt::format("{}: has {} frames, fewer than x8's {}", s.path, t, frames_));
        ++s.next;
        return f->image.view();
    }
    std::string path(int scale) const { return renderSetPath(dir_, name_, scale); }

private:
    struct Stream {
        std::string path;
        std::unique_ptr<io::ApngReader> reader;
        int next = 0;
    };
    Stream& stream(int scale) {
        reader(scale);
        return streams_[std::size_t(std::countr_zero(unsigned(scale)))];
    }
    io::ApngReader& reader(int scale) {
        if (scale != 1 && scale != 2 && scale != 4 && scale != 8)
            throw Error(fmt::format("temporal: no x{} frames (1, 2, 4, 8)", scale));
        Stream& s = streams_[std::size_t(std::countr_zero(unsigned(scale)))];
        if (!s.reader) {
            s.path = path(scale);
            if (!std::filesystem::exists(s.path)) throw Error(fmt::format("{}: no such file", s.path));
            s.reader = std::make_unique<io::ApngReader>(s.path);
            if (scale != 8 && int(s.reader->frameCount()) != frames_)
                throw Error(
                    fmt::format("{}: {} frames, but {} has {}", s.path, s.reader->frameCount(), path(8), frames_));
            if (scale != 8) {  // each scale's frames are scale/8 of the x8 frames' size
                const io::ApngReader& x8 = *streams_[3].reader;
                const int w = x8.width() / 8 * scale, h = x8.height() / 8 * scale;
                if (s.reader->width() != w || s.reader->height() != h)
                    throw Error(fmt::format("{}: {}x{}, expected {}x{} ({} times the 1x size of {}, {}x{})", s.path,
                                            s.reader->width(), s.reader->height(), w, h, scale, path(8), x8.width(),
                                            x8.height()));
            }
        }
        return *s.reader;
    }
    std::string dir_, name_;
    int frames_ = 0;
    Stream streams_[4];
};

// The truth's frame R_t: frame t at x8, resolved to 1x with the Mitchell filter, checked
// against the 1x size.
ImageRgba8 truthFrame(FrameSource& source, int t, int w, int h, const Exec& exec) {
    const ImageView<const Rgba8> x8 = source.frame(t, 8);
    if (x8.width() != 8 * w || x8.height() != 8 * h)
        throw Error(fmt::format("temporal: the x8 frame {} is {}x{}, expected 8 times {}x{}", t, x8.width(),
                                x8.height(), w, h));
    return aa::downscaleMitchell(x8, 8, {}, exec);
}

}  // namespace

void TemporalScorer::add(ImageView<const Rgba8> out, ImageView<const Rgba8> ref) {
    if (out.width() != ref.width() || out.height() != ref.height() ||
        (frames_ > 0 && (ref.width() != firstRef_.width() || ref.height() != firstRef_.height())))
        throw Error(fmt::format("temporal: frame {} differs in size", frames_));
    if (frames_ == 0) {
        firstOut_ = ImageRgba8::copyOf(out), firstRef_ = ImageRgba8::copyOf(ref);
    } else {
        flickerSum_ += flickerSum(prevOut_.view(), out, prevRef_.view(), ref, exec_);
    }
    mseSum_ += mse(out, ref, exec_);
    frameScores_.push_back(scoreOutput(Protocol::Truth, out, {}, ref, {}, exec_));
    prevOut_ = ImageRgba8::copyOf(out), prevRef_ = ImageRgba8::copyOf(ref);
    ++frames_;
}

TemporalResult TemporalScorer::result() const {
    if (frames_ < 2) throw Error("temporal: need at least 2 frames and as many truth frames");
    // Around the loop: the last frame to the first.
    const std::uint64_t sum =
        flickerSum_ + flickerSum(prevOut_.view(), firstOut_.view(), prevRef_.view(), firstRef_.view(), exec_);
    const double meanSq =
        double(sum) / (255.0 * 255.0) / (double(firstRef_.width()) * firstRef_.height() * 3 * double(frames_));
    Scores mean{0, 0, 0, 0};
    for (const Scores& f : frameScores_) {
        mean.psnr += f.psnr / frames_;
        mean.ssim += f.ssim / frames_;
        mean.maxError += f.maxError / frames_;
        mean.p99Error += f.p99Error / frames_;
    }
    return {"",  std::sqrt(meanSq) * 255.0, psnrFromMse(meanSq), psnrFromMse(mseSum_ / double(frames_)), frameScores_,
            mean};
}

TemporalResult temporalScore(const std::vector<ImageRgba8>& out, const std::vector<ImageRgba8>& ref, const Exec& exec) {
    if (out.size() < 2 || ref.size() != out.size())
        throw Error("temporal: need at least 2 frames and as many truth frames");
    TemporalScorer s(exec);
    for (std::size_t t = 0; t < out.size(); ++t) s.add(out[t].view(), ref[t].view());
    return s.result();
}

std::unique_ptr<FrameSource> drawnFrames(int frames, FrameFn frame) {
    return std::make_unique<DrawnFrames>(frames, std::move(frame));
}

std::unique_ptr<FrameSource> apngFrames(const std::string& dir, const std::string& name) {
    return std::make_unique<ApngFrames>(dir, name);
}

namespace {

// The frame loop shared by both protocols: `outputsOf(t, w, h)` gives the methods' outputs
// for frame t (w x h: the 1x size, known from frame 0).
template <class Outputs>
TemporalRun runTemporal(FrameSource& source, const std::vector<std::string>& names, const TemporalOptions& o,
                        const Outputs& outputsOf) {
    const int frames = source.frames();
    if (frames < 2) throw Error(fmt::format("temporal: an animation of {} frame(s) has no motion", frames));
    TemporalRun run;
    if (o.keepOutputs) run.outputs.resize(names.size());
    std::vector<TemporalScorer> scorers(names.size(), TemporalScorer(o.exec));
    for (int t = 0; t < frames; ++t) {
        if (o.progress) o.progress({"temporal", t + 1, frames, "frames"});
        const std::vector<ImageRgba8> outputs = outputsOf(t);
        const ImageRgba8 ref = truthFrame(source, t, outputs[0].width(), outputs[0].height(), o.exec);
        for (std::size_t m = 0; m < names.size(); ++m) {
            if (outputs[m].width() != ref.width() || outputs[m].height() != ref.height())
                throw Error(fmt::format("temporal: {} frame {} is {}x{}, the animation {}x{}", names[m], t,
                                        outputs[m].width(), outputs[m].height(), ref.width(), ref.height()));
            scorers[m].add(outputs[m].view(), ref.view());
        }
        if (o.onFrame) o.onFrame(t, outputs, ref);
        if (o.keepOutputs) {
            for (std::size_t m = 0; m < names.size(); ++m)
                run.outputs[m].push_back(ImageRgba8::copyOf(outputs[m].view()));
            run.truth.push_back(ImageRgba8::copyOf(ref.view()));
        }
    }
    for (std::size_t m = 0; m < names.size(); ++m) {
        TemporalResult r = scorers[m].result();
        r.method = names[m];
        run.results.push_back(r);
    }
    return run;
}

}  // namespace

TemporalRun evaluateTemporal(FrameSource& source, const TemporalOptions& o) {
    const std::vector<std::string> ids = o.methods.empty() ? paperMethodOrder() : o.methods;
    std::vector<const MethodInfo*> ms;
    bool need[3] = {false, false, false};  // x1, x2, x4 inputs
    for (const auto& id : ids) {
        ms.push_back(&methodById(id));
        need[ms.back()->inputScale == 4 ? 2 : ms.back()->inputScale == 2 ? 1 : 0] = true;
    }
    return runTemporal(source, ids, o, [&](int t) {
        // Each scale's frame is read once and used by every method that takes it.
        std::vector<ImageRgba8> outputs(ms.size());
        for (int k = 0; k < 3; ++k) {
            if (!need[k]) continue;
            const int scale = 1 << k;
            const ImageView<const Rgba8> in = source.frame(t, scale);
            for (std::size_t m = 0; m < ms.size(); ++m)
                if (ms[m]->inputScale == scale) outputs[m] = ms[m]->run(in, o.settings, o.exec);
        }
        return outputs;
    });
}

TemporalRun evaluateTemporal(int frames, const FrameFn& frame, const TemporalOptions& o) {
    const auto source = drawnFrames(frames, frame);
    return evaluateTemporal(*source, o);
}

TemporalRun evaluateTemporalGiven(FrameSource& source, const std::vector<std::pair<std::string, std::string>>& given,
                                  const TemporalOptions& o) {
    if (given.empty()) throw Error("temporal: no given outputs to score");
    std::vector<std::string> names;
    std::vector<io::ApngReader> readers;
    for (const auto& [name, path] : given) {
        if (!std::filesystem::exists(path))
            throw Error(fmt::format("{}: no such file (given outputs of {})", path, name));
        names.push_back(name);
        readers.emplace_back(path);
        if (int(readers.back().frameCount()) != source.frames())
            throw Error(
                fmt::format("{}: {} frames, the animation has {}", path, readers.back().frameCount(), source.frames()));
    }
    return runTemporal(source, names, o, [&](int t) {
        std::vector<ImageRgba8> outputs;
        for (std::size_t m = 0; m < readers.size(); ++m) {
            const io::Frame* f = readers[m].next();
            if (!f) throw Error(fmt::format("{}: ends before frame {}", given[m].second, t));
            outputs.push_back(ImageRgba8::copyOf(f->image.view()));
        }
        return outputs;
    });
}

std::string temporalMarkdown(const std::vector<TemporalResult>& results) {
    std::string s =
        "| method | flicker (levels RMS) | tPSNR (dB) | PSNR (dB) | mean frame PSNR (dB) | mean frame SSIM | mean max "
        "error (levels) | mean 99th-pct error (levels) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : results)
        s += fmt::format("| {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.4f} | {:.1f} | {:.1f} |\n", r.method,
                         r.flickerLevels, r.temporalPsnr, r.psnr, r.mean.psnr, r.mean.ssim, r.mean.maxError,
                         r.mean.p99Error);
    return s;
}

std::string temporalJson(const std::vector<TemporalResult>& results) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
    for (const auto& r : results) {
        j[r.method] = {
            {"flicker_levels", num(r.flickerLevels)}, {"temporal_psnr", num(r.temporalPsnr)}, {"psnr", num(r.psnr)}};
        for (const Metric k : kMetrics) {
            j[r.method]["mean"][metricKey(k)] = num(value(r.mean, k));
            auto& frames = j[r.method]["frames"][metricKey(k)] = nlohmann::ordered_json::array();
            for (const Scores& f : r.frames) frames.push_back(num(value(f, k)));
        }
    }
    return j.dump(2) + "\n";
}

}  // namespace ssfx::eval
