// Ray-traced ground truth for ambient obscurance (spec sao.md "Beyond the paper"): for
// each pixel's surface point (the primary ray's hit through the pixel centre, with the
// geometry's true normal), the distance-limited integral over the hemisphere
//   A = 1 - integral over the hemisphere of rho(d(w)) (n.w) / pi dw,
// with one of two definitions of what a hit at distance d takes away (`visibility`):
//   obscurance (the default): rho(d) = (1 - (d / r)^2)^3 for d < r, else 0, the smooth
//     falloff of SAO's updated estimator (spec gtao.md section 12, A_obs);
//   binary: rho(d) = 1 for d < r, else 0: the cosine-weighted visible fraction with a hard
//     cut at r, GTAO's definition of ambient occlusion (spec gtao.md sections 2 and 12, A_ao).
// Estimated with cosine-weighted rays: a
// Hammersley set of N directions per pixel, rotated per pixel by a hash (Cranley-Patterson),
// so the estimate is deterministic and its noise far below a random set's.
//
// The geometry comes through RayScene: analytic scenes (ssfx/scene/analytic.hpp) now,
// Embree meshes with the scene renderer.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <vector>

#include <cstdint>

#include "ssfx/ao/depth.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/params.hpp"
#include "ssfx/core/progress.hpp"

namespace ssfx::ao {

struct Vec3d {
    double x, y, z;
};

struct RayHit {
    double t;      //!< distance along the (unit) ray direction
    Vec3d normal;  //!< unit geometric normal facing the ray's origin side
};

//! Geometry that rays can be cast against (camera space, metres).
class RayScene {
public:
    virtual ~RayScene() = default;
    //! The nearest hit with tMin < t < tMax, or t = +infinity when there is none.
    //! `dir` is a unit vector.
    virtual RayHit intersect(const Vec3d& origin, const Vec3d& dir, double tMin, double tMax) const = 0;
    //! Secondary rays start this far (times max(1, distance from the camera)) off the surface,
    //! above the intersector's own rounding: exact analytic geometry needs little, float
    //! triangle intersectors more.
    virtual double surfaceOffset() const { return 1e-6; }
};

//! What a hit within r takes away (see the top of this file).
enum class Visibility {
    Obscurance,  //!< SAO's falloff weight (1 - (d / r)^2)^3: A_obs
    Binary,      //!< any hit within r occludes fully: A_ao, GTAO's definition
};
inline constexpr std::array<std::string_view, 2> kVisibilityNames{"obscurance", "binary"};

struct RaytracedParams {
    float radius = 1.0f;     //!< m: r, as SAO's
    int raysPerPixel = 256;  //!< cosine-weighted rays per pixel
    int guardBand = 0;       //!< px on each side not output (as SAO's)
    Visibility visibility = Visibility::Obscurance;
};
//! RaytracedParams' table (core/params.hpp); the defaults are the initialisers.
inline constexpr std::array kRaytracedParams{
    real<&RaytracedParams::radius>("radius", "m", 1e-6, 100, "occlusion radius r, as SAO's"),
    integer<&RaytracedParams::raysPerPixel>("raysPerPixel", "", 1, 65536, "cosine-weighted rays per pixel"),
    integer<&RaytracedParams::guardBand>("guardBand", "px", 0, 4096, "guard band on each side, not output"),
    choice<&RaytracedParams::visibility>("visibility", kVisibilityNames,
                                         "obscurance: a hit at d < r takes away (1 - (d/r)^2)^3, SAO's falloff; "
                                         "binary: any hit within r occludes fully (GTAO's ambient occlusion)"),
};
//! Throws ssfx::Error naming the first field outside its range (kRaytracedParams).
void validate(const RaytracedParams& p);

//! A for every pixel of the inner region of a width x height image seen by `camera`.
//! Sky pixels (no primary hit, or the hit at or beyond a finite far plane, where a
//! rasteriser leaves the cleared depth 1) are 1. `progress` hears the rows done.
ImageF raytraced(const RayScene& scene, const Camera& camera, int width, int height, const RaytracedParams& params = {},
                 const Exec& exec = {}, const ProgressFn& progress = {});

//! Several truths from one set of rays: image k is what raytraced() gives with truths[k]
//! (same rays, same bytes), for the cost of one cast per ray to the largest radius. The
//! truths share raysPerPixel and guardBand (else ssfx::Error).
std::vector<ImageF> raytracedSet(const RayScene& scene, const Camera& camera, int width, int height,
                                 std::span<const RaytracedParams> truths, const Exec& exec = {},
                                 const ProgressFn& progress = {});

//! The primary ray through pixel centre (px, py) (unit direction, from the origin).
Vec3d primaryRay(const Projection& proj, float px, float py);

}  // namespace ssfx::ao
