// The AlchemyAO baseline (McGuire, Osman, Bukowski, Hennessy, "The Alchemy Screen-Space
// Ambient Obscurance Algorithm", HPG 2011), as SAO's paper compares against it (spec
// sao.md "Baseline"): position and normal from the same depth buffer, but *no* z pyramid
// (every tap reads full resolution, so its cost grows with the radius), s = 12 taps on the
// same spiral, the original estimator (SAO paper eq. 1)
//   A = max(0, 1 - (2 sigma / s) * sum max(0, v.n + z_C beta) / (v.v + epsilon))^k,
// and the same separable bilateral blur (no 2x2 quad pass, which is SAO's).
#pragma once

#include <string>
#include "ssfx/ao/depth.hpp"

#include "ssfx/ao/sao.hpp"

namespace ssfx::ao {

struct AlchemyParams {
    float radius = 1.0f;     //!< m: world-space sample radius
    float sigma = 1.0f;      //!< sigma, intensity scale ("chosen for aesthetics")
    float beta = 1e-4f;      //!< bias per metre of depth (z_C beta), AlchemyAO's 10^-4
    float epsilon = 1e-4f;   //!< m^2: AlchemyAO's 0.0001
    float k = 1.0f;          //!< contrast exponent
    int numSamples = 12;     //!< s (AlchemyAO: 12)
    int numSpiralTurns = 5;  //!< spiralTurnsFor(12)
    BilateralParams blur;
    int guardBand = 0;  //!< px on each side not output
};
//! AlchemyParams' table (core/params.hpp); the defaults are the initialisers.
inline constexpr auto kAlchemyParams = concat(
    std::array{
        real<&AlchemyParams::radius>("radius", "m", 1e-6, 100, "world-space sample radius"),
        real<&AlchemyParams::sigma>("sigma", "", 0, 100, "intensity scale"),
        real<&AlchemyParams::beta>("beta", "1/m", 0, 1, "bias per metre of depth (z_C beta)"),
        real<&AlchemyParams::epsilon>("epsilon", "m^2", 1e-9, 1, "keeps the estimator finite"),
        real<&AlchemyParams::k>("k", "", 0, 10, "contrast exponent"),
        integer<&AlchemyParams::numSamples>("numSamples", "", 1, 64, "s, taps per pixel"),
        integer<&AlchemyParams::numSpiralTurns>("numSpiralTurns", "", 1, 64, "turns of the tap spiral"),
    },
    concat(bilateralRows<&AlchemyParams::blur>(),
           std::array{
               integer<&AlchemyParams::guardBand>("guardBand", "px", 0, 4096, "guard band on each side, not output")}));

void validate(const AlchemyParams& p);
//! Sets a field by name (blur fields as for SaoParams); throws ssfx::Error for an unknown one.
void setParam(AlchemyParams& p, const std::string& name, double value);

//! The sample pass's constants (see SampleConstants in sao.hpp): AlchemyAO's estimator.
SampleConstants sampleConstants(const AlchemyParams& p);

//! The raw sample pass over `region` of the z buffer (before the blur).
ImageF alchemySamplePass(ImageView<const float> z, const Projection& proj, Region region, const AlchemyParams& p,
                         const Exec& exec = {});
//! The same reading level 0 of `z` (no copy), e.g. the pyramid built for SAO.
ImageF alchemySamplePass(const ZPyramid& z, const Projection& proj, Region region, const AlchemyParams& p,
                         const Exec& exec = {});

//! The scalar oracle of alchemy() (sample pass without the vector kernel, one thread).
ImageF alchemyReference(ImageView<const float> depth, const Camera& camera, const AlchemyParams& params = {});

//! The whole baseline: depth (guard band included) -> A for the inner region.
ImageF alchemy(ImageView<const float> depth, const Camera& camera, const AlchemyParams& params = {},
               const Exec& exec = {});
//! The same, with every intermediate copied into `stages` (not null; no pyramid, no quad pass).
ImageF alchemy(ImageView<const float> depth, const Camera& camera, const AlchemyParams& params, const Exec& exec,
               AoStages* stages);

}  // namespace ssfx::ao
