# Compiler cache (docs/building.md, "Build time"): when ccache is found, every C and C++
# compile goes through it. tools/ keeps its cache in the cache folder, outside the checkout,
# and every checkout is /src inside the sysroot, so a second clone (and CI on the same
# machine) reuses the objects of the first. The settings it needs next to the precompiled
# headers (the pch_defines and time_macros sloppiness) are in tools/lib.sh's environment.
# -DFIRMAMENT_COMPILER_CACHE=OFF turns it off; a launcher given on the command line wins.
option(FIRMAMENT_COMPILER_CACHE "Compile through ccache when it is installed" ON)
if(FIRMAMENT_COMPILER_CACHE AND NOT MSVC AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    find_program(FIRMAMENT_CCACHE ccache)
    if(FIRMAMENT_CCACHE)
        set(CMAKE_C_COMPILER_LAUNCHER ${FIRMAMENT_CCACHE})
        set(CMAKE_CXX_COMPILER_LAUNCHER ${FIRMAMENT_CCACHE})
        message(STATUS "Compiler cache: ${FIRMAMENT_CCACHE}")
    endif()
endif()
