# Packs an FMU without Python (tools/pack.py is used where Python is): the staged files in
# sorted order with one time stamp, so that the same files give the same entries; the
# permissions are the files' own.
#   cmake -DSTAGE=<folder> -DFMU=<file> -P cmake/pack.cmake
file(GLOB_RECURSE files RELATIVE "${STAGE}" "${STAGE}/*")
list(SORT files)
file(REMOVE "${FMU}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E tar cf "${FMU}" --format=zip --mtime=1980-01-01T00:00:00Z -- ${files}
  WORKING_DIRECTORY "${STAGE}" RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "could not pack ${FMU}")
endif()
