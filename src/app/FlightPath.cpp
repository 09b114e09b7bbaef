#include "app/FlightPath.h"

#include "core/FileIO.h"
#include "core/SettingsJson.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firmament {

using nlohmann::json;

namespace {

float lerpDegreesShortWay(float a, float b, float t) {
    float delta = std::fmod(b - a + 540.0f, 360.0f) - 180.0f;
    float angle = a + delta * t;
    angle = std::fmod(angle + 180.0f, 360.0f);
    return (angle < 0.0f ? angle + 360.0f : angle) - 180.0f;
}

}  // namespace

FlightPath FlightPath::load(const std::filesystem::path& path) {
    const auto bytes = readFileBytes(path);
    json in;
    try {
        in = json::parse(bytes.begin(), bytes.end());
    } catch (const json::parse_error& e) {
        throw SettingsError(path.string() + ": not valid JSON: " + e.what());
    }
    const std::string where = path.string() + ": ";
    if (!in.is_object() || !in.contains("keyframes") || !in["keyframes"].is_array() || in["keyframes"].empty())
        throw SettingsError(where + "expected {\"keyframes\": [{\"time\": ..., \"camera\": {...}, \"sun\": {...}}, ...]}");
    FlightPath flight;
    Bookmark previous;
    for (size_t i = 0; i < in["keyframes"].size(); ++i) {
        const std::string name = where + "keyframes[" + std::to_string(i) + "]";
        json frame = in["keyframes"][i];
        if (!frame.is_object() || !frame.contains("time") || !frame["time"].is_number())
            throw SettingsError(name + ": needs a \"time\" in seconds");
        const double time = frame["time"].get<double>();
        if (!std::isfinite(time) || time < 0.0 || (!flight.keyframes_.empty() && time <= flight.keyframes_.back().time))
            throw SettingsError(name + ".time: " + frame["time"].dump() + " must be after the previous keyframe's");
        frame.erase("time");
        Bookmark view = previous;  // keys left out keep the previous keyframe's values
        try {
            settingsFromJson(frame, view.sections());
        } catch (const SettingsError& e) {
            throw SettingsError(name + "." + e.what());
        }
        flight.keyframes_.push_back({time, view});
        previous = view;
    }
    return flight;
}

void FlightPath::save(const std::filesystem::path& path) const {
    json frames = json::array();
    for (FlightKeyframe frame : keyframes_) {
        json entry = settingsToJson(frame.view.sections());
        entry["time"] = std::round(frame.time * 1000.0) / 1000.0;
        frames.push_back(entry);
    }
    const std::string text = json{{"format", 1}, {"keyframes", frames}}.dump(2) + "\n";
    writeFileBytes(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

std::string FlightPath::describe() const {
    if (keyframes_.size() == 1) return "a still view (one keyframe)";
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.1f", duration());
    return "a flight of " + std::to_string(keyframes_.size()) + " keyframes over " + seconds + " s";
}

void FlightPath::add(double time, const Camera& camera, const Sun& sun) { keyframes_.push_back({time, Bookmark{camera, sun}}); }

Bookmark FlightPath::at(double time) const {
    if (keyframes_.empty()) return {};
    if (time <= keyframes_.front().time) return keyframes_.front().view;
    if (time >= keyframes_.back().time) return keyframes_.back().view;
    const auto next = std::upper_bound(keyframes_.begin(), keyframes_.end(), time,
                                       [](double t, const FlightKeyframe& k) { return t < k.time; });
    const FlightKeyframe& a = *(next - 1);
    const FlightKeyframe& b = *next;
    const float t = static_cast<float>((time - a.time) / (b.time - a.time));
    Bookmark view = a.view;
    view.camera.position = glm::mix(a.view.camera.position, b.view.camera.position, t);
    view.camera.yawDegrees = lerpDegreesShortWay(a.view.camera.yawDegrees, b.view.camera.yawDegrees, t);
    view.camera.pitchDegrees = glm::mix(a.view.camera.pitchDegrees, b.view.camera.pitchDegrees, t);
    view.camera.verticalFovDegrees = glm::mix(a.view.camera.verticalFovDegrees, b.view.camera.verticalFovDegrees, t);
    view.sun.elevationDegrees = glm::mix(a.view.sun.elevationDegrees, b.view.sun.elevationDegrees, t);
    view.sun.azimuthDegrees = lerpDegreesShortWay(a.view.sun.azimuthDegrees, b.view.sun.azimuthDegrees, t);
    return view;
}

}  // namespace firmament
