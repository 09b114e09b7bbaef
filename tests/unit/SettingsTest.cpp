// Settings and state: JSON round trips, --set assignments, and every kind of bad input
// answered with a message that names the key.
#include "settings/State.h"
#include "core/SettingsJson.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace firmament {
namespace {

using nlohmann::json;

void expectSettingsError(const std::function<void()>& action, const std::string& expected) {
    try {
        action();
        ADD_FAILURE() << "no error; expected one containing: " << expected;
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << "message: " << e.what() << "\nexpected: " << expected;
    }
}

State changedState() {
    State s;
    s.display.vsync = false;
    s.scene.orientationGrid = false;
    s.camera.position = {123.5f, 4567.25f, -89.0f};
    s.camera.yawDegrees = -37.5f;
    s.camera.pitchDegrees = 12.1f;
    s.camera.verticalFovDegrees = 60.0f;
    s.sun.elevationDegrees = 5.5f;
    s.sun.azimuthDegrees = 170.0f;
    s.flight.speed = 0.1f * 3.0f * 1000.0f;  // not exactly representable: the round trip must still be exact
    s.flight.scaleWithAltitude = false;
    s.devices.stickDeadZone = 0.3f;
    s.toneMapping.exposureEv = -1.25f;
    s.toneMapping.op = ToneMapOperator::AdaptiveLogarithmic;
    s.toneMapping.middleGray = 0.3f;
    s.toneMapping.whitePoint = 7.5f;
    s.toneMapping.luminanceSaturation = 0.7f;
    s.toneMapping.autoExposure = false;
    s.toneMapping.lightAdaptation = false;
    s.toneMapping.adaptationSeconds = 2.0f;
    s.shaders.autoReload = false;
    s.ui.panel = Panel::ToneMapping;
    s.ui.help = true;
    s.bookmarks[2] = Bookmark{s.camera, s.sun};
    s.bookmarks[2]->camera.position.x = 1.0e5f;
    return s;
}

TEST(Settings, JsonRoundTripRestoresEveryField) {
    State original = changedState();
    const json saved = stateToJson(original);
    State loaded;
    stateFromJson(loaded, json::parse(saved.dump()));  // through text, as a file would
    EXPECT_EQ(stateToJson(loaded), saved);
    EXPECT_EQ(loaded.flight.speed, original.flight.speed);  // bit-exact
    EXPECT_EQ(loaded.camera.position, original.camera.position);
    EXPECT_EQ(loaded.ui.panel, Panel::ToneMapping);
    EXPECT_EQ(loaded.toneMapping.op, ToneMapOperator::AdaptiveLogarithmic);
    EXPECT_EQ(loaded.toneMapping.adaptationSeconds, 2.0f);
    ASSERT_TRUE(loaded.bookmarks[2].has_value());
    EXPECT_EQ(loaded.bookmarks[2]->camera.position.x, 1.0e5f);
    EXPECT_FALSE(loaded.bookmarks[0].has_value());
}

TEST(Settings, SavedFileIsReadableJson) {
    State state = changedState();
    const json saved = stateToJson(state);
    EXPECT_EQ(saved["format"], 1);
    EXPECT_EQ(saved["camera"]["fieldOfView"], 60.0);
    EXPECT_EQ(saved["ui"]["panel"], "Tone mapping");
    EXPECT_EQ(saved["camera"]["position"], json::array({123.5, 4567.25, -89.0}));
    EXPECT_EQ(saved["flight"]["speed"].dump(), "300.0");  // shortest form, not 300.0000xxx
    EXPECT_EQ(saved["flight"]["mouseDegreesPerPixel"].dump(), "0.15");  // not 0.15000000596
}

TEST(Settings, AFileMayHoldOnlySomeKeys) {
    State state;
    stateFromJson(state, json::parse(R"({"sun": {"elevation": 12}})"));
    EXPECT_EQ(state.sun.elevationDegrees, 12.0f);
    EXPECT_EQ(state.sun.azimuthDegrees, Sun{}.azimuthDegrees);
    EXPECT_EQ(state.camera.position, Camera{}.position);
}

TEST(Settings, BadJsonNamesTheKeyAndChangesNothing) {
    State state;
    auto load = [&](const char* text) { return [&state, text] { stateFromJson(state, json::parse(text)); }; };
    expectSettingsError(load(R"({"camera": {"fieldOfVeiw": 60}})"), "unknown key 'camera.fieldOfVeiw'");
    expectSettingsError(load(R"({"camra": {}})"), "unknown section 'camra'");
    expectSettingsError(load(R"({"camera": {"fieldOfView": "wide"}})"), "camera.fieldOfView: expected a number, got \"wide\"");
    expectSettingsError(load(R"({"camera": {"fieldOfView": 500}})"), "camera.fieldOfView: 500 is outside 10 to 120");
    expectSettingsError(load(R"({"display": {"vsync": 1}})"), "display.vsync: expected true or false");
    expectSettingsError(load(R"({"ui": {"panel": "Sky"}})"), "ui.panel: \"Sky\" is not one of Basic, Additional, Tone mapping, Clouds, Performance");
    expectSettingsError(load(R"({"camera": {"position": [1, 2]}})"), "camera.position: expected three numbers");
    expectSettingsError(load(R"({"camera": 5})"), "camera: expected an object");
    expectSettingsError(load(R"({"format": 2})"), "format: 2 is not a state format");
    expectSettingsError(load(R"({"bookmarks": {"0": {}}})"), "bookmarks: '0' is not a slot from 1 to 9");
    expectSettingsError(load(R"({"bookmarks": {"4": {"sun": {"elevation": 91}}}})"), "bookmarks.4.sun.elevation: 91 is outside -90 to 90");
    expectSettingsError(load(R"([1, 2])"), "expected a JSON object");
    // The valid part of a rejected file is not applied either.
    expectSettingsError(load(R"({"sun": {"elevation": 10}, "camera": {"yaw": 1000}})"), "camera.yaw");
    EXPECT_EQ(state.sun.elevationDegrees, Sun{}.elevationDegrees);
}

TEST(Settings, SetAssignsEveryKindOfField) {
    State state;
    applyAssignments(state, {"display.vsync=off", "camera.fieldOfView=60", "camera.position=1,2.5,-3", "ui.panel=tone mapping",
                             "flight.speed=1e3", "sun.azimuth=-90", "toneMapping.operator=filmic alu"});
    EXPECT_FALSE(state.display.vsync);
    EXPECT_EQ(state.camera.verticalFovDegrees, 60.0f);
    EXPECT_EQ(state.camera.position, glm::vec3(1.0f, 2.5f, -3.0f));
    EXPECT_EQ(state.ui.panel, Panel::ToneMapping);
    EXPECT_EQ(state.flight.speed, 1000.0f);
    EXPECT_EQ(state.sun.azimuthDegrees, -90.0f);
    EXPECT_EQ(state.toneMapping.op, ToneMapOperator::FilmicAlu);  // a choice's name in any case
}

TEST(Settings, BadSetNamesTheKeyAndChangesNothing) {
    State state;
    auto set = [&](std::string assignment) {
        return [&state, assignment] { applyAssignments(state, {"sun.elevation=5", assignment}); };
    };
    expectSettingsError(set("camera.zoom=2"), "unknown key 'camera.zoom' (known: camera.position, camera.yaw, camera.pitch, camera.fieldOfView)");
    expectSettingsError(set("lens.zoom=2"), "unknown section 'lens'");
    expectSettingsError(set("camera.fieldOfView=wide"), "camera.fieldOfView: expected a number, got 'wide'");
    expectSettingsError(set("camera.fieldOfView=5"), "camera.fieldOfView: 5 is outside 10 to 120");
    expectSettingsError(set("camera.fieldOfView=nan"), "camera.fieldOfView: expected a number");
    expectSettingsError(set("display.vsync=maybe"), "display.vsync: expected on or off");
    expectSettingsError(set("camera.position=1,2"), "camera.position: expected x,y,z");
    expectSettingsError(set("ui.panel=sky"), "ui.panel: 'sky' is not one of");
    expectSettingsError(set("camera.fieldOfView"), "is not section.key=value");
    EXPECT_EQ(state.sun.elevationDegrees, Sun{}.elevationDegrees);
}

TEST(Settings, EveryKeyIsListedOnce) {
    State state;
    const auto keys = settingKeys(state.sections());
    EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()).size(), keys.size());
    for (const char* key : {"display.vsync", "camera.fieldOfView", "sun.elevation", "flight.speed", "devices.stickDeadZone",
                            "toneMapping.exposure", "shaders.autoReload", "ui.panel", "scene.orientationGrid"})
        EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
}

