// The Vulkan renderer against analytic geometry: depth, positions and normals of planes and
// a sphere for every depth format, the guard band, the G-buffer, two-sided normals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"
#include "tests/render/render_fixture.hpp"

namespace ssfx::test {
namespace {

using scene::Scene;
using scene::Vertex;
using scene::View;

// Camera at the origin looking down -z (world = camera space), 60 degrees.
View originView(double zFar = INFINITY) {
    View v;
    v.eye = {0, 0, 0};
    v.target = {0, 0, -1};
    v.fovYDeg = 60;
    v.zNear = 0.1;
    v.zFar = zFar;
    return v;
}

void addQuad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    const auto base = std::uint32_t(s.vertices.size());
    for (glm::vec3 p : {a, b, c, d}) s.vertices.push_back({p, n, glm::vec2(p.x, p.y), 0});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) s.indices.push_back(base + i);
}

Scene planeScene(glm::vec3 normal, float offset) {
    // The plane dot(normal, p) = offset, as one big quad around the view axis.
    Scene s;
    s.name = "plane";
    s.materials.push_back({"grey", glm::vec3(0.5f), -1});
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 t = glm::normalize(glm::cross(n, std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const glm::vec3 o = n * offset;
    const float r = 200.0f;
    addQuad(s, o - r * t - r * b, o + r * t - r * b, o + r * t + r * b, o - r * t + r * b, n);
    return s;
}

Scene sphereScene(glm::vec3 centre, float radius, int segments) {
    Scene s;
    s.name = "sphere";
    s.materials.push_back({"grey", glm::vec3(0.5f), -1});
    const int rings = segments / 2;
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= segments; ++i) {
            const double th = std::numbers::pi * j / rings, ph = 2 * std::numbers::pi * i / segments;
            const glm::vec3 n(float(std::sin(th) * std::cos(ph)), float(std::cos(th)),
                              float(std::sin(th) * std::sin(ph)));
            s.vertices.push_back({centre + radius * n, n, glm::vec2(float(i) / segments, float(j) / rings), 0});
        }
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const auto a = std::uint32_t(j * (segments + 1) + i), c = a + std::uint32_t(segments + 1);
            for (std::uint32_t k : {a, c, a + 1, a + 1, c, c + 1}) s.indices.push_back(k);
        }
    return s;
}

double stepOf(DepthFormat f, double d) {
    switch (f) {
        case DepthFormat::D16: return 1.0 / 65535.0;
        case DepthFormat::D24: return 1.0 / 16777215.0;
        default: return std::ldexp(1.0, std::ilogb(std::max(d, 1e-30)) - 23);  // one float ulp
    }
}

const DepthFormat kFormats[] = {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F};
const char* kFormatNames[] = {"D16", "D24", "D32F"};

TEST_F(RenderTest, FrontoParallelPlaneHasTheAnalyticDepthInEveryFormat) {
    const double dist = 3.0;
    const Scene s = planeScene({0, 0, 1}, float(-dist));
    for (double zFar : {100.0, double(INFINITY)}) {
        for (int f = 0; f < 3; ++f) {
            SCOPED_TRACE(testing::Message() << kFormatNames[f] << " far " << zFar);
            const auto r = renderer().renderDepth(s, originView(zFar), 64, 48, kFormats[f]);
            const double exact = ao::zToDepth(-dist, r.camera.camera);
            // The rasteriser interpolates float z/w and the format rounds it: one format step
            // plus a few float32 ulps of the interpolation.
            const double tol = stepOf(kFormats[f], exact) + 4.0 * std::ldexp(1.0, -24);
            double worst = 0;
            for (float d : r.depth.pixels()) worst = std::max(worst, std::abs(double(d) - exact));
            EXPECT_LE(worst, tol) << "exact depth " << exact;
            // The reconstructed z (sao.md eq. 2) is within the format's own precision.
            const ImageF z = ao::depthToZ(r.depth.view(), r.camera.camera);
            const double dzdd = dist * dist / (-r.camera.camera.zNear) * (std::isinf(zFar) ? 1.0 : (1.0 - 0.1 / zFar));
            for (float zz : z.pixels()) ASSERT_NEAR(zz, -dist, dzdd * tol * 1.01 + 1e-6);
        }
    }
}

