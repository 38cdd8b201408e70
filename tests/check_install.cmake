# Test Install.ExampleBuildsAndRunsAgainstTheInstalledPackage: installs the build
# tree into WORK_DIR/prefix, configures and builds examples/cpp against that prefix
# alone (a Debug build: NDEBUG and the C++ standard must come from the package), and runs it
# on the installed 70ton-loaded.toml.
#   cmake -DBUILD_DIR=build -DSOURCE_DIR=. -DWORK_DIR=build/install_test -P tests/check_install.cmake
# SANITIZER_FLAGS: the build's -fsanitize flags (sanitize preset), which the example needs to link.
cmake_minimum_required(VERSION 3.22)
set(prefix ${WORK_DIR}/prefix)
set(example ${WORK_DIR}/example)
file(REMOVE_RECURSE ${WORK_DIR})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f bin/rockroll include/mbmodel/CarParameters.h include/scenarios/ScenarioRun.h include/simbody/Simbody.h
          share/rockroll/scenarios/70ton-loaded.toml share/rockroll/scenarios/reference/mit1976.toml
          share/rockroll/python/rockroll_plots/__main__.py share/rockroll/python/rockroll_plots/outputs.py lib/cmake/rockroll/rockrollConfig.cmake
          lib/cmake/rockroll/rockrollConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()
# The installed program runs from the prefix (its libraries found through its RPATH).
run("installed rockroll --version" ${prefix}/bin/rockroll --version)
message(STATUS "installed: ${out}")
# It reads its data files (the report's numbers, the scenarios, the plotting package python/rockroll_plots)
# from its own prefix, not from the source tree it was built in.
if(NOT out MATCHES "data files: ${prefix}/share/rockroll")
  message(FATAL_ERROR "the installed rockroll does not read its data from ${prefix}/share/rockroll:\n${out}")
endif()

run("configure the example" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpp -B ${example}
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "-DCMAKE_CXX_FLAGS=${SANITIZER_FLAGS}")
# rockroll::simbody carries Simbody's NDEBUG and the language standard rockroll was
# built with (CXX_STANDARD: 20 with the patched Release Simbody; 17 with Debian's
# unpatched headers, which do not compile as C++20, simbody#710).
file(READ ${example}/compile_commands.json cc)
if(NOT cc MATCHES "-DNDEBUG|-UNDEBUG")
  message(FATAL_ERROR "the example's compile command has no NDEBUG setting from rockroll::simbody:\n${cc}")
endif()
file(READ ${prefix}/lib/cmake/rockroll/rockrollTargets.cmake targets)
if(NOT targets MATCHES "INTERFACE_COMPILE_FEATURES \"cxx_std_${CXX_STANDARD}\"")
  message(FATAL_ERROR "rockroll::simbody does not carry cxx_std_${CXX_STANDARD}")
endif()
if(CXX_STANDARD EQUAL 20 AND NOT cc MATCHES "-std=(gnu|c)\\+\\+(2a|20)")
  message(FATAL_ERROR "the example does not compile as C++20 against the patched Simbody:\n${cc}")
endif()
if(CXX_STANDARD EQUAL 17 AND cc MATCHES "-std=[a-z]+\\+\\+(2a|20|2b|23)")
  message(FATAL_ERROR "the example compiles as C++20 or later, which Debian's Simbody 3.7 headers do not support:\n${cc}")
endif()
run("build the example" ${CMAKE_COMMAND} --build ${example})
run("run the example" ${example}/max_roll ${prefix}/share/rockroll/scenarios/70ton-loaded.toml)
message(STATUS "${out}")
if(NOT out MATCHES "2\\.0 s simulated: max roll ([0-9]+\\.[0-9]+) deg")
  message(FATAL_ERROR "unexpected output: ${out}")
endif()
set(example_roll ${CMAKE_MATCH_1})
if(example_roll LESS_EQUAL 0.1 OR example_roll GREATER 10)
  message(FATAL_ERROR "max roll ${example_roll} deg is not the 70-ton car rocking")
endif()

# The installed program gives the same run.
run("installed rockroll run" ${prefix}/bin/rockroll run ${prefix}/share/rockroll/scenarios/70ton-loaded.toml
  --duration-s 2 --json --out ${WORK_DIR}/cli)
string(JSON cli_roll GET "${out}" max_roll_deg)
# The installed program plots its run with the installed plotting package (PNG, SVG and sidecar).
run("installed rockroll plot" ${prefix}/bin/rockroll plot ${WORK_DIR}/cli)
foreach(f timehistory.png timehistory.svg timehistory.png.json)
  if(NOT EXISTS ${WORK_DIR}/cli/plots/${f})
    message(FATAL_ERROR "rockroll plot of the installed program wrote no ${WORK_DIR}/cli/plots/${f}")
  endif()
  file(SIZE ${WORK_DIR}/cli/plots/${f} size)
  if(size EQUAL 0)
    message(FATAL_ERROR "${WORK_DIR}/cli/plots/${f} is empty")
  endif()
endforeach()
file(READ ${WORK_DIR}/cli/plots/timehistory.png.json sidecar)
string(JSON first_csv GET "${sidecar}" lines 0 csv)
if(NOT first_csv STREQUAL "history.csv")
  message(FATAL_ERROR "the installed plot's sidecar draws from ${first_csv}, not history.csv")
endif()
file(GLOB_RECURSE pycache ${prefix}/share/rockroll/python/*.pyc)
if(pycache)
  message(FATAL_ERROR "plotting wrote bytecode into the installed prefix: ${pycache}")
endif()
# Both in micro-degrees (CMake has integer arithmetic only).
function(micro var value)
  if(NOT value MATCHES "^([0-9]+)\\.([0-9]*)")
    message(FATAL_ERROR "not a decimal: ${value}")
  endif()
  string(SUBSTRING "${CMAKE_MATCH_2}000000" 0 6 frac)
  math(EXPR m "${CMAKE_MATCH_1} * 1000000 + 1${frac} - 1000000")
  set(${var} ${m} PARENT_SCOPE)
endfunction()
micro(a ${example_roll})
micro(b ${cli_roll})
math(EXPR d "${a} - ${b}")
if(d GREATER 51 OR d LESS -51)
  message(FATAL_ERROR "the example's max roll ${example_roll} deg differs from rockroll run's ${cli_roll} deg")
endif()
message(STATUS "rockroll run: max_roll_deg ${cli_roll}")
