// The ray-traced ground truth (src/ao/raytraced.cpp) against a quadrature of the obscurance integral.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/scene/analytic.hpp"

using namespace ssfx;
using namespace ssfx::ao;

namespace {

// Floor points in front of the corner's wall: the wall is the only occluder. For a floor
// point at distance delta from the wall, rays with w.z < 0 hit it at d = delta / -w.z;
// A = 1 - (1/pi) * integral rho(d) cos(theta) dw, integrated here on a fine midpoint grid
// in (theta, phi) about the floor normal, independently of raytraced(), with rho(d) =
// (1 - d^2)^3 (obscurance) or 1 (binary) for d < r = 1 m. Tolerance 0.005: 4096 rays of a
// rotated Hammersley set (its error is measured at about 1e-3 here).
void expectQuadrature(Visibility visibility) {
    Camera cam;
    const int w = 32, h = 24;
    const auto scene = scene::cornerScene();
    RaytracedParams p;
    p.raysPerPixel = 4096;
    p.visibility = visibility;
    const ImageF a = raytraced(scene, cam, w, h, p);
    const Projection proj = projection(cam, w, h);
    int checked = 0;
    double lowest = 1;
    for (int y = h / 2; y < h; ++y) {
        const Vec3d dir = primaryRay(proj, 16.5f, float(y) + 0.5f);
        const double t = -1.0 / dir.y;                    // the floor y = -1
        if (!(dir.y < 0) || t * -dir.z > 4.99) continue;  // only floor pixels
        const double delta = 5.0 - t * -dir.z;            // distance to the wall z = -5
        const int nt = 400, np = 800;
        double occ = 0;
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j) {
                const double th = (i + 0.5) / nt * M_PI / 2, ph = (j + 0.5) / np * 2 * M_PI;
                const double wz = std::sin(th) * std::sin(ph);
                if (wz >= 0) continue;
                const double d = delta / -wz;
                if (d >= 1.0) continue;
                const double q = 1 - d * d;
                const double rho = visibility == Visibility::Binary ? 1.0 : q * q * q;
                occ += rho * std::cos(th) * std::sin(th) * (M_PI / 2 / nt) * (2 * M_PI / np);
            }
        EXPECT_NEAR(a(16, y), 1 - occ / M_PI, 0.005) << "row " << y << " delta " << delta;
        lowest = std::min(lowest, 1 - occ / M_PI);
        ++checked;
    }
    EXPECT_GE(checked, 3);
    EXPECT_LT(lowest, 0.97);  // rows close enough to the wall to be occluded (obscurance: 0.93)
}

}  // namespace

TEST(Raytraced, MatchesAQuadratureOfTheObscuranceIntegral) {
    expectQuadrature(Visibility::Obscurance);
    // An open plane: nothing within the radius, A = 1 exactly, under either definition.
    Camera cam;
    scene::AnalyticScene plane;
    plane.addPlane({0, 0, -3}, {0, 0, 1});
    const ImageF open = raytraced(plane, cam, 16, 12, {});
    for (float v : open.pixels()) ASSERT_EQ(v, 1.0f);
    RaytracedParams binary;
    binary.visibility = Visibility::Binary;
    const ImageF openBinary = raytraced(plane, cam, 16, 12, binary);
    for (float v : openBinary.pixels()) ASSERT_EQ(v, 1.0f);
}

TEST(Raytraced, BinaryVisibilityMatchesAQuadratureOfTheCosineWeightedVisibleFraction) {
    // GTAO's definition (spec gtao.md section 12): a hit within r occludes fully.
    expectQuadrature(Visibility::Binary);
    // It occludes at least as much as the obscurance (rho = 1 >= (1 - (d/r)^2)^3), ray for ray.
    Camera cam;
    const auto scene = scene::cornerScene();
    RaytracedParams p;
    p.raysPerPixel = 64;
    const ImageF obs = raytraced(scene, cam, 32, 24, p);
    p.visibility = Visibility::Binary;
    const ImageF ao = raytraced(scene, cam, 32, 24, p);
    int lower = 0;
    for (std::size_t i = 0; i < obs.pixels().size(); ++i) {
        EXPECT_LE(ao.pixels()[i], obs.pixels()[i]);
        lower += ao.pixels()[i] < obs.pixels()[i];
    }
    EXPECT_GT(lower, 0);
}

TEST(Raytraced, OneRaySetGivesEveryTruthsBytes) {
    // raytracedSet casts each ray once, to the largest radius, and scores every (radius,
    // definition) from that hit; each image must be the bytes of its own raytraced() call,
    // which casts only as far as its own radius.
    Camera cam;
    const auto scene = scene::roomScene();
    std::vector<RaytracedParams> truths;
    for (float r : {0.5f, 1.0f, 2.0f})
        for (Visibility v : {Visibility::Obscurance, Visibility::Binary}) {
            RaytracedParams p;
            p.radius = r, p.visibility = v, p.raysPerPixel = 16, p.guardBand = 2;
            truths.push_back(p);
        }
    const std::vector<ImageF> set = raytracedSet(scene, cam, 40, 30, truths, Exec{2});
    ASSERT_EQ(set.size(), truths.size());
    for (std::size_t k = 0; k < truths.size(); ++k) {
        const ImageF one = raytraced(scene, cam, 40, 30, truths[k], Exec{1});
        ASSERT_EQ(set[k].width(), 36);
        EXPECT_TRUE(std::equal(one.pixels().begin(), one.pixels().end(), set[k].pixels().begin())) << k;
    }
    // A larger radius finds more occluders: the binary truth at 2 m is the darkest somewhere.
    EXPECT_LT(*std::min_element(set[5].pixels().begin(), set[5].pixels().end()),
              *std::min_element(set[1].pixels().begin(), set[1].pixels().end()));
    // Truths from one set share the ray count and guard band.
    truths[1].raysPerPixel = 32;
    EXPECT_THROW(raytracedSet(scene, cam, 40, 30, truths), Error);
    EXPECT_THROW(raytracedSet(scene, cam, 40, 30, {}), Error);
}
