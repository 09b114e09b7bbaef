#include "support/Process.h"

#include <windows.h>

#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

namespace firmament::test {

namespace {
// Quoting as CommandLineToArgvW parses it back.
std::wstring quote(const std::wstring& argument) {
    if (!argument.empty() && argument.find_first_of(L" \t\"") == std::wstring::npos) return argument;
    std::wstring out = L"\"";
    size_t backslashes = 0;
    for (wchar_t c : argument) {
        if (c == L'\\') {
            ++backslashes;
            continue;
        }
        out.append(c == L'"' ? backslashes * 2 + 1 : backslashes, L'\\');
        backslashes = 0;
        out += c;
    }
    out.append(backslashes * 2, L'\\');
    return out + L"\"";
}

struct Started {
    PROCESS_INFORMATION process{};
    HANDLE output = nullptr;  // the read end of the program's stdout and stderr
    HANDLE input = nullptr;   // the write end of the program's stdin (with InputPipe)
};

Started start(const std::wstring& program, const std::vector<std::wstring>& arguments, bool pipeInput = false) {
    SECURITY_ATTRIBUTES inherit{sizeof inherit, nullptr, TRUE};
    HANDLE readEnd = nullptr, writeEnd = nullptr;
    if (!CreatePipe(&readEnd, &writeEnd, &inherit, 0)) throw std::runtime_error("CreatePipe failed");
    SetHandleInformation(readEnd, HANDLE_FLAG_INHERIT, 0);
    HANDLE inputRead = nullptr, inputWrite = nullptr;
    if (pipeInput) {
        if (!CreatePipe(&inputRead, &inputWrite, &inherit, 0)) throw std::runtime_error("CreatePipe failed");
        SetHandleInformation(inputWrite, HANDLE_FLAG_INHERIT, 0);  // only the program's end is inherited
    }

    std::wstring commandLine = quote(program);
    for (const auto& argument : arguments) commandLine += L" " + quote(argument);

    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdOutput = writeEnd;
    startup.hStdError = writeEnd;
    startup.hStdInput = pipeInput ? inputRead : GetStdHandle(STD_INPUT_HANDLE);
    Started started;
    const BOOL ok = CreateProcessW(program.c_str(), commandLine.data(), nullptr, nullptr, TRUE, 0, nullptr, nullptr, &startup,
                                   &started.process);
    CloseHandle(writeEnd);
    if (inputRead) CloseHandle(inputRead);
    if (!ok) {
        CloseHandle(readEnd);
        if (inputWrite) CloseHandle(inputWrite);
        throw std::runtime_error("CreateProcessW failed for the program under test");
    }
    started.output = readEnd;
    started.input = inputWrite;
    return started;
}
}  // namespace

ProcessResult runProcess(const std::wstring& program, const std::vector<std::wstring>& arguments) {
    const Started started = start(program, arguments);
    ProcessResult result;
    char buffer[4096];
    DWORD read = 0;
    while (ReadFile(started.output, buffer, sizeof buffer, &read, nullptr) && read > 0) result.output.append(buffer, read);
    WaitForSingleObject(started.process.hProcess, INFINITE);
    GetExitCodeProcess(started.process.hProcess, &result.exitCode);
    CloseHandle(started.process.hProcess);
    CloseHandle(started.process.hThread);
    CloseHandle(started.output);
    return result;
}

struct RunningProcess::Impl {
    Started started;
    std::thread reader;
    mutable std::mutex mutex;
    mutable std::condition_variable grew;
    std::string output;
    bool ended = false;  // the pipe was closed: the program (and everything that held it) ended

    ~Impl() {
        if (started.input) CloseHandle(started.input);
        CloseHandle(started.process.hProcess);
        CloseHandle(started.process.hThread);
        CloseHandle(started.output);
    }

    void read() {
        char buffer[4096];
        DWORD count = 0;
        while (ReadFile(started.output, buffer, sizeof buffer, &count, nullptr) && count > 0) {
            std::lock_guard lock(mutex);
            output.append(buffer, count);
            grew.notify_all();
        }
        std::lock_guard lock(mutex);
        ended = true;
        grew.notify_all();
    }
};

RunningProcess::RunningProcess(const std::wstring& program, const std::vector<std::wstring>& arguments, InputPipe input)
    : impl_(std::make_shared<Impl>()) {
    impl_->started = start(program, arguments, input == InputPipe::Yes);
    impl_->reader = std::thread([impl = impl_] { impl->read(); });
}

RunningProcess::~RunningProcess() {
    if (WaitForSingleObject(impl_->started.process.hProcess, 0) == WAIT_TIMEOUT) {
        TerminateProcess(impl_->started.process.hProcess, 1);
        WaitForSingleObject(impl_->started.process.hProcess, 10000);
    }
    // The pipe ends with the program. Should a process it started still hold it, the reader is
    // left to end with that one (it shares the state it reads into).
    bool ended = false;
    {
        std::unique_lock lock(impl_->mutex);
        ended = impl_->grew.wait_for(lock, std::chrono::seconds(10), [&] { return impl_->ended; });
    }
    if (ended) impl_->reader.join();
    else impl_->reader.detach();
}

unsigned long RunningProcess::id() const { return impl_->started.process.dwProcessId; }

bool RunningProcess::writeInput(const std::string& text) {
    if (!impl_->started.input) return false;
    DWORD written = 0;
    return WriteFile(impl_->started.input, text.data(), static_cast<DWORD>(text.size()), &written, nullptr) && written == text.size();
}

void RunningProcess::closeInput() {
    if (impl_->started.input) CloseHandle(std::exchange(impl_->started.input, nullptr));
}

size_t RunningProcess::outputSize() const {
    std::lock_guard lock(impl_->mutex);
    return impl_->output.size();
}

std::optional<size_t> RunningProcess::waitForFirst(const std::vector<std::string>& texts, size_t from, std::chrono::milliseconds timeout) const {
    std::optional<size_t> which;
    const auto found = [&] {
        for (size_t i = 0; i < texts.size(); ++i)
            if (impl_->output.size() > from && impl_->output.find(texts[i], from) != std::string::npos) {
                which = i;
                return true;
            }
        return false;
    };
    std::unique_lock lock(impl_->mutex);
    impl_->grew.wait_for(lock, timeout, [&] { return found() || impl_->ended; });
    return which;
}

std::string RunningProcess::output() const {
    std::lock_guard lock(impl_->mutex);
    return impl_->output;
}

bool RunningProcess::waitForOutput(const std::string& text, std::chrono::milliseconds timeout, int times) const {
    const auto found = [&] {
        int count = 0;
        for (size_t at = impl_->output.find(text); at != std::string::npos && count < times; at = impl_->output.find(text, at + text.size())) ++count;
        return count >= times;
    };
    std::unique_lock lock(impl_->mutex);
    return impl_->grew.wait_for(lock, timeout, [&] { return found() || impl_->ended; }) && found();
}

std::optional<unsigned long> RunningProcess::waitForExit(std::chrono::milliseconds timeout) {
    if (WaitForSingleObject(impl_->started.process.hProcess, static_cast<DWORD>(timeout.count())) != WAIT_OBJECT_0) return std::nullopt;
    DWORD code = 0;
    GetExitCodeProcess(impl_->started.process.hProcess, &code);
    // The rest of its output: the pipe closes with it.
    std::unique_lock lock(impl_->mutex);
    impl_->grew.wait_for(lock, std::chrono::seconds(10), [&] { return impl_->ended; });
    return code;
}

}  // namespace firmament::test
