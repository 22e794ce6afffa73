# Checks the module layering by the #include lines of every source file:
#   formats      <- nothing (nlohmann-json only)
#   solver       <- formats
#   surrogate    <- formats            (never solver/: the case files are the interface)
#   calibration  <- surrogate, formats
#   bench        <- solver, calibration, surrogate, formats (benchmarks of each)
#   cli          <- everything
#   python       <- calibration, surrogate, formats  (the Python module: no solver)
# and each module's detail/ folders (at any depth: solver/simulation/detail/) are its own: no
# other module includes from them, and no public header of the module itself does (a public
# header that did would hand it on). Tests may. No library exports an include directory
# (target_include_directories ... PUBLIC or INTERFACE): the repository root is every target's
# own, set once for the tree.
# Run as: cmake -DSOURCE_DIR=... -P check_layering.cmake; fails naming file and include.
cmake_minimum_required(VERSION 3.22)
set(allowed_formats formats rbcal)
set(allowed_solver solver formats)
set(allowed_surrogate surrogate formats)
set(allowed_calibration calibration surrogate formats)
set(allowed_bench bench solver calibration surrogate formats)
set(allowed_cli cli bench calibration surrogate solver formats rbcal)
set(allowed_python python calibration surrogate formats)
set(violations "")
foreach(module formats solver surrogate calibration bench cli python)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${module}/*.cpp" "${SOURCE_DIR}/${module}/*.hpp")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" target "${line}")
      file(RELATIVE_PATH shown "${SOURCE_DIR}" "${source}")
      if(NOT target IN_LIST allowed_${module})
        string(APPEND violations "\n  ${shown}: ${line} (${module}/ may include ${allowed_${module}})")
      endif()
      # detail/ at any depth of a module (solver/simulation/detail/...) is the module's own.
      if(line MATCHES "^#include \"[a-z_]+/([a-z_]+/)*detail/")
        if(NOT target STREQUAL module)
          string(APPEND violations "\n  ${shown}: ${line} (another module's detail/)")
        elseif(shown MATCHES "\\.hpp$" AND NOT shown MATCHES "/detail/")
          string(APPEND violations "\n  ${shown}: ${line} (a public header includes a detail/ one)")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()
# Every folder of the checkout but the build trees (and hidden ones), walked to any depth; the
# build trees are not walked at all: other tests create and delete files there meanwhile.
set(build_files CMakeLists.txt)
file(GLOB top_folders LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*")
foreach(folder IN LISTS top_folders)
  if(IS_DIRECTORY "${SOURCE_DIR}/${folder}" AND NOT folder MATCHES "^(build|\\.)")
    file(GLOB_RECURSE found RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${folder}/CMakeLists.txt")
    list(APPEND build_files ${found})
  endif()
endforeach()
foreach(build_file IN LISTS build_files)
  file(READ "${SOURCE_DIR}/${build_file}" text)
  string(REGEX MATCHALL "target_include_directories\\([^)]*(PUBLIC|INTERFACE)[^)]*\\)" exported "${text}")
  if(exported)
    string(APPEND violations "\n  ${build_file}: ${exported} (an exported include directory)")
  endif()
endforeach()
if(violations)
  message(FATAL_ERROR "layering violated:${violations}")
endif()
message(STATUS "layering respected")
