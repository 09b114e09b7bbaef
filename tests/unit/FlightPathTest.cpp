// Recorded flights: interpolation between keyframes, save and load, bad files.
#include "app/FlightPath.h"
#include "core/SettingsJson.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace firmament {
namespace {

TEST(FlightPath, InterpolatesBetweenKeyframesTheShortWayRound) {
    FlightPath flight;
    Camera a, b;
    Sun sun;
    a.position = {0.0f, 100.0f, 0.0f};
    a.yawDegrees = 170.0f;
    b.position = {1000.0f, 300.0f, -500.0f};
    b.yawDegrees = -170.0f;  // 20 degrees further, across +-180
    b.pitchDegrees = -40.0f;
    flight.add(0.0, a, sun);
    flight.add(2.0, b, sun);
    EXPECT_EQ(flight.duration(), 2.0);
    const Bookmark middle = flight.at(1.0);
    EXPECT_EQ(middle.camera.position, glm::vec3(500.0f, 200.0f, -250.0f));
    EXPECT_NEAR(std::abs(middle.camera.yawDegrees), 180.0f, 1e-4f);
    EXPECT_NEAR(middle.camera.pitchDegrees, -20.0f, 1e-5f);
    EXPECT_NEAR(flight.at(1.5).camera.yawDegrees, -175.0f, 1e-4f);
    EXPECT_EQ(flight.at(-1.0).camera.position, a.position);  // clamped at both ends
    EXPECT_EQ(flight.at(9.0).camera.position, b.position);
}

TEST(FlightPath, DescribesItselfInPlainEnglish) {
    FlightPath flight;
    const Camera camera;
    const Sun sun;
    flight.add(0.0, camera, sun);
    EXPECT_EQ(flight.describe(), "a still view (one keyframe)");
    flight.add(8.49, camera, sun);
    EXPECT_EQ(flight.describe(), "a flight of 2 keyframes over 8.5 s");
}

TEST(FlightPath, SavedFlightsLoadBack) {
    const auto path = std::filesystem::temp_directory_path() / "firmament-flight-test.json";
    FlightPath flight;
    Camera camera;
    Sun sun;
    for (int i = 0; i < 5; ++i) {
        camera.position.z = 100.0f * static_cast<float>(i);
        sun.elevationDegrees = static_cast<float>(10 + i);
        flight.add(0.1 * i, camera, sun);
    }
    flight.save(path);
    const FlightPath loaded = FlightPath::load(path);
    ASSERT_EQ(loaded.size(), 5u);
    EXPECT_NEAR(loaded.duration(), 0.4, 1e-9);
    EXPECT_EQ(loaded.at(0.3).camera.position.z, 300.0f);
    EXPECT_EQ(loaded.at(0.3).sun.elevationDegrees, 13.0f);
}

TEST(FlightPath, BadFilesNameTheKeyframe) {
    const auto path = std::filesystem::temp_directory_path() / "firmament-bad-flight.json";
    auto expectError = [&](const char* text, const std::string& expected) {
        std::ofstream(path) << text;
        try {
            FlightPath::load(path);
            ADD_FAILURE() << "no error for " << text;
        } catch (const SettingsError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    expectError(R"({"frames": []})", "expected {\"keyframes\"");
    expectError(R"({"keyframes": [{"camera": {}}]})", "keyframes[0]: needs a \"time\"");
    expectError(R"({"keyframes": [{"time": 1}, {"time": 0.5}]})", "keyframes[1].time: 0.5 must be after");
    expectError(R"({"keyframes": [{"time": 0, "camera": {"pitch": 95}}]})", "keyframes[0].camera.pitch: 95 is outside -89 to 89");
    expectError(R"({"keyframes": [{"time": 0, "lens": {}}]})", "keyframes[0].unknown section 'lens'");
    expectError(R"({"keyframes": [{"time": 0}], "captures": [{"time": 0, "name": "../up"}]})", "captures[0].name: \"../up\" must be a name");
    expectError(R"({"keyframes": [{"time": 0}], "captures": [{"time": 0, "name": ""}]})", "captures[0].name");
    expectError(R"({"keyframes": [{"time": 0}], "captures": [{"time": 0}]})", "captures[0].name: null must be a name");
    expectError(R"({"keyframes": [{"time": 0}], "captures": [{"name": "a"}]})", "captures[0]: needs a \"time\"");
    expectError(R"({"keyframes": [{"time": 0}], "captures": [{"time": 0, "name": "a"}, {"time": 1, "name": "a"}]})", "captures[1].name: \"a\" is used twice");
    expectError(R"({"keyframes": [{"time": 0}], "captures": {}})", "captures: expected");
    // Found by fuzzing the state file: a number too large for a double is an error, not a crash.
    expectError(R"({"keyframes": [{"time": 8e619}]})", "not valid JSON");
}

// The flight's captures: read, written back, and each due once, on the first frame at or past its time.
TEST(FlightPath, CapturesAreDueOnceWhenTheirKeyframeIsReached) {
    const auto path = std::filesystem::temp_directory_path() / "firmament-flight-captures.json";
    std::ofstream(path) << R"({"keyframes": [
        {"time": 0, "camera": {"position": [0, 100, 0]}},
        {"time": 1, "camera": {"position": [0, 200, 0]}}],
        "captures": [{"time": 1, "name": "end"}, {"time": 0, "name": "start"}, {"time": 0.5, "name": "middle-view_2"}]})";
    FlightPath flight = FlightPath::load(path);
    ASSERT_EQ(flight.size(), 2u);
    EXPECT_EQ(flight.capturesBetween(-1.0, 0.0), std::vector<std::string>{"start"});
    EXPECT_TRUE(flight.capturesBetween(0.0, 0.49).empty());
    EXPECT_EQ(flight.capturesBetween(0.49, 0.51), std::vector<std::string>{"middle-view_2"});
    EXPECT_EQ(flight.capturesBetween(0.51, 2.0), std::vector<std::string>{"end"});
    EXPECT_EQ(flight.capturesBetween(-1.0, 2.0), (std::vector<std::string>{"start", "middle-view_2", "end"}));
    flight.save(path);
    EXPECT_EQ(FlightPath::load(path).capturesBetween(-1.0, 2.0), (std::vector<std::string>{"start", "middle-view_2", "end"}));
    std::filesystem::remove_all(path);
}

}  // namespace
}  // namespace firmament
