// The real window under Xvfb, driven from outside as a window manager and a person would: this
// test finds firmament.exe's window and sends it what they send (SetWindowPos, ShowWindow,
// Alt+Enter, F8, F12, WM_CLOSE). After each event the next frame must be the right one: an F12
// shot compared with a headless capture of the same view at the same size, made by the same
// build. A minimized window must use no CPU time, which on WARP is where the GPU's work runs.
#include "core/PngImage.h"
#include "gpu/PrecompiledShaders.h"
#include "support/ImageComparison.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <windows.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace firmament::test {
namespace {

using namespace std::chrono_literals;

// A small scene that keeps every technique (the soak's base: the clouds' grid and the shadow
// cascades made small), so that even a full-screen frame takes seconds, not minutes, on WARP.
// The clock stands still (the clouds' wind and pulses), and the exposure is each frame's own
// measure (no light adaptation, which a held clock would hold at the first size's exposure), so
// that a window's frames match a headless capture whatever their number and the sizes before.
// File changes do not reload shaders by themselves: F8 does, when the test says so.
const std::vector<std::wstring> kScene{L"--time-step", L"0",
                                       L"--set", L"clouds.rings=1",
                                       L"--set", L"clouds.ringDimension=16",
                                       L"--set", L"clouds.maxLayers=1",
                                       L"--set", L"shadows.cascades=1",
                                       L"--set", L"toneMapping.lightAdaptation=off",
                                       L"--set", L"shaders.autoReload=off"};
constexpr int kStartWidth = 160, kStartHeight = 90;
constexpr auto kFrameTimeout = 180s;  // the longest wait for one event's frame (a full-screen one)

std::filesystem::path scratchFolder(const std::string& name) {
    // One per test process: CTest runs two tests at once.
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-window-" + name + "-" + std::to_string(GetCurrentProcessId()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

std::vector<std::wstring> withScene(std::vector<std::wstring> arguments) {
    arguments.insert(arguments.end(), kScene.begin(), kScene.end());
    return arguments;
}

// The headless frame of the same view at width x height (made once per size).
const Rgba8Image& reference(int width, int height) {
    static std::map<std::pair<int, int>, Rgba8Image> made;
    auto& image = made[{width, height}];
    if (image.width == 0) {
        const auto folder = scratchFolder("reference");
        const std::wstring size = std::to_wstring(width) + L"x" + std::to_wstring(height);
        const ProcessResult run = runProcess(
            firmamentExe(), withScene({L"--headless", L"--frames", L"3", L"--resolution", size, L"--capture", (folder / "frame.png").wstring()}));
        EXPECT_EQ(run.exitCode, 0u) << run.output;
        if (run.exitCode == 0) image = readPng(folder / "frame.png");
        std::filesystem::remove_all(folder);
    }
    return image;
}

struct FoundWindow {
    DWORD processId;
    HWND hwnd;
};

// The program's top-level window (class FirmamentWindow), once it exists.
HWND findWindow(const RunningProcess& program) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < deadline) {
        FoundWindow found{program.id(), nullptr};
        EnumWindows(
            [](HWND hwnd, LPARAM data) -> BOOL {
                auto* f = reinterpret_cast<FoundWindow*>(data);
                DWORD owner = 0;
                GetWindowThreadProcessId(hwnd, &owner);
                wchar_t name[64] = {};
                GetClassNameW(hwnd, name, 64);
                if (owner != f->processId || std::wstring(name) != L"FirmamentWindow") return TRUE;
                f->hwnd = hwnd;
                return FALSE;
            },
            reinterpret_cast<LPARAM>(&found));
        if (found.hwnd) return found.hwnd;
        std::this_thread::sleep_for(100ms);
    }
    return nullptr;
}

SIZE clientSize(HWND hwnd) {
    RECT r{};
    GetClientRect(hwnd, &r);
    return {r.right - r.left, r.bottom - r.top};
}

// Waits until the client area is width x height; false when it never became that.
bool waitForClientSize(HWND hwnd, int width, int height) {
    const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
    while (std::chrono::steady_clock::now() < deadline) {
        const SIZE s = clientSize(hwnd);
        if (s.cx == width && s.cy == height) return true;
        std::this_thread::sleep_for(100ms);
    }
    return false;
}

