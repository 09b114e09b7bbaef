// firmament_crash_probe: writes through a null pointer, on purpose. Under Wine a crash is handed
// to winedbg; the test wine.a_crash_fails_with_its_report (tests/CMakeLists.txt) holds that it
// ends the program at once with its report printed, instead of waiting on Wine's crash dialog
// until the test's timeout (docs/building.md, "A passed test that does not end").
#include <cstdio>

int main() {
    std::printf("firmament_crash_probe: writing through a null pointer\n");
    std::fflush(stdout);
    volatile int* nowhere = nullptr;
    *nowhere = 1;
    return 0;
}
