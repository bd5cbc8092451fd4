# CMake toolchain file: cross-compile the FMUs for 64-bit Windows (binaries/win64) with
# mingw-w64 on Linux (Debian package gcc-mingw-w64-x86-64).
#   cmake -S . -B build-win64 -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64.cmake
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(MINGW_PREFIX x86_64-w64-mingw32 CACHE STRING "Target triple prefix of the mingw-w64 tools")
set(CROSS_PREFIX ${MINGW_PREFIX})
include(${CMAKE_CURRENT_LIST_DIR}/cross.cmake)
set(CMAKE_RC_COMPILER ${MINGW_PREFIX}-windres)
