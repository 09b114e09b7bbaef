#pragma once
// A recorded camera flight: keyframes of camera and sun over time, played back by
// --flight FILE (the demo's headless run, benchmarks) and written by --record-flight FILE
// from a person's flight. Between keyframes everything is interpolated linearly (yaw and
// azimuth the short way round).
//
//   {"format": 1, "keyframes": [{"time": 0, "camera": {...}, "sun": {...}}, ...],
//    "captures": [{"time": 2.5, "name": "sunrise"}, ...]}
//
// The optional "captures" name pictures along the way: with --capture PATH.png, the first frame
// at or past each one's time is also captured as PATH-name.png (and .exr).
#include "settings/State.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace firmament {

struct FlightKeyframe {
    double time = 0.0;  // seconds from the start
    Bookmark view;
};

struct FlightCapture {
    double time = 0.0;
    std::string name;  // letters, digits, '-' and '_'
};

class FlightPath {
public:
    // Throws SettingsError naming the keyframe and key; keyframes must be in time order.
    static FlightPath load(const std::filesystem::path& path);
    // The same from a file's bytes; `fileName` stands for the file in the messages.
    static FlightPath parse(std::span<const std::uint8_t> bytes, const std::string& fileName);
    void save(const std::filesystem::path& path) const;

    void add(double time, const Camera& camera, const Sun& sun);
    Bookmark at(double time) const;  // clamped to the first and last keyframes
    double duration() const { return keyframes_.empty() ? 0.0 : keyframes_.back().time; }
    size_t size() const { return keyframes_.size(); }
    // The names of the captures in (after, upTo]; with `after` < 0, from the start on.
    std::vector<std::string> capturesBetween(double after, double upTo) const;
    const std::vector<FlightCapture>& captures() const { return captures_; }
    // For the log: "a flight of 12 keyframes over 8.5 s", or "a still view (one keyframe)".
    std::string describe() const;

private:
    std::vector<FlightKeyframe> keyframes_;
    std::vector<FlightCapture> captures_;  // in time order
};

}  // namespace firmament
