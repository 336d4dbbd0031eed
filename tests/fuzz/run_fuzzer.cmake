# Runs the scene fuzzer for SECONDS from the seed folders SEEDS (read only, a list), into a fresh corpus
# folder CORPUS; a finding (libFuzzer's non-zero exit) fails the test and leaves the crashing input
# as crash-* in ARTIFACTS. Used by ctest:
#   cmake -DFUZZER=... -DCORPUS=... -DARTIFACTS=... -DSEEDS="a;b" -DDICT=... -DSECONDS=60 -P run_fuzzer.cmake
file(REMOVE_RECURSE "${CORPUS}")
file(MAKE_DIRECTORY "${CORPUS}" "${ARTIFACTS}")
execute_process(
  COMMAND "${FUZZER}" "-max_total_time=${SECONDS}" "-dict=${DICT}" -max_len=16384 -timeout=10 -rss_limit_mb=2048
          -print_final_stats=1 "-artifact_prefix=${ARTIFACTS}/" "${CORPUS}" ${SEEDS}
  RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the scene fuzzer found a problem (exit ${code}); the input is in ${ARTIFACTS}")
endif()
