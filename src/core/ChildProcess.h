#pragma once
// Running a compiler as a child process and collecting what it printed. Two kinds:
//  - a Windows program (fxc.exe): CreateProcess with a pipe, waiting for its exit code;
//  - under Wine, a program of the Linux host (/usr/bin/vkd3d-compiler). Wine starts such a
//    process but hands back a handle that is signalled at once, with exit code 0, and does
//    not connect its output to our pipes. So it runs through /bin/sh with its output sent to
//    a file and its exit status written last, and we wait for that status file.
#include <filesystem>
#include <optional>
#include <string>

namespace firmament {

struct ChildResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

bool runningUnderWine();

// The host's path of a Windows path under Wine (Z:\src\x -> /src/x); nullopt elsewhere.
std::optional<std::string> hostPath(const std::filesystem::path& path);

// Quotes one argument for a POSIX shell.
std::string shellQuote(const std::string& text);

// Throws Error when the program cannot be started or does not finish within the timeout.
ChildResult runWindowsProgram(const std::wstring& commandLine, const std::filesystem::path& workingFolder,
                              int timeoutMilliseconds);
ChildResult runHostShellCommand(const std::string& shellCommand, const std::filesystem::path& scratchFolder,
                                int timeoutMilliseconds);

}  // namespace firmament
