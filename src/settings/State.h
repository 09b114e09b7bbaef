#pragma once
// Everything a person can set, and where the camera and the sun are: one plain struct per
// technique, gathered here. Saved and loaded whole as JSON (F5 / F9, --settings), changed one
// key at a time with --set section.key=value, edited in the GUI through the same listing.
//
//   {"format": 1, "camera": {"position": [0, 8000, 0], "yaw": 0, ...}, "sun": {...}, ...,
//    "bookmarks": {"1": {"camera": {...}, "sun": {...}}}}
#include "atmosphere/AtmosphereSettings.h"
#include "clouds/CloudSettings.h"
#include "core/Camera.h"
#include "core/Settings.h"
#include "input/FlyCamera.h"
#include "input/HidReports.h"
#include "lightshafts/LightShaftSettings.h"
#include "postfx/ToneMappingSettings.h"
#include "scene/SceneSettings.h"
#include "shadows/ShadowSettings.h"
#include "terrain/TerrainSettings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace firmament {

struct DisplaySettings {
    bool vsync = true;
    void visit(SettingsVisitor& v) { v.field("vsync", vsync, "VSync"); }  // section "display"
};

struct ShaderSettings {
    bool autoReload = true;  // recompile a technique when one of its shader files changes
    void visit(SettingsVisitor& v) { v.field("autoReload", autoReload, "Reload shaders when their files change"); }
};

enum class Panel { Basic, Additional, ToneMapping, Clouds, Performance };
inline constexpr std::array<std::string_view, 5> kPanelNames{"Basic", "Additional", "Tone mapping", "Clouds", "Performance"};

struct UiSettings {
    Panel panel = Panel::Basic;
    bool help = false;  // the F1 window
    void visit(SettingsVisitor& v) {
        v.choice("panel", panel, kPanelNames, "Panel");
        v.field("help", help, "Help window");
    }
};

// A camera bookmark: where the camera is and looks, and where the sun is (Ctrl+1..9 stores,
// 1..9 recalls).
struct Bookmark {
    Camera camera;
    Sun sun;

    std::vector<SettingsSection> sections();  // "camera" and "sun", as in the state file
};

inline constexpr int kBookmarkSlots = 9;
inline constexpr int kStateFormat = 1;

struct State {
    DisplaySettings display;
    SceneSettings scene;
    Camera camera;
    Sun sun;
    FlightSettings flight;
    DeviceSettings devices;
    AtmosphereSettings atmosphere;
    TerrainSettings terrain;
    ShadowSettings shadows;
    LightShaftSettings lightShafts;
    CloudSettings clouds;
    ToneMappingSettings toneMapping;
    ShaderSettings shaders;
    UiSettings ui;
    std::array<std::optional<Bookmark>, kBookmarkSlots> bookmarks;

    // The sections of this object, in the order they are saved.
    std::vector<SettingsSection> sections();

    void storeBookmark(int slot);   // slot 1..9
    bool recallBookmark(int slot);  // false when the slot is empty
};

nlohmann::json stateToJson(State& state);
// Strict: throws SettingsError naming the key; `state` is unchanged when it throws.
void stateFromJson(State& state, const nlohmann::json& json);

void saveStateFile(State& state, const std::filesystem::path& path);  // throws Error
// Throws SettingsError ("path: key: why") for bad content, Error for unreadable files.
void loadStateFile(State& state, const std::filesystem::path& path);
// The same from a file's bytes; `name` stands for the file in the messages.
void parseStateFile(State& state, std::span<const std::uint8_t> bytes, const std::string& name);
// --set assignments in order; throws SettingsError, `state` unchanged.
void applyAssignments(State& state, const std::vector<std::string>& assignments);

}  // namespace firmament
