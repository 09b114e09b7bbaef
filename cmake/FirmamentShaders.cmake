# HLSL compiled to DXBC at build time, so that a shader error fails the build with the
# compiler's own message.
#
#   firmament_shader_library(<target> ROOT <dir> OUTPUT <folder under bin/>)
#   firmament_add_shader(<target> FILE <path under ROOT> ENTRY <name> PROFILE <vs_5_0|...>
#                        [DEFINES NAME=VALUE ...] [INCLUDE_ROOT <dir>])
#
# INCLUDE_ROOT (default ROOT) is the folder #include paths are relative to: a test shader sets
# it to the program's shader folder to include the program's headers.
#
# Every shader permutation is identified by a key: file, entry point, profile and sorted
# defines, written "file|entry|profile|A=1,B=2". The library writes manifest.txt beside the
# .cso files, one "key<TAB>cso file" line per permutation; the program looks permutations up
# by that key (src/gpu/ShaderKey.h builds the same string). Its first line, "#source<TAB>ROOT",
# names the HLSL folder, which hot reload (F8) compiles from; a "#cache<TAB>SCRIPT" line, when the
# build compiles through cmake/shader-cache.sh, lets hot reload use the same cache.
#
# Compilers: vkd3d-compiler (Linux, the sysroot) or FXC (Windows SDK). Pick one with
# FIRMAMENT_SHADER_COMPILER=vkd3d|fxc; by default the first found is used.
set(FIRMAMENT_SHADER_COMPILER "auto" CACHE STRING "HLSL compiler at build time: auto, vkd3d or fxc")
set_property(CACHE FIRMAMENT_SHADER_COMPILER PROPERTY STRINGS auto vkd3d fxc)

if(FIRMAMENT_SHADER_COMPILER STREQUAL "auto" OR FIRMAMENT_SHADER_COMPILER STREQUAL "vkd3d")
    find_program(FIRMAMENT_VKD3D_COMPILER vkd3d-compiler)
endif()
if(FIRMAMENT_SHADER_COMPILER STREQUAL "auto" OR FIRMAMENT_SHADER_COMPILER STREQUAL "fxc")
    # FXC ships with the Windows SDK; CMake knows the SDK's bin folder on MSVC builds.
    find_program(FIRMAMENT_FXC fxc HINTS
        "${CMAKE_WINDOWS_KITS_10_DIR}/bin/${CMAKE_VS_WINDOWS_TARGET_PLATFORM_VERSION}/x64"
        "$ENV{WindowsSdkVerBinPath}/x64")
endif()

if(FIRMAMENT_VKD3D_COMPILER AND NOT FIRMAMENT_SHADER_COMPILER STREQUAL "fxc")
    set(FIRMAMENT_SHADER_BACKEND vkd3d)
elseif(FIRMAMENT_FXC)
    set(FIRMAMENT_SHADER_BACKEND fxc)
else()
    message(FATAL_ERROR "No HLSL compiler found: install vkd3d-compiler (Linux, tools/sysroot/create "
        "does) or the Windows SDK's fxc.exe, or set FIRMAMENT_SHADER_COMPILER.")
endif()
message(STATUS "Firmament: shaders compiled with ${FIRMAMENT_SHADER_BACKEND}")

# vkd3d-compiler runs through cmake/shader-cache.sh, a cache of compiled shaders kept where
# FIRMAMENT_SHADER_CACHE points at build time (tools/ sets it to a folder in the cache folder).
set(FIRMAMENT_SHADER_LAUNCHER "")
set(FIRMAMENT_SHADER_LAUNCHER_SCRIPT "")
if(FIRMAMENT_SHADER_BACKEND STREQUAL "vkd3d" AND FIRMAMENT_COMPILER_CACHE AND CMAKE_HOST_UNIX)
    set(FIRMAMENT_SHADER_LAUNCHER_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/shader-cache.sh")
    set(FIRMAMENT_SHADER_LAUNCHER sh "${FIRMAMENT_SHADER_LAUNCHER_SCRIPT}")
endif()

function(firmament_shader_library target)
    cmake_parse_arguments(ARG "" "ROOT;OUTPUT" "" ${ARGN})
    add_custom_target(${target} ALL)
    set_target_properties(${target} PROPERTIES
        FIRMAMENT_SHADER_ROOT "${ARG_ROOT}"
        FIRMAMENT_SHADER_OUTPUT "${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/${ARG_OUTPUT}")
    # Every shader depends on every header of its library: the compilers write no depfile.
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS "${ARG_ROOT}/*.hlsli")
    set_target_properties(${target} PROPERTIES FIRMAMENT_SHADER_HEADERS "${headers}")
    # The manifest is written once all permutations are known (end of the directory).
    # (DEFER evaluates its arguments late: EVAL fixes the target's name now.)
    cmake_language(EVAL CODE "cmake_language(DEFER CALL _firmament_write_manifest [[${target}]])")
