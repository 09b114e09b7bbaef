// Recorded flights: interpolation between keyframes, save and load, bad files.
#include "app/FlightPath.h"
#include "core/SettingsJson.h"

#include <gtest/gtest.h>

#include <fstream>

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
}

}  // namespace
}  // namespace firmament
