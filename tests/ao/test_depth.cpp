// Depth to camera-space z, positions and the z pyramid (src/ao/depth.cpp) on analytic depths.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/scene/analytic.hpp"

using namespace ssfx;
using namespace ssfx::ao;

TEST(Depth, ZReconstructionIsExactForAnalyticDepths) {
    for (const double zFar : {-100.0, -double(INFINITY)}) {
        Camera cam;
        cam.zNear = -0.1, cam.zFar = zFar;
        const Projection p = projection(cam, 8, 1);
        ImageF d(8, 1);
        const double zs[] = {-0.1, -0.5, -1, -3.7, -10, -42, -99.9, -99.99};  // z = zFar is d = 1: sky
        for (int i = 0; i < 8; ++i) d(i, 0) = float(zToDepth(zs[i], cam));
        const ImageF z = depthToZ(d.view(), cam);
        for (int i = 0; i < 8; ++i) {
            // The only errors allowed: storing the depth as float32 (moves z by
            // |dz/dd| * |d_float - d_exact|, dz/dd = -c0 c1 / (d c1 + c2)^2) and storing z
            // as float32 (half an ulp, < |z| 2^-24).
            const double dExact = zToDepth(zs[i], cam), dStored = d(i, 0);
            const double den = dExact * p.c1 + p.c2;
            const double bound =
                std::abs(p.c0 * p.c1 / (den * den)) * std::abs(dStored - dExact) * 1.01 + std::abs(zs[i]) * 6e-8;
            EXPECT_LE(std::abs(double(z(i, 0)) - zs[i]), bound) << zs[i];
        }
        EXPECT_EQ(z(0, 0), -0.1f);  // d = 0 is the near plane exactly
    }
    Camera inf;
    ImageF sky(1, 1, 1.0f);
    EXPECT_TRUE(std::isinf(depthToZ(sky.view(), inf)(0, 0)));
    Camera finite;  // depth 1 is nothing drawn, sky, with a finite far plane too
    finite.zFar = -50;
    EXPECT_TRUE(std::isinf(depthToZ(sky.view(), finite)(0, 0)));
}

TEST(Depth, ZIsEquationTwoInDoubleForEveryPixel) {
    // The vector rows and the per-pixel tail give eq. 2 in double rounded to float, bit for
    // bit, for row lengths around the vector widths; a bad value anywhere in a row (vector
    // part or tail) is reported with its pixel, the first one in row-major order.
    Camera cam;
    cam.zNear = -0.05;
    for (int w : {1, 7, 8, 9, 16, 17, 33, 67}) {
        const Projection p = projection(cam, w, 3);
        ImageF d(w, 3);
        unsigned s = unsigned(w);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < w; ++x) d(x, y) = float((s = s * 1664525u + 1013904223u) >> 8) / float(1 << 24);
        d(w - 1, 2) = 1.0f;  // sky
        const ImageF z = depthToZ(d.view(), cam, Exec{2});
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < w; ++x)
                ASSERT_EQ(z(x, y), float(p.c0 / (double(d(x, y)) * p.c1 + p.c2))) << w << ": " << x << "," << y;
        EXPECT_TRUE(std::isinf(z(w - 1, 2)));
        for (int bx : {0, w / 2, w - 1}) {
            ImageF bad = d;
            bad(bx, 1) = -1e-7f;
            bad(w - 1, 2) = NAN;
            try {
                depthToZ(bad.view(), cam, Exec{2});
                ADD_FAILURE() << "no error";
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find(fmt::format("pixel ({}, 1)", bx)), std::string::npos) << e.what();
            }
        }
    }
}

TEST(Depth, PositionsReprojectToTheirPixels) {
    // A point projected with the OpenGL perspective matrix lands at the pixel whose centre
    // reconstructs to it (y down in the image, up in camera space).
    Camera cam;
    cam.fovY = 0.9;
    const int w = 320, h = 200;
    const Projection p = projection(cam, w, h);
    const Vec3 pts[] = {{1.0f, 0.5f, -4.0f}, {-2.0f, -1.0f, -7.5f}, {0.0f, 0.0f, -1.0f}};
    for (const Vec3& q : pts) {
        const double ndcX = p.p00 * q.x / -q.z, ndcY = p.p11 * q.y / -q.z;
        const double px = (ndcX + 1) * w / 2, py = (1 - ndcY) * h / 2;  // y down
        const Vec3 r = reconstructPosition(p, float(px), float(py), q.z);
        EXPECT_NEAR(r.x, q.x, 1e-4);
        EXPECT_NEAR(r.y, q.y, 1e-4);
    }
    EXPECT_NEAR(p.pixelsPerMeter, h / (2 * std::tan(0.45)), 1e-3);
}

TEST(Depth, PyramidFiltersOnA4x4ByHand) {
    // z values (negative), row-major:
    const float v[16] = {-1, -2, -3, -4,  //
                         -5, -6, -7, -8,  //
                         -2, -2, -4, -4,  //
                         -8, -8, -1, -1};
    ImageF z(4, 4);
    for (int i = 0; i < 16; ++i) z(i % 4, i / 4) = v[i];
    auto level1 = [&](PyramidFilter f) { return zPyramid(z.view(), 1, f)[1]; };
    // Rotated grid: (x, y) <- (2x + (y & 1), 2y + (x & 1)):
    // (0,0) <- (0,0) = -1; (1,0) <- (2,1) = -7; (0,1) <- (1,2) = -2; (1,1) <- (3,3) = -1.
    const ImageF rg = level1(PyramidFilter::RotatedGrid);
    EXPECT_EQ(rg(0, 0), -1);
    EXPECT_EQ(rg(1, 0), -7);
    EXPECT_EQ(rg(0, 1), -2);
    EXPECT_EQ(rg(1, 1), -1);
    // Blocks: {-1,-2,-5,-6}, {-3,-4,-7,-8}, {-2,-2,-8,-8}, {-4,-4,-1,-1}.
    const ImageF mean = level1(PyramidFilter::Mean);
    EXPECT_FLOAT_EQ(mean(0, 0), -3.5f);
    EXPECT_FLOAT_EQ(mean(1, 0), -5.5f);
    EXPECT_FLOAT_EQ(mean(0, 1), -5.0f);
    const ImageF harm = level1(PyramidFilter::HarmonicMean);
    EXPECT_FLOAT_EQ(harm(0, 1), -3.2f);  // 4 / (-1/2 - 1/2 - 1/8 - 1/8) = 4 / -1.25
    EXPECT_FLOAT_EQ(level1(PyramidFilter::Min)(1, 1), -4.0f);
    EXPECT_FLOAT_EQ(level1(PyramidFilter::Max)(1, 0), -3.0f);
    // Sizes halve (rounding down, at least 1).
    ImageF odd(5, 3, -1.0f);
    const auto pyr = zPyramid(odd.view(), 3);
    ASSERT_EQ(pyr.size(), 4u);
    EXPECT_EQ(pyr[1].width(), 2);
    EXPECT_EQ(pyr[1].height(), 1);
    EXPECT_EQ(pyr[3].width(), 1);
}