TEST_F(RenderTest, ReconstructedPositionsLieOnATiltedPlane) {
    // Plane through (0, -1, 0)-ish, tilted in x and y so a wrong sign of either axis or a wrong
    // field of view moves the reconstructed points off it.
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    const float offset = -1.0f;
    const Scene s = planeScene(n, offset);
    View v = originView();
    v.target = {0.2, -0.4, -1};
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE(kFormatNames[f]);
        const auto r = renderer().renderDepth(s, v, 80, 60, kFormats[f], 8);
        const auto p = ssfx::projection(r.camera.camera, r.camera.bufferWidth(), r.camera.bufferHeight());
        const ImageF z = ao::depthToZ(r.depth.view(), r.camera.camera);
        const glm::dmat4 toWorld = glm::inverse(r.camera.view);
        int hits = 0;
        double worst = 0;
        for (int y = 0; y < z.height(); ++y)
            for (int x = 0; x < z.width(); ++x) {
                if (!std::isfinite(z(x, y)) || z(x, y) < -30.0f) continue;  // far away: precision-limited
                const auto c = ao::reconstructPosition(p, float(x) + 0.5f, float(y) + 0.5f, z(x, y));
                const glm::dvec3 w = glm::dvec3(toWorld * glm::dvec4(c.x, c.y, c.z, 1.0));
                worst = std::max(worst, std::abs(glm::dot(glm::dvec3(n), w) - offset) / std::abs(double(c.z)));
                ++hits;
            }
        EXPECT_GT(hits, 80 * 60 / 3);
        // Relative to the distance: D16 at 30 m is the coarsest (z step ~ z^2 / (n 65535)).
        EXPECT_LT(worst, kFormats[f] == DepthFormat::D16 ? 0.15 : 2e-3);
    }
}

TEST_F(RenderTest, SphereDepthAndNormalsMatchTheAnalyticSphere) {
    const glm::vec3 centre(0.3f, -0.2f, -4.0f);
    const Scene s = sphereScene(centre, 1.0f, 128);
    const View v = originView(50.0);
    const auto g = renderer().renderGBuffer(s, v, 96, 96, 1);
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE(kFormatNames[f]);
        const auto d = renderer().renderDepth(s, v, 96, 96, kFormats[f]);
        if (kFormats[f] == DepthFormat::D32F) {
            ASSERT_EQ(d.depth, g.depth);  // same rasterisation, same depth
        }
        const auto p = ssfx::projection(d.camera.camera, 96, 96);
        const ImageF z = ao::depthToZ(d.depth.view(), d.camera.camera);
        // 128 segments: the chord lies at most 1 - cos(pi / 128) = 3e-4 inside the sphere; the
        // format adds its z step at ~5 m (D16: z^2 / (n (2^16 - 1)) = 3.8 mm; D24: 15 um).
        const double tol = 1e-3 + (kFormats[f] == DepthFormat::D16 ? 4e-3 : 0.0);
        int inside = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                if (d.depth(x, y) == 1.0f) {
                    if (f == 2) {
                        EXPECT_EQ(g.material[g.index(x, y)], scene::GBuffer::kNoMaterial);
                    }
                    continue;
                }
                ++inside;
                const auto c = ao::reconstructPosition(p, float(x) + 0.5f, float(y) + 0.5f, z(x, y));
                const glm::vec3 q(c.x, c.y, c.z);
                EXPECT_NEAR(glm::length(q - centre), 1.0, tol) << x << "," << y;
                if (f != 2) continue;
                const glm::vec3 analytic = glm::normalize(q - centre);
                const glm::vec3 normal = g.normal[g.index(x, y)];
                // Interpolated vertex normals and 16-bit snorm storage: within 1.5 degrees.
                EXPECT_GT(glm::dot(normal, analytic), std::cos(1.5 * std::numbers::pi / 180)) << x << "," << y;
                EXPECT_EQ(g.material[g.index(x, y)], 0);
                EXPECT_EQ(g.layer[g.index(x, y)], -1);
            }
        // The sphere's disc: angular radius asin(1 / |centre|), in pixels through the projection.
        const double rPix = std::tan(std::asin(1.0 / glm::length(centre))) * 48.0 / std::tan(std::numbers::pi / 6);
        EXPECT_NEAR(inside, std::numbers::pi * rPix * rPix, 0.05 * std::numbers::pi * rPix * rPix);
    }
}

