# CMake toolchain file: cross-compile the FMI 3.0 FMUs' libraries for 64-bit ARM Linux
# (binaries/aarch64-linux) with Debian's cross compiler (packages gcc-aarch64-linux-gnu and
# libc6-dev-arm64-cross). FMI 2.0 names no platform for it, so this build makes only the FMI 3.0
# libraries (CMakeLists.txt).
#   cmake -S . -B build-aarch64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux.cmake
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(AARCH64_PREFIX aarch64-linux-gnu CACHE STRING "Target triple prefix of the aarch64 tools")
set(CROSS_PREFIX ${AARCH64_PREFIX})
include(${CMAKE_CURRENT_LIST_DIR}/cross.cmake)
