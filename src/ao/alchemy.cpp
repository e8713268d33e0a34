// The AlchemyAO baseline (see alchemy.hpp).
#include "ssfx/ao/alchemy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "src/ao/ao_sampling.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::ao {

namespace {

// SAO paper eq. 1 (AlchemyAO's estimator).
struct AlchemyEstimator {
    float beta, epsilon, scale, k;
    float term(float vv, float vn, float zc) const { return std::max(0.0f, vn + zc * beta) / (vv + epsilon); }
    float finish(float sum) const { return post(std::max(0.0f, 1.0f - scale * sum)); }
    float post(float a) const { return k == 1.0f ? a : std::pow(a, k); }
    void fill(detail::SimdSampleInput& in) const {
        in.estimator = 1, in.beta = beta, in.epsilon = epsilon, in.scale = scale;
    }
};

}  // namespace

void validate(const AlchemyParams& p) {
    validateParams(kAlchemyParams, &p, "alchemy");
    detail::checkBilateral("alchemy", p.blur);
}

void setParam(AlchemyParams& p, const std::string& name, double v) {
    ssfx::setParam(kAlchemyParams, &p, "alchemy", name, v);
}

SampleConstants sampleConstants(const AlchemyParams& p) {
    validate(p);
    SampleConstants k;
    k.bias = p.beta, k.epsilon = p.epsilon, k.scale = 2.0f * p.sigma / float(p.numSamples), k.exponent = p.k;
    detail::spiral({p.numSamples, p.numSpiralTurns, 0, 0, p.radius, false, false}, k.alpha, k.dirX, k.dirY, k.tapAngle);
    return k;
}

namespace {
ImageF alchemyImpl(ImageView<const float> depth, const Camera& camera, const AlchemyParams& p, const Exec& exec,
                   bool vector, AoStages* stages = nullptr);
ImageF samplePassImpl(const ZPyramid& z, const Projection& proj, Region region, const AlchemyParams& p,
                      const Exec& exec, bool vector);
}  // namespace

ImageF alchemySamplePass(ImageView<const float> z, const Projection& proj, Region region, const AlchemyParams& p,
                         const Exec& exec) {
    thread_local ZPyramid level0;
    zPyramid(z, 0, PyramidFilter::RotatedGrid, level0, exec);
    return samplePassImpl(level0, proj, region, p, exec, true);
}

ImageF alchemySamplePass(const ZPyramid& z, const Projection& proj, Region region, const AlchemyParams& p,
                         const Exec& exec) {
    if (z.levels() == 0) throw Error("alchemy: empty z buffer");
    return samplePassImpl(z, proj, region, p, exec, true);
}

ImageF alchemyReference(ImageView<const float> depth, const Camera& camera, const AlchemyParams& p) {
    return alchemyImpl(depth, camera, p, Exec{1}, false);
}

ImageF alchemy(ImageView<const float> depth, const Camera& camera, const AlchemyParams& p, const Exec& exec) {
    return alchemyImpl(depth, camera, p, exec, true);
}

ImageF alchemy(ImageView<const float> depth, const Camera& camera, const AlchemyParams& p, const Exec& exec,
               AoStages* stages) {
    if (!stages) throw Error("alchemy: no AoStages to fill");
    return alchemyImpl(depth, camera, p, exec, true, stages);
}

namespace {
ImageF samplePassImpl(const ZPyramid& level0, const Projection& proj, Region region, const AlchemyParams& p,
                      const Exec& exec, bool vector) {
    const SampleConstants k = sampleConstants(p);
    const AlchemyEstimator est{k.bias, k.epsilon, k.scale, k.exponent};
    const detail::SampleSetup setup{p.numSamples, p.numSpiralTurns, 0, 0, p.radius, false, vector};
    ImageF out;
    detail::samplePass(level0, proj, region, setup, est, exec, out);
    return out;
}

ImageF alchemyImpl(ImageView<const float> depth, const Camera& camera, const AlchemyParams& p, const Exec& exec,
                   bool vector, AoStages* stages) {
    validate(p);
    const int g = p.guardBand;
    if (depth.width() <= 2 * g || depth.height() <= 2 * g)
        throw Error(fmt::format("alchemy: a {}x{} depth buffer has no pixels inside a guard band of {}", depth.width(),
                                depth.height(), g));
    const Projection proj = projection(camera, depth.width(), depth.height());
    // z written straight into the buffer the sample pass gathers from (kept per thread).
    thread_local ZPyramid level0;
    level0.shape(depth.width(), depth.height(), 0);
    depthToZ(depth, camera, level0.level(0), exec);
    const ImageView<const float> z = std::as_const(level0).level(0);
    const Region out{g, g, depth.width() - 2 * g, depth.height() - 2 * g};
    ImageF a = samplePassImpl(level0, proj, out, p, exec, vector);
    ImageF h = bilateralPass(a, z, out, p.blur, true, exec);
    ImageF result = bilateralPass(h, z, out, p.blur, false, exec);
    if (stages) {
        *stages = AoStages{};
        stages->z = ImageF(z.width(), z.height());
        for (int y = 0; y < z.height(); ++y) std::copy(z.row(y), z.row(y) + z.width(), &stages->z(0, y));
        stages->work = out, stages->raw = std::move(a), stages->horizontal = std::move(h), stages->result = result;
    }
    return result;
}
}  // namespace

}  // namespace ssfx::ao