// As dragging the window's border does: the outer size that gives this client area.
void setClientSize(HWND hwnd, int width, int height) {
    RECT r{0, 0, width, height};
    AdjustWindowRectEx(&r, static_cast<DWORD>(GetWindowLongW(hwnd, GWL_STYLE)), FALSE, static_cast<DWORD>(GetWindowLongW(hwnd, GWL_EXSTYLE)));
    SetWindowPos(hwnd, nullptr, 0, 0, r.right - r.left, r.bottom - r.top, SWP_NOMOVE | SWP_NOZORDER | SWP_NOACTIVATE);
}

void pressKey(HWND hwnd, WPARAM key) {
    PostMessageW(hwnd, WM_KEYDOWN, key, 1);
    PostMessageW(hwnd, WM_KEYUP, key, static_cast<LPARAM>(1 | (1u << 30) | (1u << 31)));
}

void pressAltEnter(HWND hwnd) {
    constexpr LPARAM kAltDown = 1 << 29;  // the context code: Alt is held
    PostMessageW(hwnd, WM_SYSKEYDOWN, VK_RETURN, 1 | kAltDown);
    PostMessageW(hwnd, WM_SYSKEYUP, VK_RETURN, static_cast<LPARAM>(1 | kAltDown | (1u << 30) | (1u << 31)));
}

// A windowed firmament.exe with its captures in `folder`: F12 writes window-shot-N.png.
class WindowedProgram {
public:
    WindowedProgram(const std::filesystem::path& folder, std::vector<std::wstring> extra = {})
        : folder_(folder),
          atStart_(reference(kStartWidth, kStartHeight)),  // first: the headless run also fills the table cache
          program_(firmamentExe(), [&] {
              std::vector<std::wstring> arguments{L"--resolution", std::to_wstring(kStartWidth) + L"x" + std::to_wstring(kStartHeight),
                                                  L"--capture", (folder / "window.png").wstring()};
              arguments = withScene(arguments);
              arguments.insert(arguments.end(), extra.begin(), extra.end());  // after the scene: a test's --set wins
              return arguments;
          }()),
          hwnd_(findWindow(program_)) {}
    ~WindowedProgram() {
        if (::testing::Test::HasFailure()) std::printf("firmament.exe's output:\n%s\n", program_.output().c_str());
    }
    WindowedProgram(const WindowedProgram&) = delete;
    WindowedProgram& operator=(const WindowedProgram&) = delete;

    HWND hwnd() const { return hwnd_; }
    RunningProcess& program() { return program_; }
    // The headless capture of the window's first view at the start's size.
    const Rgba8Image& atStart() const { return atStart_; }

    // F12, and the frame it captured (empty, with a failure, when none came).
    Rgba8Image shot() {
        pressKey(hwnd_, VK_F12);
        const int n = ++shots_;
        const auto png = folder_ / ("window-shot-" + std::to_string(n) + ".png");
        const std::string logged = "captured " + png.string();
        if (!program_.waitForOutput(logged, kFrameTimeout)) {
            ADD_FAILURE() << "no shot " << n << " (" << png.string() << ") came:\n" << program_.output();
            return {};
        }
        return readPng(png);
    }

    // WM_CLOSE, as the window's close button sends it: the program ends with 0.
    void close() {
        PostMessageW(hwnd_, WM_CLOSE, 0, 0);
        const auto code = program_.waitForExit(kFrameTimeout);
        ASSERT_TRUE(code.has_value()) << "the program did not end after WM_CLOSE:\n" << program_.output();
        EXPECT_EQ(*code, 0u) << program_.output();
    }

private:
    std::filesystem::path folder_;
    const Rgba8Image& atStart_;
    RunningProcess program_;
    HWND hwnd_;
    int shots_ = 0;
};

// Where a failing comparison leaves its images: build/mingw/test-output/window.
std::filesystem::path failureFolder() { return executableFolder().parent_path() / "test-output" / "window"; }

// The windowed frame is the headless one: within one 8-bit step per channel.
void expectFrame(const Rgba8Image& shot, const Rgba8Image& expected, const std::string& what) {
    ASSERT_GT(expected.width, 0) << what << ": no reference";
    ASSERT_EQ(shot.width, expected.width) << what;
    ASSERT_EQ(shot.height, expected.height) << what;
    const golden::Comparison c = golden::compare(shot, expected);
    if (c.maxDifference > 1) {
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::string name = test + "-" + what;
        std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)) && ch != '-'; }, '_');
        std::filesystem::create_directories(failureFolder());
        writePng(failureFolder() / (name + ".window.png"), shot);
        writePng(failureFolder() / (name + ".expected.png"), expected);
        ADD_FAILURE() << what << ": the window's frame and the expected one are in " << failureFolder().string() << " as " << name
                      << ".window.png and .expected.png";
    }
    EXPECT_LE(c.maxDifference, 1) << what << ": " << c.differingPixels << " pixels differ, PSNR " << c.psnrDb << " dB, worst at ("
                                  << c.worstPixel.x << ", " << c.worstPixel.y << ")";
    std::printf("%s: %dx%d, largest difference %d/255 (%zu pixels differ)\n", what.c_str(), shot.width, shot.height, c.maxDifference,
                c.differingPixels);
}

