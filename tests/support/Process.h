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
class RunningProcess {
public:
    RunningProcess(const std::wstring& program, const std::vector<std::wstring>& arguments);  // throws std::runtime_error
    ~RunningProcess();
    RunningProcess(const RunningProcess&) = delete;
    RunningProcess& operator=(const RunningProcess&) = delete;

    unsigned long id() const;
    std::string output() const;  // what it has written so far
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
