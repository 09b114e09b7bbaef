// Files are replaced whole or not at all (core/FileIO.h): a write that fails for any reason (the
// encoder fails, the folder is missing, read-only or full) throws Error naming the file, keeps
// the old file's bytes and leaves no temporary file behind.
//
// The read-only and full folders are made by tools/test for the portable build (a read-only
// bind mount and a 512 KiB tmpfs, named by FIRMAMENT_TEST_READ_ONLY_FOLDER and
// FIRMAMENT_TEST_FULL_FOLDER); elsewhere those two tests are skipped, unless
// FIRMAMENT_REQUIRE_FILESYSTEM_FIXTURES is set, when their absence fails.
#include "core/Error.h"
#include "core/ExrImage.h"
#include "core/FileIO.h"
#include "core/PngImage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace firmament {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    const auto bytes = readFileBytes(path);
    return std::string(bytes.begin(), bytes.end());
}

std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A fresh folder of the test's own under the system's temporary folder.
fs::path scratchFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("firmament-file-io-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// The folder an environment variable names, or nullopt (then the test is skipped, or fails
// where the fixtures are required).
std::optional<fs::path> fixtureFolder(const char* variable) {
    if (const char* value = std::getenv(variable); value && *value) return fs::path(value);
    return std::nullopt;
}

bool fixturesRequired() { return std::getenv("FIRMAMENT_REQUIRE_FILESYSTEM_FIXTURES") != nullptr; }

template <typename Function>
std::string errorOf(Function&& function) {
    try {
        function();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

TEST(FileIO, WritesAFileAndReplacesItWhole) {
    const fs::path folder = scratchFolder("replace");
    const fs::path file = folder / "state.json";
    writeFileText(file, "old");
    EXPECT_EQ(readText(file), "old");
    writeFileText(file, "the new contents, longer than the old");
    EXPECT_EQ(readText(file), "the new contents, longer than the old");
    writeFileText(file, "");
    EXPECT_EQ(readText(file), "");
    EXPECT_EQ(namesIn(folder), std::vector<std::string>{"state.json"});  // no temporary file left
    fs::remove_all(folder);
}

TEST(FileIO, AnExrThatCannotBeEncodedKeepsTheOldFileAndLeavesNoTemporary) {
    const fs::path folder = scratchFolder("encoder-fails");
    const fs::path file = folder / "table.exr";
    writeFileText(file, "old table");
    const std::string error = errorOf([&] { writeExr(file, FloatImage{2, 2, {1.0f}}, {}); });  // 1 value for 4 pixels
    EXPECT_NE(error.find("does not match"), std::string::npos) << error;
    EXPECT_EQ(readText(file), "old table");
    EXPECT_EQ(namesIn(folder), std::vector<std::string>{"table.exr"});
    fs::remove_all(folder);
}

TEST(FileIO, AnExrWriteReplacesTheFileAndLeavesNoTemporary) {
    const fs::path folder = scratchFolder("exr");
    const fs::path file = folder / "capture.exr";
    writeFileText(file, "not yet an EXR file");
    writeExr(file, FloatImage{2, 1, {0.25f, 4.0f}}, {{"firmament.lut.key", std::string("k")}});
    const FloatImageFile read = readFloatChannelExr(file);
    EXPECT_EQ(read.image.values, (std::vector<float>{0.25f, 4.0f}));
    EXPECT_EQ(namesIn(folder), std::vector<std::string>{"capture.exr"});
    fs::remove_all(folder);
}

TEST(FileIO, AMissingFolderIsAnErrorNamingTheFile) {
    const fs::path folder = scratchFolder("missing");
    const fs::path file = folder / "no-such-folder" / "shot.png";
    const std::string error = errorOf([&] { writePng(file, Rgba8Image{1, 1, {1, 2, 3, 4}}); });
    EXPECT_NE(error.find(file.string()), std::string::npos) << error;
    EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
    EXPECT_EQ(namesIn(folder), std::vector<std::string>{});
    fs::remove_all(folder);
}

TEST(FileIO, AReadOnlyFolderIsAnErrorAndTheOldFileIsKept) {
    const auto folder = fixtureFolder("FIRMAMENT_TEST_READ_ONLY_FOLDER");
    if (!folder) {
        if (fixturesRequired()) FAIL() << "FIRMAMENT_TEST_READ_ONLY_FOLDER is not set";
        GTEST_SKIP() << "no read-only folder (FIRMAMENT_TEST_READ_ONLY_FOLDER)";
    }
    const fs::path file = *folder / "kept.txt";  // made by tools/test before the folder was mounted read-only
    ASSERT_EQ(readText(file), "kept\n");
    for (const auto& write : {std::function<void()>([&] { writeFileText(file, "replaced"); }),
                              std::function<void()>([&] { writePng(file, Rgba8Image{1, 1, {1, 2, 3, 4}}); }),
                              std::function<void()>([&] { writeExr(file, FloatImage{1, 1, {1.0f}}, {}); }),
                              std::function<void()>([&] { ensureWritable(file); })}) {
        const std::string error = errorOf(write);
        EXPECT_NE(error.find(file.string()), std::string::npos) << error;
        EXPECT_NE(error.find("Read-only file system"), std::string::npos) << error;
        EXPECT_EQ(readText(file), "kept\n");
    }
    EXPECT_EQ(namesIn(*folder), std::vector<std::string>{"kept.txt"});
}

TEST(FileIO, AFullDiskIsAnErrorAndTheOldFileIsKept) {
    const auto folder = fixtureFolder("FIRMAMENT_TEST_FULL_FOLDER");
    if (!folder) {
        if (fixturesRequired()) FAIL() << "FIRMAMENT_TEST_FULL_FOLDER is not set";
        GTEST_SKIP() << "no small file system (FIRMAMENT_TEST_FULL_FOLDER)";
    }
    const fs::path file = *folder / "state.json";
    const fs::path filler = *folder / "filler";
    writeFileText(file, "the old state");
    {  // fill the file system to the last block
        std::ofstream fill(filler, std::ios::binary);
        const std::string block(4096, 'x');
        for (int i = 0; i < 4096 && fill; ++i) fill.write(block.data(), static_cast<std::streamsize>(block.size())), fill.flush();
    }
    const std::string big(256 * 1024, 'y');
    for (const auto& write : {std::function<void()>([&] { writeFileText(file, big); }),
                              std::function<void()>([&] {
                                  writeExr(file, FloatImage{256, 256, std::vector<float>(256 * 256, 0.5f)}, {});
                              })}) {
        const std::string error = errorOf(write);
        EXPECT_NE(error.find(file.string()), std::string::npos) << error;
        EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
        EXPECT_EQ(readText(file), "the old state");
    }
    EXPECT_EQ(namesIn(*folder), (std::vector<std::string>{"filler", "state.json"}));
    fs::remove(filler);
    writeFileText(file, big);  // with room again, the same write succeeds
    EXPECT_EQ(readText(file), big);
    fs::remove(file);
}

}  // namespace
}  // namespace firmament
