// Camera paths (scene::CameraPath, scene::orbit): interpolation through the keyframes, the
// orbit, and bad files refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ssfx/core/error.hpp"
#include "ssfx/scene/camera_path.hpp"

namespace ssfx::scene {
namespace {

const char* kPath = R"({"keyframes": [
  {"position": [0, 1, 5], "target": [0, 1, 0], "fov": 60},
  {"position": [5, 1, 0], "target": [0, 1, 0], "fov": 50},
  {"position": [0, 1, -5], "target": [0, 0, 0], "fov": 40}]})";

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(CameraPath, PassesThroughEveryKeyframeAndKeepsTheBasePlanes) {
    View base;
    base.zNear = 0.25;
    base.zFar = 40;
    const CameraPath path = parseCameraPath(kPath, "path.json", base);
    for (std::size_t i = 0; i < 3; ++i) {
        const View v = path.at(double(i));  // no "time": keyframe i at time i
        expectNear(v.eye, path.keyframes()[i].position);
        expectNear(v.target, path.keyframes()[i].target);
        EXPECT_DOUBLE_EQ(v.fovYDeg, path.keyframes()[i].fovYDeg);
        EXPECT_EQ(v.zNear, 0.25);
        EXPECT_EQ(v.zFar, 40);
    }
    // Halfway along the first segment: fov linear; the Catmull-Rom position by its formula,
    // (p0 + p1) / 2 + (m0 - m1) / 8 with m0 = p1 - p0, m1 = (p2 - p0) / 2.
    const View mid = path.at(0.5);
    EXPECT_DOUBLE_EQ(mid.fovYDeg, 55.0);
    const glm::dvec3 p0(0, 1, 5), p1(5, 1, 0), p2(0, 1, -5);
    expectNear(mid.eye, (p0 + p1) * 0.5 + ((p1 - p0) - (p2 - p0) * 0.5) / 8.0);
    // Times outside the keyframes clamp; sample() spans first to last evenly.
    expectNear(path.at(-3).eye, p0);
    expectNear(path.at(9).eye, p2);
    const auto views = path.sample(5);
    ASSERT_EQ(views.size(), 5u);
    expectNear(views[0].eye, p0);
    expectNear(views[2].eye, p1);
    expectNear(views[4].eye, p2);
    EXPECT_EQ(path.sample(1).size(), 1u);
}

TEST(CameraPath, TimesSpaceTheKeyframes) {
    const CameraPath path = parseCameraPath(
        R"({"keyframes": [{"position": [0,0,1], "target": [0,0,0], "fov": 30, "time": 0},
                          {"position": [0,0,2], "target": [0,0,0], "fov": 90, "time": 4}]})",
        "timed", View{});
    EXPECT_DOUBLE_EQ(path.at(1).fovYDeg, 45.0);
    EXPECT_DOUBLE_EQ(path.sample(3)[1].fovYDeg, 60.0);  // time 2
}

TEST(CameraPath, OrbitTurnsAFullCircleAroundTheTarget) {
    View base;
    base.eye = {3, 2, 4};
    base.target = {0, 1, 0};
    const auto views = orbit(base, 8);
    ASSERT_EQ(views.size(), 8u);
    expectNear(views[0].eye, base.eye);
    for (const View& v : views) {
        EXPECT_NEAR(v.eye.y, 2.0, 1e-12);                       // the same height
        EXPECT_NEAR(std::hypot(v.eye.x, v.eye.z), 5.0, 1e-12);  // the same distance from the axis
        expectNear(v.target, base.target);
    }
    expectNear(views[4].eye, {-3, 2, -4}, 1e-12);  // half a turn
}

TEST(CameraPath, BadFilesAreRefusedByName) {
    const auto refused = [](const std::string& text, const char* words) {
        try {
            parseCameraPath(text, "p.json", View{});
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("p.json"), std::string::npos) << m;
            EXPECT_NE(m.find(words), std::string::npos) << m;
        }
    };
    const std::string k = R"({"position": [0,0,1], "target": [0,0,0], "fov": 60})";
    refused(R"({"keyframes": [)" + k + "]}", "at least two keyframes");
    refused(R"({"keyframes": []})", "at least two keyframes");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,NaN], "target": [0,0,0], "fov": 60}]})",
            "not valid JSON");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,1e999], "target": [0,0,0], "fov": 60}]})", "overflow");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,1], "target": [0,0,1], "fov": 60}]})",
            "position equals target");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,2], "target": [0,0,0], "fov": 180}]})", "fov");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,2], "target": [0,0,0]}]})", "no 'fov'");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,0,2], "target": [0,0,0], "fov": 60, "fox": 1}]})",
            "unknown key 'fox'");
    refused(R"({"keyframes": [)" + k + R"(, {"position": [0,2], "target": [0,0,0], "fov": 60}]})", "three numbers");
    refused(R"({"keyframes": [{"position": [0,0,1], "target": [0,0,0], "fov": 60, "time": 1},
                              {"position": [0,0,2], "target": [0,0,0], "fov": 60, "time": 1}]})",
            "does not come after");
    refused(R"({"keyframes": [{"position": [0,0,1], "target": [0,0,0], "fov": 60, "time": 1}, )" + k + "]}",
            "all or none");
    refused(R"({"frames": 3, "keyframes": []})", "unknown key 'frames'");
    refused("[1, 2]", "'keyframes' array");
    EXPECT_THROW(readCameraPath("/nonexistent/path.json", View{}), Error);
    // Keyframes made in code: NaN and infinity are refused by name.
    Keyframe a, b;
    b.position = {0.0, 0.0, 2.0};
    b.target.y = NAN;
    EXPECT_THROW(CameraPath({a, b}, View{}), Error);
    b.target.y = 0;
    b.fovYDeg = INFINITY;
    EXPECT_THROW(CameraPath({a, b}, View{}), Error);
    b.fovYDeg = 60;
    b.time = NAN;
    EXPECT_THROW(CameraPath({a, b}, View{}), Error);
    b.time = 1;
    EXPECT_NO_THROW(CameraPath({a, b}, View{}));
    EXPECT_THROW(orbit(View{}, 0), Error);
}

}  // namespace
}  // namespace ssfx::scene
