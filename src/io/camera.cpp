// Camera JSON files (see camera.hpp).
#include "ssfx/io/camera.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <numbers>
#include <utility>

#include "ssfx/io/png.hpp"

namespace ssfx::io {

Camera parseCameraJson(const std::string& text, const std::string& name, CameraBuffer* buffer) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const std::exception& e) {
        throw Error(fmt::format("{}: not valid JSON ({})", name, e.what()));
    }
    if (!j.is_object()) throw Error(fmt::format("{}: a camera must be a JSON object", name));
    Camera c;
    for (auto it = j.begin(); it != j.end(); ++it) {  // (not a structured binding: clang 14 lambdas)
        const std::string& key = it.key();
        const nlohmann::json& value = it.value();
        auto number = [&]() {
            if (!value.is_number()) throw Error(fmt::format("{}: '{}' must be a number", name, key));
            return value.get<double>();
        };
        if (key == "fov_y_deg") {
            const double degrees = number();
            if (!(degrees > 0 && degrees < 180))  // the file's unit, not the struct's radians
                throw Error(fmt::format("{}: 'fov_y_deg' {} is not in (0, 180) degrees", name, degrees));
            c.fovY = degrees * std::numbers::pi / 180.0;
        } else if (key == "z_near") {
            c.zNear = number();
        } else if (key == "z_far") {
            if (value.is_null() || (value.is_string() && value.get<std::string>() == "-inf"))
                c.zFar = -INFINITY;
            else
                c.zFar = number();
        } else if (key == "width" || key == "height" || key == "guard") {
            const int v =
                wholeNumber(number(), fmt::format("{}: '{}'", name, key), key == "guard" ? 0 : 1, kMaxDimension);
            if (buffer) {
                (key == "width" ? buffer->width : key == "height" ? buffer->height : buffer->guard) = v;
                buffer->stated = true;
            }
        } else if (key == "projection" || key == "view") {
            // Written by `ssfx render` for other consumers; the AO passes derive all from the three above.
        } else {
            throw Error(
                fmt::format("{}: unknown key '{}' (known: fov_y_deg, z_near, z_far; width, height, "
                            "guard, projection, view are ignored)",
                            name, key));
        }
    }
    // Every camera key is required: defaults would silently describe another camera.
    for (const char* key : {"fov_y_deg", "z_near", "z_far"})
        if (!j.contains(key))
            throw Error(
                fmt::format("{}: missing key '{}' (a camera needs fov_y_deg, z_near and z_far; z_far null for "
                            "an infinite far plane)",
                            name, key));
    try {
        ssfx::projection(c, 1, 1);  // validates
    } catch (const Error& e) {
        // The library names the fields as the struct does (zNear); the file has z_near.
        std::string m = e.what();
        for (const auto& [from, to] : {std::pair{"zNear", "z_near"}, {"zFar", "z_far"}, {"fovY", "fov_y_deg"}})
            for (std::size_t at; (at = m.find(from)) != std::string::npos;) m.replace(at, std::strlen(from), to);
        if (m.rfind("camera: ", 0) == 0) m = m.substr(8);
        throw Error(fmt::format("{}: {}", name, m));
    }
    return c;
}

Camera readCameraJson(const std::string& path, CameraBuffer* buffer) {
    const auto bytes = readFile(path, kMaxJsonFileBytes, "JSON");
    return parseCameraJson(std::string(bytes.begin(), bytes.end()), path, buffer);
}

std::string cameraJson(const Camera& c) {
    nlohmann::ordered_json j;
    j["fov_y_deg"] = std::round(c.fovY * 180.0 / std::numbers::pi * 1e9) / 1e9;  // no 59.99999999999999
    j["z_near"] = c.zNear;
    j["z_far"] = std::isinf(c.zFar) ? nlohmann::ordered_json() : nlohmann::ordered_json(c.zFar);
    return j.dump(2) + "\n";
}

void writeCameraJson(const std::string& path, const Camera& c) {
    const std::string text = cameraJson(c);
    writeTextAtomic(path, text);
}

}  // namespace ssfx::io
