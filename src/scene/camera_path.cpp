// Camera paths: keyframes read from JSON and interpolated, and the built-in orbit
// (ssfx/scene/camera_path.hpp).
#include "ssfx/scene/camera_path.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::scene {

namespace {

using Json = nlohmann::json;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Hermite basis on [0, 1] (Catmull-Rom when the tangents are the neighbours' differences).
glm::dvec3 hermite(const glm::dvec3& p0, const glm::dvec3& m0, const glm::dvec3& p1, const glm::dvec3& m1, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

}  // namespace

CameraPath::CameraPath(std::vector<Keyframe> keyframes, const View& base) : keys_(std::move(keyframes)), base_(base) {
    if (keys_.size() < 2)
        throw Error(fmt::format("a camera path needs at least two keyframes (it has {})", keys_.size()));
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const Keyframe& k = keys_[i];
        if (!finite(k.position)) throw Error(fmt::format("keyframe {}: position is not finite", i));
        if (!finite(k.target)) throw Error(fmt::format("keyframe {}: target is not finite", i));
        if (k.position == k.target) throw Error(fmt::format("keyframe {}: position equals target", i));
        if (!(k.fovYDeg > 0 && k.fovYDeg < 180))
            throw Error(fmt::format("keyframe {}: fov {} is not in (0, 180) degrees", i, k.fovYDeg));
        if (!std::isfinite(k.time)) throw Error(fmt::format("keyframe {}: time is not finite", i));
        if (i > 0 && !(k.time > keys_[i - 1].time))
            throw Error(fmt::format("keyframe {}: time {} does not come after {}", i, k.time, keys_[i - 1].time));
    }
}

View CameraPath::at(double time) const {
    const std::size_t n = keys_.size();
    const double t = std::clamp(time, keys_.front().time, keys_.back().time);
    std::size_t i = 0;  // the segment [i, i + 1] that holds t
    while (i + 2 < n && t >= keys_[i + 1].time) ++i;
    const Keyframe &a = keys_[i], &b = keys_[i + 1];
    const double span = b.time - a.time, s = (t - a.time) / span;
    // Catmull-Rom tangents (finite differences over the neighbours, one-sided at the ends),
    // in units per segment of this span, so that uneven keyframe times keep the speed continuous.
    const auto tangent = [&](std::size_t k, auto member) {
        const std::size_t lo = k == 0 ? 0 : k - 1, hi = std::min(k + 1, n - 1);
        return (keys_[hi].*member - keys_[lo].*member) * (span / (keys_[hi].time - keys_[lo].time));
    };
    View v = base_;
    v.eye = hermite(a.position, tangent(i, &Keyframe::position), b.position, tangent(i + 1, &Keyframe::position), s);
    v.target = hermite(a.target, tangent(i, &Keyframe::target), b.target, tangent(i + 1, &Keyframe::target), s);
    if (v.eye == v.target) v.target = a.target + (b.target - a.target) * s;  // a degenerate spline point
    v.fovYDeg = a.fovYDeg + (b.fovYDeg - a.fovYDeg) * s;
    return v;
}

std::vector<View> CameraPath::sample(int frames) const {
    if (frames < 1) throw Error(fmt::format("{} frames: at least one", frames));
    std::vector<View> views;
    const double t0 = keys_.front().time, t1 = keys_.back().time;
    for (int f = 0; f < frames; ++f) views.push_back(at(frames == 1 ? t0 : t0 + (t1 - t0) * f / (frames - 1)));
    return views;
}

CameraPath parseCameraPath(std::string_view text, const std::string& name, const View& base) {
    Json j;
    try {
        j = Json::parse(text.begin(), text.end());
    } catch (const std::exception& e) {
        throw Error(fmt::format("camera path '{}': not valid JSON ({})", name, e.what()));
    }
    const auto fail = [&](const std::string& what) { return Error(fmt::format("camera path '{}': {}", name, what)); };
    if (!j.is_object() || !j.contains("keyframes") || !j["keyframes"].is_array())
        throw fail("expected an object with a 'keyframes' array");
    for (const auto& [key, value] : j.items())
        if (key != "keyframes") throw fail(fmt::format("unknown key '{}'", key));
    const auto number = [&](const Json& v, const std::string& where) {
        if (!v.is_number()) throw fail(fmt::format("{} is not a number", where));
        return v.get<double>();
    };
    const auto vec3 = [&](const Json& v, const std::string& where) {
        if (!v.is_array() || v.size() != 3) throw fail(fmt::format("{} is not an array of three numbers", where));
        return glm::dvec3(number(v[0], where), number(v[1], where), number(v[2], where));
    };
    std::vector<Keyframe> keys;
    std::size_t timed = 0;
    for (std::size_t i = 0; i < j["keyframes"].size(); ++i) {
        const Json& k = j["keyframes"][i];
        const std::string at = fmt::format("keyframe {}", i);
        if (!k.is_object()) throw fail(at + " is not an object");
        for (const auto& [key, value] : k.items())
            if (key != "position" && key != "target" && key != "fov" && key != "time")
                throw fail(fmt::format("{}: unknown key '{}' (position, target, fov, time)", at, key));
        for (const char* key : {"position", "target", "fov"})
            if (!k.contains(key)) throw fail(fmt::format("{}: no '{}'", at, key));
        Keyframe f;
        f.position = vec3(k["position"], at + " position");
        f.target = vec3(k["target"], at + " target");
        f.fovYDeg = number(k["fov"], at + " fov");
        f.time = k.contains("time") ? (++timed, number(k["time"], at + " time")) : double(i);
        keys.push_back(f);
    }
    if (timed != 0 && timed != keys.size()) throw fail("'time' on some keyframes only: give it on all or none");
    try {
        return CameraPath(std::move(keys), base);
    } catch (const Error& e) {
        throw fail(e.what());
    }
}

CameraPath readCameraPath(const std::string& path, const View& base) {
    const auto bytes = io::readFile(path, io::kMaxJsonFileBytes, "JSON");
    return parseCameraPath(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path, base);
}

std::vector<View> orbit(const View& base, int frames) {
    if (frames < 1) throw Error(fmt::format("{} frames: at least one", frames));
    const glm::dvec3 up = glm::normalize(base.up);
    const glm::dvec3 offset = base.eye - base.target;
    const double height = glm::dot(offset, up);
    const glm::dvec3 radial = offset - height * up;  // in the plane around the axis
    const glm::dvec3 side = glm::cross(up, radial);
    std::vector<View> views;
    for (int f = 0; f < frames; ++f) {
        const double a = 2.0 * std::numbers::pi * f / frames;
        View v = base;
        v.eye = base.target + height * up + std::cos(a) * radial + std::sin(a) * side;
        views.push_back(v);
    }
    return views;
}

}  // namespace ssfx::scene
