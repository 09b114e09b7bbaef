# Precompiled headers (docs/building.md, "Build time"): the standard library, GLM and
# nlohmann-json are parsed once per target group instead of once per translation unit. Not
# <windows.h> (nor the Direct3D headers that include it): its `near` and `far` macros would
# reach every file, where they are ordinary names. The project's libraries share one
# precompiled header, made by firmament_core; the test executables share another, with
# GoogleTest, made by firmament_test_support. Every source still includes what it uses: the
# precompiled header only saves the parsing.
option(FIRMAMENT_PRECOMPILED_HEADERS "Precompile the heavy third-party headers" ON)

set(FIRMAMENT_PCH_LIBRARY_HEADERS
    <algorithm> <array> <cmath> <cstdint> <cstdio> <cstring> <filesystem> <fstream> <functional>
    <map> <memory> <optional> <span> <string> <string_view> <vector>
    <glm/glm.hpp> <nlohmann/json.hpp>)

# firmament_precompile(TARGET [FROM OTHER] [EXTRA header...]): TARGET makes its own precompiled
# header of the library headers (and EXTRA), or reuses OTHER's.
function(firmament_precompile target)
    if(NOT FIRMAMENT_PRECOMPILED_HEADERS)
        return()
    endif()
    cmake_parse_arguments(ARG "" "FROM" "EXTRA" ${ARGN})
    if(ARG_FROM)
        target_precompile_headers(${target} REUSE_FROM ${ARG_FROM})
    else()
        target_precompile_headers(${target} PRIVATE ${FIRMAMENT_PCH_LIBRARY_HEADERS} ${ARG_EXTRA})
    endif()
endfunction()
