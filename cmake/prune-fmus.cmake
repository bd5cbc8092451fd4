# Removes every .fmu that no block makes from the folders the FMUs are written into, so that they
# hold exactly the FMUs of the blocks that exist: the FMU of a deleted or renamed block goes
# (and with it from what `make package` bundles and `make dist` releases). CMakeLists.txt runs it
# at build time, as the target lgf_prune_fmus that every FMU target depends on, with the list of
# the FMUs the blocks make (one path a line) that it writes at configure time:
#   cmake -DFMU_LIST=<build>/fmus.list -P cmake/prune-fmus.cmake
# Only the .fmu files directly in those folders are looked at (fmus/ and fmus/fmi3/, or those of
# FMU_OUTPUT_DIR); anything else there is left alone.
cmake_minimum_required(VERSION 3.17)  # as CMakeLists.txt: its policies (if(IN_LIST))
if(NOT FMU_LIST OR NOT EXISTS "${FMU_LIST}")
  message(FATAL_ERROR "prune-fmus.cmake needs FMU_LIST=<the file listing the FMUs to keep>")
endif()
file(STRINGS "${FMU_LIST}" listed)
set(made)
set(folders)
foreach(fmu IN LISTS listed)
  get_filename_component(fmu "${fmu}" REALPATH)
  get_filename_component(folder "${fmu}" DIRECTORY)
  list(APPEND made "${fmu}")
  list(APPEND folders "${folder}")
endforeach()
list(REMOVE_DUPLICATES folders)
foreach(folder IN LISTS folders)
  file(GLOB found LIST_DIRECTORIES false "${folder}/*.fmu")
  foreach(fmu IN LISTS found)
    get_filename_component(fmu "${fmu}" REALPATH)
    if(NOT fmu IN_LIST made)
      message(STATUS "Removing ${fmu}: no block makes it")
      file(REMOVE "${fmu}")
    endif()
  endforeach()
endforeach()
