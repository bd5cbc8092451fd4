# What the cross toolchain files (mingw-w64.cmake, aarch64-linux.cmake) share: Debian's cross
# tools, named CROSS_PREFIX-gcc, with their target's libraries and headers under
# /usr/CROSS_PREFIX. Programs (e.g. Python) come from the build machine; libraries and headers
# from the target.
set(CMAKE_C_COMPILER ${CROSS_PREFIX}-gcc)
set(CMAKE_FIND_ROOT_PATH /usr/${CROSS_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
