#pragma once
// Runs a program to completion and collects its exit code and its output (stdout and
// stderr together), for the tests that drive firmament.exe from outside.
#include <string>
#include <vector>

namespace firmament::test {

struct ProcessResult {
    unsigned long exitCode = 0;
    std::string output;
};

ProcessResult runProcess(const std::wstring& program, const std::vector<std::wstring>& arguments);

}  // namespace firmament::test
