#include "support/HeadlessCapture.h"

#include "core/Text.h"
#include "support/TestPaths.h"

#include <windows.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <memory>

namespace firmament::test {

namespace {

// A capture may compute tables the cache does not hold yet (a minute at Full size) and draw
// clouds at two seconds a frame; CTest's timeout for the test is the outer bound.
constexpr std::chrono::minutes kCaptureTimeout{15};

std::vector<std::wstring> sizeArguments(const HeadlessCapture& c) {
    return {L"--headless", L"--frames", std::to_wstring(c.frames), L"--resolution", std::to_wstring(c.width) + L"x" + std::to_wstring(c.height)};
}

// As the tests ran before the batch: one firmament.exe for this capture.
ProcessResult captureInItsOwnProcess(const HeadlessCapture& c) {
    std::vector<std::wstring> arguments = sizeArguments(c);
    const auto fragment = std::filesystem::path(c.png).replace_extension(".settings.json");
    if (!c.fragment.empty()) {
        std::ofstream(fragment) << c.fragment.dump(2);
        arguments.insert(arguments.end(), {L"--settings", fragment.wstring()});
    }
    for (const std::wstring& s : c.settings) arguments.insert(arguments.end(), {L"--set", s});
    if (c.captureUi) arguments.push_back(L"--capture-ui");
    arguments.insert(arguments.end(), {L"--capture", c.png.wstring()});
    ProcessResult result = runProcess(firmamentExe(), arguments);
    std::error_code ec;
    std::filesystem::remove(fragment, ec);
    return result;
}

// The test process's one firmament.exe --batch -, started at its first capture (and again after
// it ended); it ends when this process does and its standard input closes.
class CaptureService {
public:
    ProcessResult capture(const HeadlessCapture& c) {
        if (!program_ || program_->waitForExit(std::chrono::milliseconds(0))) {
            program_ = std::make_unique<RunningProcess>(firmamentExe(), std::vector<std::wstring>{L"--batch", L"-"}, InputPipe::Yes);
        }
        const std::string id = "capture-" + std::to_string(++requests_);
        nlohmann::json request = {{"id", id},
                                  {"resolution", {c.width, c.height}},
                                  {"frames", c.frames},
                                  {"settings", c.fragment.is_null() ? nlohmann::json::object() : c.fragment},
                                  {"captureUi", c.captureUi},
                                  {"capture", narrow(c.png.wstring())}};
        request["set"] = nlohmann::json::array();
        for (const std::wstring& s : c.settings) request["set"].push_back(narrow(s));
        const size_t from = program_->outputSize();
        ProcessResult result;
        if (!program_->writeInput(request.dump() + "\n")) {
            result.exitCode = 1;
            result.output = "could not send the request to firmament.exe --batch -; its output:\n" + program_->output();
            program_.reset();
            return result;
        }
        const auto answer = program_->waitForFirst({"batch: done " + id + "\n", "batch: done " + id + "\r\n", "batch: refused " + id + ":"},
                                                   from, kCaptureTimeout);
        result.output = program_->output().substr(from);
        if (answer && *answer < 2) return result;
        result.exitCode = 1;
        if (!answer) {
            const auto code = program_->waitForExit(std::chrono::milliseconds(0));
            result.output += code ? "\n(firmament.exe --batch - ended with exit code " + std::to_string(*code) + ")"
                                  : "\n(no answer from firmament.exe --batch - in time)";
            program_.reset();
        }
        return result;
    }

private:
    std::unique_ptr<RunningProcess> program_;
    int requests_ = 0;
};

}  // namespace

bool separateCaptures() {
    const char* value = std::getenv("FIRMAMENT_TEST_SEPARATE_CAPTURES");
    return value && std::string(value) == "1";
}

ProcessResult captureHeadless(const HeadlessCapture& capture) {
    std::filesystem::create_directories(capture.png.parent_path());
    if (separateCaptures()) return captureInItsOwnProcess(capture);
    static CaptureService service;  // one program for the test process's captures
    return service.capture(capture);
}

}  // namespace firmament::test
