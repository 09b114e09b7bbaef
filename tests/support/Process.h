#pragma once
// Runs a program and collects its exit code and its output (stdout and stderr together), for
// the tests that drive firmament.exe from outside: to completion (runProcess), or left running
// while the test works its window (RunningProcess).
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace firmament::test {

struct ProcessResult {
    unsigned long exitCode = 0;
    std::string output;
};

ProcessResult runProcess(const std::wstring& program, const std::vector<std::wstring>& arguments);

// A program started and left running; its output is read as it comes. The destructor ends the
// program if it still runs.
enum class InputPipe { No, Yes };  // No: the program reads this process's own standard input

class RunningProcess {
public:
    // throws std::runtime_error
    RunningProcess(const std::wstring& program, const std::vector<std::wstring>& arguments, InputPipe input = InputPipe::No);
    ~RunningProcess();
    RunningProcess(const RunningProcess&) = delete;
    RunningProcess& operator=(const RunningProcess&) = delete;

    unsigned long id() const;
    std::string output() const;  // what it has written so far
    size_t outputSize() const;
    // With InputPipe::Yes: writes to the program's standard input (false when it cannot), or
    // closes it (the program reads its end).
    bool writeInput(const std::string& text);
    void closeInput();
    // The index of the first of `texts` found in the output after its first `from` characters,
    // once one is; nullopt when the time ran out or the program ended first.
    std::optional<size_t> waitForFirst(const std::vector<std::string>& texts, size_t from, std::chrono::milliseconds timeout) const;
    // True once `text` is in the output `times` times; false when the time ran out or the
    // program ended first.
    bool waitForOutput(const std::string& text, std::chrono::milliseconds timeout, int times = 1) const;
    // The exit code; nullopt when the program still runs after `timeout`.
    std::optional<unsigned long> waitForExit(std::chrono::milliseconds timeout);

private:
    struct Impl;
    std::shared_ptr<Impl> impl_;  // shared with the thread that reads the output
};

}  // namespace firmament::test
