#pragma once
// Where the test executables find what the build put beside them.
#ifdef _WIN32
#include <windows.h>
#endif

#include <cstdlib>
#include <filesystem>
#include <string>

namespace firmament::test {

inline std::filesystem::path executableFolder() {
#ifdef _WIN32
    wchar_t path[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, path, MAX_PATH);
    return std::filesystem::path(std::wstring(path, length)).parent_path();
#else
    return std::filesystem::read_symlink("/proc/self/exe").parent_path();  // the portable build (Linux)
#endif
}

inline std::filesystem::path productShaders() { return executableFolder() / "shaders"; }
inline std::filesystem::path testShaders() { return executableFolder() / "test-shaders"; }
inline std::wstring firmamentExe() { return (executableFolder() / "firmament.exe").wstring(); }

// The Direct3D 11 implementation the tools chose for this run (tools/test --d3d11, which sets
// FIRMAMENT_D3D11; Wine passes it on): what the program must report it ran on.
inline std::string chosenD3D11Implementation() {
    const char* chosen = std::getenv("FIRMAMENT_D3D11");
    return chosen != nullptr && *chosen != '\0' ? chosen : "wined3d";
}

}  // namespace firmament::test