TEST(Window, ResizedTo1x1AndToLargeSizesTheNextFrameIsRight) {
    const auto folder = scratchFolder("resize");
    WindowedProgram window(folder);
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    ASSERT_TRUE(waitForClientSize(window.hwnd(), kStartWidth, kStartHeight));
    const Rgba8Image first = window.shot();
    expectFrame(first, window.atStart(), "at start");

    // 1x1. The window keeps its smallest tracking width (Wine grants 111x1), and a side below the
    // renderer's 16 is drawn at 16 and stretched by the swap chain.
    setClientSize(window.hwnd(), 1, 1);
    const SIZE tiny = clientSize(window.hwnd());
    EXPECT_TRUE(tiny.cx < 16 || tiny.cy < 16) << tiny.cx << "x" << tiny.cy;
    expectFrame(window.shot(), reference(std::max<int>(tiny.cx, 16), std::max<int>(tiny.cy, 16)),
                "client 1x1 (granted " + std::to_string(tiny.cx) + "x" + std::to_string(tiny.cy) + ")");

    // An odd size (half- and quarter-resolution passes round), then one beyond the 1920x1080 screen.
    setClientSize(window.hwnd(), 333, 187);
    ASSERT_TRUE(waitForClientSize(window.hwnd(), 333, 187));
    expectFrame(window.shot(), reference(333, 187), "client 333x187");
    // Asked for more than the screen, the window gets at most the screen and its frame (Wine
    // grants 1924x1058 of the 1920x1080 Xvfb screen).
    setClientSize(window.hwnd(), 2400, 1350);
    const SIZE large = clientSize(window.hwnd());
    EXPECT_GE(double(large.cx) * large.cy, 0.95 * GetSystemMetrics(SM_CXSCREEN) * GetSystemMetrics(SM_CYSCREEN)) << large.cx << "x" << large.cy;
    expectFrame(window.shot(), reference(large.cx, large.cy), "client " + std::to_string(large.cx) + "x" + std::to_string(large.cy));

    setClientSize(window.hwnd(), kStartWidth, kStartHeight);
    ASSERT_TRUE(waitForClientSize(window.hwnd(), kStartWidth, kStartHeight));
    expectFrame(window.shot(), first, "back at the start's size");
    window.close();
    EXPECT_EQ(window.program().output().find("[firmament] error"), std::string::npos) << window.program().output();
    std::filesystem::remove_all(folder);
}

TEST(Window, MinimizedItUsesNoTimeAndRestoredItDrawsTheSameFrame) {
    const auto folder = scratchFolder("minimize");
    WindowedProgram window(folder);
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    const Rgba8Image before = window.shot();
    expectFrame(before, window.atStart(), "before minimizing");

    // As the title bar's button and the task bar do. The program logs the CPU time it used while
    // minimized (on WARP the GPU's work is CPU time too): a frame at this size takes more than
    // 0.1 s of it, so 3 s of frames would take seconds; asleep it takes a few hundredths (Wine's
    // own threads), and the bound leaves room for a busy machine.
    PostMessageW(window.hwnd(), WM_SYSCOMMAND, SC_MINIMIZE, 0);
    ASSERT_TRUE(window.program().waitForOutput("window minimized after frame", kFrameTimeout)) << window.program().output();
    EXPECT_TRUE(IsIconic(window.hwnd()));
    std::this_thread::sleep_for(3s);
    PostMessageW(window.hwnd(), WM_SYSCOMMAND, SC_RESTORE, 0);
    ASSERT_TRUE(window.program().waitForOutput("is next", kFrameTimeout)) << window.program().output();
    EXPECT_FALSE(IsIconic(window.hwnd()));
    const std::string output = window.program().output();
    const size_t line = output.find("window restored after ");
    ASSERT_NE(line, std::string::npos) << output;
    double seconds = 0.0, cpu = -1.0;
    ASSERT_EQ(std::sscanf(output.c_str() + line, "window restored after %lf s minimized, using %lf s of CPU time", &seconds, &cpu), 2)
        << output.substr(line, 120);
    EXPECT_GE(seconds, 3.0);
    EXPECT_LT(cpu, 0.3) << "minimized for " << seconds << " s, the program used " << cpu << " s of CPU time";
    std::printf("minimized for %.1f s: %.3f s of CPU time\n", seconds, cpu);
    ASSERT_TRUE(waitForClientSize(window.hwnd(), kStartWidth, kStartHeight));
    expectFrame(window.shot(), before, "restored");
    window.close();
    std::filesystem::remove_all(folder);
}

