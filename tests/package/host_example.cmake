# Installs the build tree into a fresh prefix, builds examples/host against it with find_package,
# runs it with the validation layer (any message fails it) and compares its last frame.
include(GNUInstallDirs)
set(prefix "${WORK_DIR}/prefix")
set(example_build "${WORK_DIR}/host-build")
set(frames "${WORK_DIR}/host-frames")
file(REMOVE_RECURSE "${prefix}" "${example_build}" "${frames}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
  message(STATUS "$ ${ARGN}\n${out}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/host" -B "${example_build}" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
run(${CMAKE_COMMAND} --build "${example_build}")
# The shipped scenes are installed with the package (RasterLiquids_SCENES_DIR).
set(scene "${prefix}/${CMAKE_INSTALL_DATADIR}/rasterliquids/scenes/dam_break_3d.json")
if(NOT EXISTS "${scene}")
  message(FATAL_ERROR "the install holds no shipped scenes: ${scene} is missing")
endif()
# 8 frames of 10 steps (0.18 s) of the 3D dam break at 160x120: the front reaches the box; the
# 2D dam break in the corner panel.
run("${example_build}/liquid_host" "${scene}" --panel "${prefix}/${CMAKE_INSTALL_DATADIR}/rasterliquids/scenes/dam_break_2d.json"
    --frames 8 --steps-per-frame 10 --width 160 --height 120 --out "${frames}" --validation)
run("${COMPARE}" "${frames}/frame_0007.png" host_example)
