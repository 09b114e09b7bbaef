#pragma once
// What the process holds of the system's resources, for the soak run.
//
// - Private bytes: PROCESS_MEMORY_COUNTERS::PagefileUsage, the commit charge (the memory
//   committed for this process alone) on Windows; under Wine, the Linux process's anonymous
//   resident memory and swap (Wine leaves PrivateUsage at 0).
// - Handles: GetProcessHandleCount; where it says 0 (Wine's is a stub), the entries of the
//   system's handle table that belong to this process (NtQuerySystemInformation,
//   SystemHandleInformation), which Wine's server keeps.
#include <cstdint>

namespace firmament {

struct ProcessCounters {
    std::uint64_t privateBytes = 0;
    long handles = 0;
};

ProcessCounters sampleProcessCounters();  // throws Error when the system cannot say

// The CPU time this process has used so far, user and kernel, every thread, in seconds
// (GetProcessTimes; under Wine it counts llvmpipe's threads too: measured, docs/building.md). On
// a CPU device this is the GPU's work too. -1 when the system cannot say.
double processCpuSeconds();

}  // namespace firmament
