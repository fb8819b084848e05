# ctest (tests/package/CMakeLists.txt), run as cmake -P after the build: installs the build tree
# into WORK_DIR/prefix, checks that the installed package names neither the source nor the build
# tree, configures tests/package/consumer with only that prefix on CMAKE_PREFIX_PATH, builds it
# and runs it on CASE, comparing its output with known answers.
# Variables: SOURCE_DIR, BUILD_DIR, WORK_DIR, CASE, GENERATOR, CXX, LAUNCHER (may be empty), and
# the build's GNUInstallDirs BINDIR, INCLUDEDIR, LIBDIR.

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(include_dir ${prefix}/${INCLUDEDIR}/freestand)
set(package_dir ${prefix}/${LIBDIR}/cmake/freestand)
foreach(required IN ITEMS ${include_dir}/core/record.hpp ${include_dir}/api/assess.hpp
                          ${package_dir}/freestandConfig.cmake
                          ${package_dir}/freestandConfigVersion.cmake ${prefix}/${BINDIR}/freestand)
  if(NOT EXISTS ${required})
    message(FATAL_ERROR "not installed: ${required}")
  endif()
endforeach()
# Every header an installed header includes by a quoted path is installed too.
file(GLOB_RECURSE headers RELATIVE ${include_dir} ${include_dir}/*.hpp)
foreach(h IN LISTS headers)
  file(STRINGS ${include_dir}/${h} includes REGEX "^#include \"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${include_dir}/${included})
      message(FATAL_ERROR "installed ${h} includes ${included}, which is not installed")
    endif()
  endforeach()
endforeach()

# A package that points back into the tree it was built in works here and nowhere else.
file(GLOB package_files ${package_dir}/*.cmake)
foreach(f IN LISTS package_files)
  file(READ ${f} text)
  foreach(tree IN ITEMS ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${f} names ${tree}")
    endif()
  endforeach()
endforeach()

# Only the prefix: no CMAKE_PREFIX_PATH from the environment, no package registry.
unset(ENV{CMAKE_PREFIX_PATH})
set(consumer ${WORK_DIR}/consumer)
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/package/consumer
    -B ${consumer} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
    ${launcher} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${consumer}/CMakeCache.txt found_dir REGEX "^freestand_DIR:")
if(NOT found_dir STREQUAL "freestand_DIR:PATH=${package_dir}")
  message(FATAL_ERROR "the consumer found another freestand: ${found_dir}")
endif()
run("building the consumer" ${CMAKE_COMMAND} --build ${consumer})

run("running the consumer" ${consumer}/consumer ${CASE})
message("${run_output}")
# The rigid oscillator's PSA is the sine's 0.3 g; the shipped glove box case's verdict is the one
# reports/glovebox-single/result.json holds.
foreach(expected IN ITEMS "psa_100hz_g 0\\.300\n"
                          "Glove box, single, on PVC sheet: anchor"
                          "report_html_bytes [1-9][0-9][0-9][0-9]+\n")
  if(NOT run_output MATCHES "${expected}")
    message(FATAL_ERROR "the consumer's output lacks /${expected}/")
  endif()
endforeach()
