# Test Install.ExampleBuildsAndRunsAgainstTheInstalledPackage: installs the build
# tree into WORK_DIR/prefix, configures and builds examples/cpp against that prefix
# alone (a Debug build: NDEBUG and C++17 must come from the package), and runs it
# on the installed 70ton-loaded.toml.
#   cmake -DBUILD_DIR=build -DSOURCE_DIR=. -DWORK_DIR=build/install_test -P tests/check_install.cmake
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
          share/rockroll/scenarios/70ton-loaded.toml lib/cmake/rockroll/rockrollConfig.cmake
          lib/cmake/rockroll/rockrollConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()
# The installed program runs from the prefix (its libraries found through its RPATH).
run("installed rockroll --version" ${prefix}/bin/rockroll --version)
message(STATUS "installed: ${out}")

run("configure the example" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpp -B ${example}
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(READ ${example}/compile_commands.json cc)
foreach(flag -std=gnu\\+\\+17 "-DNDEBUG|-UNDEBUG")
  if(NOT cc MATCHES "${flag}")
    message(FATAL_ERROR "the example's compile command lacks ${flag} (from rockroll::simbody):\n${cc}")
  endif()
endforeach()
run("build the example" ${CMAKE_COMMAND} --build ${example})
run("run the example" ${example}/max_roll ${prefix}/share/rockroll/scenarios/70ton-loaded.toml)
message(STATUS "${out}")
if(NOT out MATCHES "2\\.0 s simulated: max roll ([0-9]+\\.[0-9]+) deg")
  message(FATAL_ERROR "unexpected output: ${out}")
endif()
if(CMAKE_MATCH_1 LESS_EQUAL 0.1 OR CMAKE_MATCH_1 GREATER 10)
  message(FATAL_ERROR "max roll ${CMAKE_MATCH_1} deg is not the 70-ton car rocking")
endif()
