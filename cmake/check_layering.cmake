# Checks the module layering by the #include lines of every source file:
#   formats      <- nothing (nlohmann-json only)
#   solver       <- formats
#   surrogate    <- formats            (never solver/: the case files are the interface)
#   calibration  <- surrogate, formats
#   bench        <- solver, formats
#   cli          <- everything
# Run as: cmake -DSOURCE_DIR=... -P check_layering.cmake; fails naming file and include.
cmake_minimum_required(VERSION 3.22)
set(allowed_formats formats rbcal)
set(allowed_solver solver formats)
set(allowed_surrogate surrogate formats)
set(allowed_calibration calibration surrogate formats)
set(allowed_bench bench solver formats)
set(allowed_cli cli bench calibration surrogate solver formats rbcal)
set(violations "")
foreach(module formats solver surrogate calibration bench cli)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${module}/*.cpp" "${SOURCE_DIR}/${module}/*.hpp")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" target "${line}")
      if(NOT target IN_LIST allowed_${module})
        file(RELATIVE_PATH shown "${SOURCE_DIR}" "${source}")
        string(APPEND violations "\n  ${shown}: ${line} (${module}/ may include ${allowed_${module}})")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "layering violated:${violations}")
endif()
message(STATUS "layering respected")
