#include "core/ChildProcess.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Text.h"

#include <windows.h>

#include <atomic>
#include <fstream>
#include <sstream>

namespace firmament {

namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

bool runningUnderWine() {
    const HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
    return ntdll && GetProcAddress(ntdll, "wine_get_version");
}

std::optional<std::string> hostPath(const std::filesystem::path& path) {
    using ToUnix = char*(CDECL*)(const wchar_t*);
    const HMODULE kernel32 = GetModuleHandleW(L"kernel32.dll");
    const auto toUnix = kernel32 ? reinterpret_cast<ToUnix>(reinterpret_cast<void*>(GetProcAddress(kernel32, "wine_get_unix_file_name")))
                                 : nullptr;
    if (!toUnix) return std::nullopt;
    char* hostName = toUnix(std::filesystem::absolute(path).wstring().c_str());
    if (!hostName) return std::nullopt;
    std::string result(hostName);
    HeapFree(GetProcessHeap(), 0, hostName);  // wine_get_unix_file_name allocates on the process heap
    return result;
}

std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

ChildResult runWindowsProgram(const std::wstring& commandLine, const std::filesystem::path& workingFolder,
                              int timeoutMilliseconds) {
    SECURITY_ATTRIBUTES inherit{sizeof(inherit), nullptr, TRUE};
    HANDLE readEnd = nullptr, writeEnd = nullptr;
    if (!CreatePipe(&readEnd, &writeEnd, &inherit, 0)) throw Error("CreatePipe failed");
    SetHandleInformation(readEnd, HANDLE_FLAG_INHERIT, 0);
    STARTUPINFOW startup{};
    startup.cb = sizeof(startup);
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdOutput = writeEnd;
    startup.hStdError = writeEnd;
    PROCESS_INFORMATION process{};
    std::wstring mutableLine = commandLine;
    const BOOL started = CreateProcessW(nullptr, mutableLine.data(), nullptr, nullptr, TRUE, CREATE_NO_WINDOW, nullptr,
                                        workingFolder.wstring().c_str(), &startup, &process);
    CloseHandle(writeEnd);
    if (!started) {
        CloseHandle(readEnd);
        throw Error("could not start " + narrow(commandLine) + " (error " + std::to_string(GetLastError()) + ")");
    }
    ChildResult result;
    char buffer[4096];
    DWORD read = 0;
    while (ReadFile(readEnd, buffer, sizeof(buffer), &read, nullptr) && read) result.output.append(buffer, read);
    CloseHandle(readEnd);
    const DWORD waited = WaitForSingleObject(process.hProcess, static_cast<DWORD>(timeoutMilliseconds));
    DWORD exitCode = 1;
    if (waited == WAIT_OBJECT_0) GetExitCodeProcess(process.hProcess, &exitCode);
    else TerminateProcess(process.hProcess, 1);
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);
    if (waited != WAIT_OBJECT_0) throw Error(narrow(commandLine) + " did not finish within " + std::to_string(timeoutMilliseconds) + " ms");
    result.exitCode = static_cast<int>(exitCode);
    return result;
}

ChildResult runHostShellCommand(const std::string& shellCommand, const std::filesystem::path& scratchFolder,
                                int timeoutMilliseconds) {
    static std::atomic<unsigned> counter{0};
    const std::string stem = "run-" + std::to_string(GetCurrentProcessId()) + "-" + std::to_string(counter++);
    const auto script = scratchFolder / (stem + ".sh");
    const auto log = scratchFolder / (stem + ".log");
    const auto status = scratchFolder / (stem + ".status");
    const auto hostScript = hostPath(script), hostLog = hostPath(log), hostStatus = hostPath(status);
    if (!hostScript || !hostLog || !hostStatus) throw Error("host programs can be run only under Wine");

    // The status file appears (renamed into place) only once the command has finished.
    const std::string text = "(" + shellCommand + ") >" + shellQuote(*hostLog) + " 2>&1\necho $? >" +
                             shellQuote(*hostStatus + ".tmp") + "\nmv " + shellQuote(*hostStatus + ".tmp") + " " +
                             shellQuote(*hostStatus) + "\n";
    writeFileText(script, text);

    std::wstring commandLine = L"/bin/sh \"" + std::filesystem::path(*hostScript).wstring() + L"\"";
    STARTUPINFOW startup{};
    startup.cb = sizeof(startup);
    PROCESS_INFORMATION process{};
    if (!CreateProcessW(nullptr, commandLine.data(), nullptr, nullptr, FALSE, CREATE_NO_WINDOW, nullptr, nullptr, &startup, &process))
        throw Error("could not start /bin/sh on the host (error " + std::to_string(GetLastError()) + ")");
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);

    const ULONGLONG deadline = GetTickCount64() + static_cast<ULONGLONG>(timeoutMilliseconds);
    std::error_code ec;
    while (!std::filesystem::exists(status, ec)) {
        if (GetTickCount64() > deadline) throw Error("host command did not finish within " + std::to_string(timeoutMilliseconds) + " ms: " + shellCommand);
        Sleep(2);
    }
    ChildResult result;
    result.exitCode = std::atoi(readText(status).c_str());
    result.output = readText(log);
    for (const auto& file : {script, log, status}) std::filesystem::remove(file, ec);
    return result;
}

}  // namespace firmament
