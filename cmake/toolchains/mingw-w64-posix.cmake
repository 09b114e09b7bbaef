# Cross-compiling for 64-bit Windows with MinGW-w64 GCC (posix threads), as installed in the
# Debian sid sysroot made by tools/sysroot/create. Third-party libraries cross-built there
# live under /opt/firmament/mingw.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(FIRMAMENT_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${FIRMAMENT_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${FIRMAMENT_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${FIRMAMENT_MINGW_TRIPLE}-windres)

set(FIRMAMENT_THIRD_PARTY_PREFIX /opt/firmament/mingw CACHE PATH "MinGW prefix of cross-built libraries")
set(CMAKE_FIND_ROOT_PATH /usr/${FIRMAMENT_MINGW_TRIPLE} ${FIRMAMENT_THIRD_PARTY_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# The executables carry their C and C++ runtimes, so Wine (and a Windows machine) needs no
# MinGW DLLs beside them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")

# Test executables are Windows programs: CTest starts them through Wine.
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/../../tools/sandbox/wine-exec)
