// The test executables' entry point: GoogleTest's, except for how the process ends. Under Wine,
// a test executable once hung after printing its results, while the process exited (one run in
// 211, under load, in a GPU test; not reproduced in 30 runs alone): ending the process once the
// results are out skips the exit path (static destructors, the Direct3D driver's unloading) where
// it hung, and CTest gets the exit code at once. The portable build (Linux, sanitizers) exits
// normally, so that LeakSanitizer checks the heap at exit.
#include <gtest/gtest.h>

#ifdef _WIN32
#include <windows.h>
#endif

#include <cstdio>

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    const int result = RUN_ALL_TESTS();
#ifdef _WIN32
    std::fflush(stdout);
    std::fflush(stderr);
    TerminateProcess(GetCurrentProcess(), static_cast<UINT>(result));
#endif
    return result;
}
