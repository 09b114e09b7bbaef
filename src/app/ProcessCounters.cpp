#include "app/ProcessCounters.h"

#include "core/Error.h"

#include <windows.h>
// (psapi.h after windows.h)
#include <psapi.h>

#include <string>
#include <vector>

namespace firmament {

namespace {

// NtQuerySystemInformation's SystemHandleInformation (class 16): a count, then one entry per
// open handle in the system. Declared here: the SDK's winternl.h leaves the class out.
constexpr ULONG kSystemHandleInformation = 16;
constexpr LONG kStatusInfoLengthMismatch = static_cast<LONG>(0xC0000004);
struct SystemHandleEntry {
    ULONG ownerProcessId;
    BYTE objectType;
    BYTE flags;
    USHORT handle;
    PVOID object;
    ACCESS_MASK access;
};
using QuerySystemInformation = LONG(WINAPI*)(ULONG, PVOID, ULONG, PULONG);

long handlesInTheSystemTable() {
    const auto query = reinterpret_cast<QuerySystemInformation>(
        reinterpret_cast<void*>(GetProcAddress(GetModuleHandleW(L"ntdll.dll"), "NtQuerySystemInformation")));
    if (!query) throw Error("counting handles: ntdll.dll has no NtQuerySystemInformation");
    std::vector<unsigned char> buffer(1 << 16);
    LONG status = 0;
    for (;;) {
        ULONG length = 0;
        status = query(kSystemHandleInformation, buffer.data(), static_cast<ULONG>(buffer.size()), &length);
        if (status != kStatusInfoLengthMismatch || buffer.size() >= (1u << 30)) break;
        buffer.resize(buffer.size() * 2);
    }
    if (status < 0) throw Error("counting handles: NtQuerySystemInformation failed (NTSTATUS " + std::to_string(status) + ")");
    const ULONG count = *reinterpret_cast<const ULONG*>(buffer.data());
    const auto* entries = reinterpret_cast<const SystemHandleEntry*>(buffer.data() + sizeof(ULONG_PTR));
    const size_t room = (buffer.size() - sizeof(ULONG_PTR)) / sizeof(SystemHandleEntry);
    const DWORD self = GetCurrentProcessId();
    long mine = 0;
    for (size_t i = 0; i < count && i < room; ++i)
        if (entries[i].ownerProcessId == self) ++mine;
    return mine;
}

}  // namespace

double processCpuSeconds() {
    FILETIME created{}, exited{}, kernel{}, user{};
    if (!GetProcessTimes(GetCurrentProcess(), &created, &exited, &kernel, &user)) return -1.0;
    const auto seconds = [](const FILETIME& t) {
        return static_cast<double>((static_cast<unsigned long long>(t.dwHighDateTime) << 32) | t.dwLowDateTime) * 1e-7;
    };
    return seconds(kernel) + seconds(user);
}

ProcessCounters sampleProcessCounters() {
    ProcessCounters c;
    PROCESS_MEMORY_COUNTERS memory{};
    memory.cb = sizeof memory;
    if (!K32GetProcessMemoryInfo(GetCurrentProcess(), &memory, sizeof memory))
        throw Error("GetProcessMemoryInfo failed (error " + std::to_string(GetLastError()) + ")");
    c.privateBytes = memory.PagefileUsage;
    DWORD handles = 0;
    if (!GetProcessHandleCount(GetCurrentProcess(), &handles))
        throw Error("GetProcessHandleCount failed (error " + std::to_string(GetLastError()) + ")");
    c.handles = handles > 0 ? static_cast<long>(handles) : handlesInTheSystemTable();
    return c;
}

}  // namespace firmament