TEST(Window, AltEnterGoesFullScreenAndBack) {
    const auto folder = scratchFolder("full-screen");
    WindowedProgram window(folder);
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    const Rgba8Image windowed = window.shot();
    expectFrame(windowed, window.atStart(), "windowed");
    RECT original{};
    GetWindowRect(window.hwnd(), &original);

    pressAltEnter(window.hwnd());
    const int screenWidth = GetSystemMetrics(SM_CXSCREEN), screenHeight = GetSystemMetrics(SM_CYSCREEN);
    ASSERT_TRUE(waitForClientSize(window.hwnd(), screenWidth, screenHeight)) << "client " << clientSize(window.hwnd()).cx << "x"
                                                                              << clientSize(window.hwnd()).cy;
    EXPECT_EQ(GetWindowLongW(window.hwnd(), GWL_STYLE) & WS_CAPTION, 0) << "full screen is borderless";
    expectFrame(window.shot(), reference(screenWidth, screenHeight), "full screen");

    pressAltEnter(window.hwnd());
    ASSERT_TRUE(waitForClientSize(window.hwnd(), kStartWidth, kStartHeight)) << "client " << clientSize(window.hwnd()).cx << "x"
                                                                              << clientSize(window.hwnd()).cy;
    RECT restored{};
    GetWindowRect(window.hwnd(), &restored);
    EXPECT_TRUE(EqualRect(&original, &restored)) << "the window is back where it was";
    EXPECT_EQ(GetWindowLongW(window.hwnd(), GWL_STYLE) & WS_CAPTION, WS_CAPTION);
    expectFrame(window.shot(), windowed, "windowed again");
    window.close();
    std::filesystem::remove_all(folder);
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

// A copy of the program's HLSL folder in `folder`, for a test to edit: the hot reload tests
// edit the tone mapping's last line.
struct EditableShaders {
    std::filesystem::path sources, toneMapping;
    std::string original;  // tone_mapping.hlsl as built
    static constexpr const char* kEnding = "return float4(display, 1.0);";

    explicit EditableShaders(const std::filesystem::path& folder) {
        const auto sourceRoot = PrecompiledShaders(productShaders()).sourceRoot();
        EXPECT_TRUE(sourceRoot.has_value()) << "the program's shader manifest names no #source folder";
        if (!sourceRoot) return;
        sources = folder / "shaders";
        std::filesystem::copy(*sourceRoot, sources, std::filesystem::copy_options::recursive);
        toneMapping = sources / "postfx" / "tone_mapping.hlsl";
        original = readText(toneMapping);
    }
    bool usable() const { return original.find(kEnding) != std::string::npos; }
    // The tone mapping with red and blue swapped in its output.
    std::string swapped() const {
        std::string text = original;
        return text.replace(text.find(kEnding), std::string(kEnding).size(), "return float4(display.bgr, 1.0);");
    }
};

// `before` with red and blue swapped, as the swapped tone mapping draws it.
Rgba8Image swappedRedBlue(Rgba8Image image) {
    for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) std::swap(image.pixels[i], image.pixels[i + 2]);
    return image;
}

// The time from saving an edit to its frame, reported, not asserted (a shared machine's wall
// clock is no measure to fail on; the goal is 3 s, docs/controls.md), with the program's line.
void reportReloadTime(const char* what, std::chrono::steady_clock::time_point saved, const std::string& log) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - saved).count();
    const size_t line = log.find("shaders reloaded:");
    const std::string said = line == std::string::npos ? std::string("(none)") : log.substr(line, log.find('\n', line) - line);
    std::printf("%s: %.2f s from saving the edit to its frame captured; the program's line: %s\n", what, seconds, said.c_str());
}

