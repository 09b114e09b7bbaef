// The batch of captures (--batch): a views file expands in order, each view's size, frame count
// and settings falling back on the file's and then the command line's; a request line carries
// its own capture path; every malformed file or request is refused naming the field.
#include "app/CaptureBatch.h"
#include "core/SettingsJson.h"

#include <gtest/gtest.h>

#include <string>

namespace firmament {
namespace {

using nlohmann::json;

CaptureDefaults defaults() {
    CaptureDefaults d;
    d.state.camera.verticalFovDegrees = 50.0f;  // as --set would have made it
    d.width = 320;
    d.height = 180;
    d.frames = 30;
    d.capture = std::filesystem::path("out") / "view.png";
    return d;
}

TEST(CaptureBatch, ViewsFallBackOnTheFileThenOnTheCommandLine) {
    const auto views = parseCaptureBatch(json::parse(R"json({
        "resolution": [256, 144], "frames": 3, "comment": "other fields are ignored",
        "views": [{"name": "a", "what": "first", "settings": {"sun": {"elevation": 5}}},
                  {"name": "b.2", "settings": {"sun": {"elevation": 7}}, "set": ["sun.elevation=9", "camera.fieldOfView=60"],
                   "resolution": [64, 32], "frames": 1, "captureUi": true}]})json"),
                                         defaults(), "views.json");
    ASSERT_EQ(views.size(), 2u);
    EXPECT_EQ(views[0].id, "a");
    EXPECT_EQ(views[0].width, 256);
    EXPECT_EQ(views[0].height, 144);
    EXPECT_EQ(views[0].frames, 3);
    EXPECT_FLOAT_EQ(views[0].state.sun.elevationDegrees, 5.0f);
    EXPECT_FLOAT_EQ(views[0].state.camera.verticalFovDegrees, 50.0f);  // the command line's
    EXPECT_EQ(views[0].png, std::filesystem::path("out") / "view-a.png");
    EXPECT_FALSE(views[0].captureUi);
    EXPECT_EQ(views[1].width, 64);
    EXPECT_EQ(views[1].frames, 1);
    EXPECT_FLOAT_EQ(views[1].state.sun.elevationDegrees, 9.0f);  // "set" after "settings"
    EXPECT_FLOAT_EQ(views[1].state.camera.verticalFovDegrees, 60.0f);
    EXPECT_EQ(views[1].png, std::filesystem::path("out") / "view-b.2.png");
    EXPECT_TRUE(views[1].captureUi);

    const auto bare = parseCaptureBatch(json::parse(R"({"views": [{"name": "c"}]})"), defaults(), "f");
    EXPECT_EQ(bare[0].width, 320);
    EXPECT_EQ(bare[0].frames, 30);
}

TEST(CaptureBatch, RefusesMalformedFilesNamingTheField) {
    const auto refused = [](const std::string& text, const std::string& expected) {
        try {
            parseCaptureBatch(json::parse(text), defaults(), "views.json");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const SettingsError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    refused(R"([])", "views.json: (top)");
    refused(R"({"views": []})", "views: expected a non-empty list");
    refused(R"({"views": [{"settings": {}}]})", "views[0].name: is missing");
    refused(R"({"views": [{"name": "../up"}]})", "views[0].name: \"../up\" is not a name");
    refused(R"({"views": [{"name": "a"}, {"name": "a"}]})", "views[1].name: 'a' is used twice");
    refused(R"({"resolution": [8, 8], "views": [{"name": "a"}]})", "resolution: [8,8] is not [width, height]");
    refused(R"({"views": [{"name": "a", "frames": 0}]})", "views[0].frames: expected a whole number from 1");
    refused(R"({"views": [{"name": "a", "settings": {"camera": {"fieldOfVeiw": 60}}}]})", "views[0].settings");
    refused(R"({"views": [{"name": "a", "set": ["camera.fieldOfView=500"]}]})", "500 is outside 10 to 120");
    refused(R"({"views": [{"name": "a", "set": "camera.fieldOfView=50"}]})", "views[0].set: expected a list");
    refused(R"({"views": [{"name": "a", "captureUi": "yes"}]})", "views[0].captureUi: expected true or false");
}

TEST(CaptureBatch, ARequestCarriesItsOwnCapturePath) {
    const CaptureItem item = parseCaptureRequest(
        R"({"id": "capture-7", "resolution": [96, 54], "frames": 2, "set": ["sun.elevation=3"], "capture": "shots/x.png"})", defaults());
    EXPECT_EQ(item.id, "capture-7");
    EXPECT_EQ(item.width, 96);
    EXPECT_EQ(item.frames, 2);
    EXPECT_FLOAT_EQ(item.state.sun.elevationDegrees, 3.0f);
    EXPECT_EQ(item.png, std::filesystem::path("shots/x.png"));
    EXPECT_EQ(captureRequestId(R"({"id": "capture-7", "frames": "x"})"), "capture-7");
    EXPECT_EQ(captureRequestId("not json"), "?");

    const auto refused = [](const std::string& line, const std::string& expected) {
        try {
            parseCaptureRequest(line, defaults());
            ADD_FAILURE() << "accepted: " << line;
        } catch (const SettingsError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    refused("{\"id\": \"r\"", "not valid JSON");
    refused(R"({"id": "r"})", "request 'r': capture: expected the PNG's path");
    refused(R"({"id": "r", "capture": "x.bmp"})", "does not end in .png");
    refused(R"({"id": "r", "capture": "x.png", "set": ["sun.elevation=high"]})", "request 'r': settings");
}

}  // namespace
}  // namespace firmament
