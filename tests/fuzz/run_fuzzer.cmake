# Runs a fuzzer for SECONDS from the seed folders SEEDS (read only, separated by '|'), into a fresh corpus
# folder CORPUS; a finding (libFuzzer's non-zero exit) fails the test and leaves the crashing input
# as crash-* in ARTIFACTS. Used by ctest:
#   cmake -DFUZZER=... -DCORPUS=... -DARTIFACTS=... -DSEEDS="a|b" -DDICT=... -DSECONDS=60 -P run_fuzzer.cmake
string(REPLACE "|" ";" SEEDS "${SEEDS}")
file(REMOVE_RECURSE "${CORPUS}")
file(MAKE_DIRECTORY "${CORPUS}" "${ARTIFACTS}")
execute_process(
  COMMAND "${FUZZER}" "-max_total_time=${SECONDS}" "-dict=${DICT}" -max_len=16384 -timeout=10 -rss_limit_mb=2048
          -print_final_stats=1 "-artifact_prefix=${ARTIFACTS}/" "${CORPUS}" ${SEEDS}
  RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a problem (exit ${code}); the input is in ${ARTIFACTS}")
endif()