TEST_F(RenderTest, GuardBandWidensTheViewWithoutMovingTheImage) {
    const Scene s = sphereScene({0.2f, 0.1f, -3.0f}, 1.0f, 64);
    const View v = originView(20.0);
    const auto plain = renderer().renderDepth(s, v, 64, 40, DepthFormat::D32F, 0);
    const auto guarded = renderer().renderDepth(s, v, 64, 40, DepthFormat::D32F, 12);
    ASSERT_EQ(guarded.depth.width(), 64 + 24);
    ASSERT_EQ(guarded.depth.height(), 40 + 24);
    EXPECT_EQ(guarded.camera.guard, 12);
    int differ = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 64; ++x) {
            const float a = plain.depth(x, y), b = guarded.depth(x + 12, y + 12);
            // The two projections differ in float rounding only: depth within a few ulps, and
            // coverage can flip only on silhouette pixels.
            if (a == 1.0f || b == 1.0f)
                differ += a != b;
            else
                EXPECT_NEAR(a, b, 4e-7) << x << "," << y;
        }
    EXPECT_LE(differ, 4);
}

TEST_F(RenderTest, GBufferAtM2IsThe2xRenderAndAveragesToThe1xOne) {
    const Scene s = sphereScene({0.0f, 0.0f, -3.0f}, 1.0f, 96);
    const View v = originView(20.0);
    const auto g2 = renderer().renderGBuffer(s, v, 48, 48, 2);
    const auto g1 = renderer().renderGBuffer(s, v, 48, 48, 1);
    const auto d2 = renderer().renderDepth(s, v, 96, 96, DepthFormat::D32F);
    ASSERT_EQ(g2.sampleWidth(), 96);
    EXPECT_EQ(g2.depth, d2.depth);  // the supersampled G-buffer is a 2x render
    int compared = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) {
            glm::vec3 n(0.0f);
            bool full = g1.depth(x, y) < 1.0f;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const std::size_t k = g2.index(2 * x + i, 2 * y + j);
                    full = full && g2.depth(2 * x + i, 2 * y + j) < 1.0f;
                    n += g2.normal[k];
                }
            if (!full) continue;
            ++compared;
            // Averaging the four samples of a smooth surface approximates the pixel centre's
            // normal: within 2 degrees. (Texture derivatives are piecewise constant per 2x2
            // quad and triangle, so they are checked on a plane, in the next test.)
            const glm::vec3 n1 = g1.normal[g1.index(x, y)];
            EXPECT_GT(glm::dot(glm::normalize(n), n1), std::cos(2 * std::numbers::pi / 180)) << x << "," << y;
        }
    EXPECT_GT(compared, 600);
}

TEST_F(RenderTest, TextureDerivativesArePerFinalImagePixel) {
    // A fronto-parallel plane at 2 m with u = world x: du/dx per final pixel = 2 * 2 tan(30) / h.
    const Scene s = planeScene({0, 0, 1}, -2.0f);
    for (int m = 1; m <= 4; ++m) {
        const auto g = renderer().renderGBuffer(s, originView(), 32, 32, m);
        const double expected = 2.0 * 2.0 * std::tan(std::numbers::pi / 6) / 32.0;
        const glm::vec4 d = g.uvGrad[g.index(g.sampleWidth() / 2, g.sampleHeight() / 2)];
        EXPECT_NEAR(std::abs(d.x), expected, 1e-3 * expected) << "m = " << m;
        EXPECT_NEAR(d.y, 0.0, 1e-6);
        EXPECT_NEAR(d.z, 0.0, 1e-6);
        EXPECT_NEAR(std::abs(d.w), expected, 1e-3 * expected) << "m = " << m;
    }
}

TEST_F(RenderTest, SurfacesAreTwoSidedWithNormalsTowardsTheCamera) {
    // The same quad with its normal towards the camera and away from it.
    for (float facing : {1.0f, -1.0f}) {
        Scene s;
        s.name = "quad";
        s.materials.push_back({"m", glm::vec3(1.0f), -1});
        const glm::vec3 a(-1, -1, -2), b(1, -1, -2), c(1, 1, -2), d(-1, 1, -2);
        if (facing > 0)
            addQuad(s, a, b, c, d, {0, 0, 1});
        else
            addQuad(s, a, d, c, b, {0, 0, -1});
        const auto g = renderer().renderGBuffer(s, originView(), 16, 16, 1);
        const glm::vec3 n = g.normal[g.index(8, 8)];
        EXPECT_NEAR(n.z, 1.0f, 1e-4f) << "facing " << facing;
        const auto col = renderer().renderColor(s, originView(), 16, 16);
        EXPECT_GT(int(col.color(8, 8).r), 0);
    }
}

