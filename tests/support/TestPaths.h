#pragma once
// Where the test executables find what the build put beside them.
#include <windows.h>

#include <filesystem>
#include <string>

namespace firmament::test {

inline std::filesystem::path executableFolder() {
    wchar_t path[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, path, MAX_PATH);
    return std::filesystem::path(std::wstring(path, length)).parent_path();
}

inline std::filesystem::path productShaders() { return executableFolder() / "shaders"; }
inline std::filesystem::path testShaders() { return executableFolder() / "test-shaders"; }
inline std::wstring firmamentExe() { return (executableFolder() / "firmament.exe").wstring(); }

}  // namespace firmament::test