TEST(Window, F8ReloadsASavedEditAndABrokenEditKeepsTheOldShaderAndShowsTheError) {
    const auto folder = scratchFolder("hot-reload");
    const EditableShaders shaders(folder);
    ASSERT_TRUE(shaders.usable()) << "tone_mapping.hlsl no longer ends with " << EditableShaders::kEnding;

    WindowedProgram window(folder, {L"--shader-source", shaders.sources.wstring()});
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    const Rgba8Image before = window.shot();
    expectFrame(before, window.atStart(), "before the edit");

    // A saved edit that swaps red and blue: after F8 the frame is the old one with them swapped.
    const std::string swapped = shaders.swapped();
    const auto saved = std::chrono::steady_clock::now();
    writeText(shaders.toneMapping, swapped);
    pressKey(window.hwnd(), VK_F8);
    ASSERT_TRUE(window.program().waitForOutput("shaders reloaded:", kFrameTimeout)) << window.program().output();
    const Rgba8Image edited = window.shot();
    reportReloadTime("hot reload (F8)", saved, window.program().output());
    expectFrame(edited, swappedRedBlue(before), "after the edit (red and blue swapped)");

    // A broken edit: the reload fails, says where, and the edited shader stays in use.
    std::string broken = swapped;
    broken.replace(broken.find("display.bgr, 1.0"), 16, "display.bgr 1.0");
    writeText(shaders.toneMapping, broken);
    pressKey(window.hwnd(), VK_F8);
    // The reload's summary follows its errors in the log.
    ASSERT_TRUE(window.program().waitForOutput("shaders reloaded:", kFrameTimeout, 2)) << window.program().output();
    const std::string output = window.program().output();
    const size_t error = output.find("[firmament] error: shader reload of 'postfx' failed; the previous shaders stay in use:");
    ASSERT_NE(error, std::string::npos) << output;
    EXPECT_NE(output.find("postfx/tone_mapping.hlsl|ps_main", error), std::string::npos) << output;
    EXPECT_NE(output.find("syntax error", error), std::string::npos) << output;
    expectFrame(window.shot(), edited, "after the broken edit");
    window.close();
    std::filesystem::remove_all(folder);
}

// With shaders.autoReload on (the default), saving an edit is enough: the program sees the file
// change (it looks four times a second), compiles the edited technique's permutations in use and
// draws with them. The time from saving to the new frame is reported (the goal is 3 s).
TEST(Window, ASavedEditIsDrawnWithoutF8AndTheTimeIsReported) {
    const auto folder = scratchFolder("auto-reload");
    const EditableShaders shaders(folder);
    ASSERT_TRUE(shaders.usable()) << "tone_mapping.hlsl no longer ends with " << EditableShaders::kEnding;

    WindowedProgram window(folder, {L"--shader-source", shaders.sources.wstring(), L"--set", L"shaders.autoReload=on"});
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    const Rgba8Image before = window.shot();
    expectFrame(before, window.atStart(), "before the edit");

    const auto saved = std::chrono::steady_clock::now();
    writeText(shaders.toneMapping, shaders.swapped());
    ASSERT_TRUE(window.program().waitForOutput("shaders reloaded:", kFrameTimeout)) << window.program().output();
    const Rgba8Image edited = window.shot();
    reportReloadTime("automatic reload", saved, window.program().output());
    EXPECT_NE(window.program().output().find("shader source changed:"), std::string::npos) << window.program().output();
    expectFrame(edited, swappedRedBlue(before), "after the saved edit (red and blue swapped)");
    window.close();
    std::filesystem::remove_all(folder);
}

TEST(Window, ClosedWhileTheTablesArePrecomputedItEndsCleanlyAndLeavesNoHalfFile) {
    const auto folder = scratchFolder("close-early");
    const auto cache = folder / "cache";
    WindowedProgram window(folder, {L"--cache-dir", cache.wstring()});
    ASSERT_NE(window.hwnd(), nullptr) << window.program().output();
    // A window computes the tables a unit of work per frame: close it a few frames in.
    ASSERT_TRUE(window.program().waitForOutput("atmosphere: pre-computing", kFrameTimeout)) << window.program().output();
    ASSERT_TRUE(window.program().waitForOutput("atmosphere: 10%", kFrameTimeout)) << window.program().output();
    window.close();
    const std::string output = window.program().output();
    EXPECT_EQ(output.find("atmosphere: tables"), std::string::npos) << "the tables were finished before the close:\n" << output;
    EXPECT_EQ(output.find("[firmament] error"), std::string::npos) << output;
    std::error_code ec;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(cache, ec))
        EXPECT_EQ(entry.path().filename().string().find(".part-"), std::string::npos) << "a half-written file: " << entry.path().string();
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