TEST(Settings, BookmarksStoreAndRecallCameraAndSun) {
    State state;
    EXPECT_FALSE(state.recallBookmark(3));
    state.camera.position = {10.0f, 20.0f, 30.0f};
    state.camera.yawDegrees = 45.0f;
    state.sun.elevationDegrees = 3.0f;
    state.storeBookmark(3);
    state.camera = Camera{};
    state.sun = Sun{};
    ASSERT_TRUE(state.recallBookmark(3));
    EXPECT_EQ(state.camera.position, glm::vec3(10.0f, 20.0f, 30.0f));
    EXPECT_EQ(state.camera.yawDegrees, 45.0f);
    EXPECT_EQ(state.sun.elevationDegrees, 3.0f);
    EXPECT_FALSE(state.recallBookmark(9));
}

TEST(Settings, StateFilesReportTheirProblems) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-settings-test";
    std::filesystem::create_directories(folder);
    State state = changedState();
    saveStateFile(state, folder / "state.json");
    State loaded;
    loadStateFile(loaded, folder / "state.json");
    EXPECT_EQ(stateToJson(loaded), stateToJson(state));

    std::ofstream(folder / "broken.json") << "{\"camera\": {\"yaw\": 10,}}";
    expectSettingsError([&] { loadStateFile(loaded, folder / "broken.json"); }, "broken.json: not valid JSON");
    // Found by fuzzing (tests/fuzz/regressions/state_file): a number too large for a double made
    // the JSON library throw out_of_range, which nothing caught.
    std::ofstream(folder / "huge.json") << R"({"camera": {"yaw": 8e619}})";
    expectSettingsError([&] { loadStateFile(loaded, folder / "huge.json"); }, "huge.json: not valid JSON");
    std::ofstream(folder / "range.json") << R"({"toneMapping": {"exposure": 99}})";
    expectSettingsError([&] { loadStateFile(loaded, folder / "range.json"); }, "range.json: toneMapping.exposure: 99 is outside -10 to 10");
    EXPECT_THROW(loadStateFile(loaded, folder / "missing.json"), Error);
}

}  // namespace
}  // namespace firmament
