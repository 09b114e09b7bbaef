# Third-party libraries, found the same way on both builds: on Linux they are cross-built
# into the sysroot's MinGW prefix by tools/sysroot/build-third-party; on Windows vcpkg's
# manifest (vcpkg.json) provides them under the same package and target names.
# Static zlib (also for OpenEXR, which looks it up in its own config): the MinGW executables
# carry everything they need.
set(ZLIB_USE_STATIC_LIBS ON)

find_package(glm CONFIG REQUIRED)              # glm::glm
find_package(Imath CONFIG REQUIRED)            # Imath::Imath
find_package(OpenEXR CONFIG REQUIRED)          # OpenEXR::OpenEXR
find_package(hidapi CONFIG REQUIRED)           # hidapi::hidapi
find_package(imgui CONFIG REQUIRED)            # imgui::imgui (win32 + dx11 backends)
find_package(nlohmann_json CONFIG REQUIRED)    # nlohmann_json::nlohmann_json
find_package(ZLIB REQUIRED)                    # ZLIB::ZLIB (PNG encoding)