endfunction()

function(firmament_add_shader target)
    cmake_parse_arguments(ARG "" "FILE;ENTRY;PROFILE;INCLUDE_ROOT" "DEFINES" ${ARGN})
    get_target_property(root ${target} FIRMAMENT_SHADER_ROOT)
    set(include_root "${root}")
    set(extra_headers "")
    if(ARG_INCLUDE_ROOT)
        set(include_root "${ARG_INCLUDE_ROOT}")
        file(GLOB_RECURSE extra_headers CONFIGURE_DEPENDS "${include_root}/*.hlsli")
    endif()
    get_target_property(output_dir ${target} FIRMAMENT_SHADER_OUTPUT)
    get_target_property(headers ${target} FIRMAMENT_SHADER_HEADERS)

    list(SORT ARG_DEFINES)
    list(JOIN ARG_DEFINES "," defines_text)
    set(key "${ARG_FILE}|${ARG_ENTRY}|${ARG_PROFILE}|${defines_text}")

    string(REGEX REPLACE "\\.hlsl$" "" stem "${ARG_FILE}")
    string(REPLACE "/" "_" stem "${stem}")
    set(cso_name "${stem}.${ARG_ENTRY}.${ARG_PROFILE}")
    if(ARG_DEFINES)
        string(MD5 defines_hash "${defines_text}")
        string(SUBSTRING "${defines_hash}" 0 8 defines_hash)
        string(APPEND cso_name ".${defines_hash}")
    endif()
    set(cso "${output_dir}/${cso_name}.cso")
    set(source "${root}/${ARG_FILE}")

    if(FIRMAMENT_SHADER_BACKEND STREQUAL "vkd3d")
        # vkd3d-compiler 2.1 takes no -D or -I and resolves #include against its working
        # directory: a generated wrapper holds the defines and includes the source, and the
        # compiler runs in the include root, so includes are written relative to it.
        set(wrapper "${CMAKE_CURRENT_BINARY_DIR}/hlsl-wrappers/${cso_name}.hlsl")
        set(wrapper_text "// Generated by FirmamentShaders.cmake for ${key}\n")
        foreach(define IN LISTS ARG_DEFINES)
            string(REPLACE "=" " " define_line "${define}")
            string(APPEND wrapper_text "#define ${define_line}\n")
        endforeach()
        string(APPEND wrapper_text "#include \"${source}\"\n")
        file(CONFIGURE OUTPUT "${wrapper}" CONTENT "${wrapper_text}" @ONLY)
        set(command ${FIRMAMENT_SHADER_LAUNCHER} ${FIRMAMENT_VKD3D_COMPILER} -x hlsl -b dxbc-tpf
            -p ${ARG_PROFILE} -e ${ARG_ENTRY} -o "${cso}" "${wrapper}")
    else()
        set(define_args "")
        foreach(define IN LISTS ARG_DEFINES)
            list(APPEND define_args /D "${define}")
        endforeach()
        set(command ${FIRMAMENT_FXC} /nologo /O3 /T ${ARG_PROFILE} /E ${ARG_ENTRY}
            /I "${include_root}" ${define_args} /Fo "${cso}" "${source}")
    endif()

    add_custom_command(OUTPUT "${cso}"
        COMMAND ${CMAKE_COMMAND} -E make_directory "${output_dir}"
        COMMAND ${command}
        DEPENDS "${source}" ${headers} ${extra_headers} ${FIRMAMENT_SHADER_LAUNCHER_SCRIPT}
        WORKING_DIRECTORY "${include_root}"
        COMMENT "HLSL ${ARG_FILE} (${ARG_ENTRY}, ${ARG_PROFILE})"
        VERBATIM)
    target_sources(${target} PRIVATE "${cso}")
    set_property(TARGET ${target} APPEND PROPERTY FIRMAMENT_SHADER_MANIFEST "${key}\t${cso_name}.cso")
endfunction()

function(_firmament_write_manifest target)
    get_target_property(output_dir ${target} FIRMAMENT_SHADER_OUTPUT)
    get_target_property(root ${target} FIRMAMENT_SHADER_ROOT)
    get_target_property(lines ${target} FIRMAMENT_SHADER_MANIFEST)
    if(FIRMAMENT_SHADER_LAUNCHER_SCRIPT)
        list(PREPEND lines "#cache\t${FIRMAMENT_SHADER_LAUNCHER_SCRIPT}")
    endif()
    list(PREPEND lines "#source\t${root}")
    list(JOIN lines "\n" content)
    file(GENERATE OUTPUT "${output_dir}/manifest.txt" CONTENT "${content}\n")
endfunction()