TEST_F(RenderTest, RenderingIsDeterministic) {
    const Scene s = scene::atrium();
    const auto a = renderer().renderColor(s, s.view("colonnade"), 96, 64);
    const auto b = renderer().renderColor(s, s.view("colonnade"), 96, 64);
    EXPECT_EQ(a.color, b.color);
    const auto da = renderer().renderDepth(s, s.view("nave"), 96, 64, DepthFormat::D24, 8);
    const auto db = renderer().renderDepth(s, s.view("nave"), 96, 64, DepthFormat::D24, 8);
    EXPECT_EQ(da.depth, db.depth);
}

TEST_F(RenderTest, BuiltInScenesRender) {
    for (const auto& name : scene::builtinScenes()) {
        const Scene s = scene::builtinScene(name);
        for (const auto& [viewName, view] : s.views) {
            SCOPED_TRACE(name + "/" + viewName);
            const auto d = renderer().renderDepth(s, view, 64, 36, DepthFormat::D32F);
            int geometry = 0;
            for (float x : d.depth.pixels()) geometry += x < 1.0f;
            EXPECT_GT(geometry, 64 * 36 / 4);  // every view looks at the scene
        }
    }
    // The atrium's nave: sky at the top centre, floor at the bottom, textures in the G-buffer.
    const Scene a = scene::atrium();
    const auto d = renderer().renderDepth(a, a.view("nave"), 96, 54);
    EXPECT_EQ(d.depth(48, 1), 1.0f);
    EXPECT_LT(d.depth(48, 52), 1.0f);
    const auto g = renderer().renderGBuffer(a, a.view("nave"), 96, 54, 2);
    int textured = 0;
    for (auto l : g.layer) textured += l >= 0;
    EXPECT_GT(textured, int(g.layer.size()) / 4);
}

TEST_F(RenderTest, NothingDrawnIsSkyForSaoWithAFiniteFarPlane) {
    // The renderer clears depth to 1 where nothing is drawn; with a finite far plane that
    // background was a wall at zFar that occluded itself along the roof line (922 pixels off
    // by more than 8 levels at 480x270). Now it is sky: A = 1 there, and the two far planes
    // agree on the geometry within the D32F precision at the nave's distances.
    const Scene a = scene::atrium();
    View finite = a.view("nave"), infinite = finite;
    finite.zFar = 60, infinite.zFar = INFINITY;
    const int w = 192, h = 108, g = 16;
    const auto rf = renderer().renderDepth(a, finite, w, h, DepthFormat::D32F, g);
    const auto ri = renderer().renderDepth(a, infinite, w, h, DepthFormat::D32F, g);
    ao::SaoParams p;
    p.guardBand = g;
    const ImageF af = ao::sao(rf.depth.view(), rf.camera.camera, p), ai = ao::sao(ri.depth.view(), ri.camera.camera, p);
    int sky = 0, far8 = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (rf.depth(x + g, y + g) == 1.0f) {
                ++sky;
                EXPECT_EQ(af(x, y), 1.0f) << x << "," << y;
            }
            far8 += std::fabs(af(x, y) - ai(x, y)) * 255.0f > 8.0f;
        }
    EXPECT_GT(sky, w * h / 20);
    EXPECT_LE(far8, w * h / 1000);  // a few distant pixels, from the depth precision at up to 60 m
}

TEST_F(RenderTest, BadRequestsAreRefused) {
    const Scene s = scene::cornellBox();
    EXPECT_THROW(renderer().renderDepth(s, s.view("front"), 0, 10), Error);
    EXPECT_THROW(renderer().renderDepth(s, s.view("front"), 100000, 100000), Error);
    EXPECT_THROW(renderer().renderDepth(s, s.view("front"), 20000, 20), Error);  // over the device's 2-D limit
    EXPECT_THROW(renderer().renderGBuffer(s, s.view("front"), 10, 10, 5), Error);
    EXPECT_THROW(renderer().renderColor(s, s.view("front"), 10, 10, 0), Error);
    View bad = s.view("front");
    bad.zNear = 0;
    EXPECT_THROW(renderer().renderDepth(s, bad, 10, 10), Error);
    bad = s.view("front");
    bad.target = bad.eye;
    EXPECT_THROW(renderer().renderDepth(s, bad, 10, 10), Error);
    Scene broken = s;
    broken.indices.push_back(99999);
    broken.indices.push_back(0);
    broken.indices.push_back(1);
    EXPECT_THROW(renderer().renderDepth(broken, s.view("front"), 10, 10), Error);
    EXPECT_THROW(render::Renderer({"no-such-device-name", false}), Error);
    EXPECT_THROW(render::Renderer({"99", false}), Error);
}

}  // namespace
}  // namespace ssfx::test
