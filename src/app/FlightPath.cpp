#include "app/FlightPath.h"

#include "core/FileIO.h"
#include "core/SettingsJson.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cctype>
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

FlightPath FlightPath::load(const std::filesystem::path& path) { return parse(readFileBytes(path), path.string()); }

FlightPath FlightPath::parse(std::span<const std::uint8_t> bytes, const std::string& fileName) {
    json in;
    try {
        in = json::parse(bytes.begin(), bytes.end());
    } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large for a double
        throw SettingsError(fileName + ": not valid JSON: " + e.what());
    }
    const std::string where = fileName + ": ";
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
    if (in.contains("captures")) {
        const json& captures = in["captures"];
        if (!captures.is_array()) throw SettingsError(where + "captures: expected [{\"time\": ..., \"name\": ...}, ...]");
        for (size_t i = 0; i < captures.size(); ++i) {
            const std::string name = where + "captures[" + std::to_string(i) + "]";
            const json& c = captures[i];
            if (!c.is_object() || !c.contains("time") || !c["time"].is_number() || !std::isfinite(c["time"].get<double>()) ||
                c["time"].get<double>() < 0.0)
                throw SettingsError(name + ": needs a \"time\" in seconds, 0 or more");
            const json label = c.value("name", json());
            const std::string text = label.is_string() ? label.get<std::string>() : std::string();
            const bool named = !text.empty() && std::all_of(text.begin(), text.end(), [](char ch) {
                return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_';
            });
            if (!named) throw SettingsError(name + ".name: " + label.dump() + " must be a name of letters, digits, '-' and '_'");
            for (const FlightCapture& earlier : flight.captures_)
                if (earlier.name == text) throw SettingsError(name + ".name: \"" + text + "\" is used twice");
            flight.captures_.push_back({c["time"].get<double>(), text});
        }
        std::stable_sort(flight.captures_.begin(), flight.captures_.end(), [](const FlightCapture& a, const FlightCapture& b) { return a.time < b.time; });
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
    json out{{"format", 1}, {"keyframes", frames}};
    if (!captures_.empty()) {
        json captures = json::array();
        for (const FlightCapture& c : captures_) captures.push_back({{"time", c.time}, {"name", c.name}});
        out["captures"] = captures;
    }
    const std::string text = out.dump(2) + "\n";
    writeFileText(path, text);
}

std::string FlightPath::describe() const {
    if (keyframes_.size() == 1) return "a still view (one keyframe)";
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.1f", duration());
    return "a flight of " + std::to_string(keyframes_.size()) + " keyframes over " + seconds + " s";
}

void FlightPath::add(double time, const Camera& camera, const Sun& sun) { keyframes_.push_back({time, Bookmark{camera, sun}}); }

std::vector<std::string> FlightPath::capturesBetween(double after, double upTo) const {
    std::vector<std::string> names;
    for (const FlightCapture& c : captures_)
        if (c.time > after && c.time <= upTo) names.push_back(c.name);
    return names;
}

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
