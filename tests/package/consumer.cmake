# Configures (and for FetchContent, builds) tests/package/consumer, a host project with a target of
# its own called `engine`, in one of three ways: MODE=build_tree (find_package with
# RasterLiquids_DIR=<this build>), add_subdirectory, fetch_content.
set(consumer_build "${WORK_DIR}/consumer-${MODE}")
file(REMOVE_RECURSE "${consumer_build}")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/package/consumer" -B "${consumer_build}"
                        -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release -DMODE=${MODE}
                        -DRASTERLIQUIDS_SOURCE=${SOURCE_DIR} -DRasterLiquids_DIR=${BUILD_DIR} -DEXPECT_VDB=${EXPECT_VDB}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
message(STATUS "${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "configuring the consumer (${MODE}) failed")
endif()
if(MODE STREQUAL "add_subdirectory")
  return()  # the clash with the host's `engine` target shows at configure time
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${consumer_build}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 1500)
message(STATUS "${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "building the consumer (${MODE}) failed")
endif()
