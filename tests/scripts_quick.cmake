# Every script of benchmarks/ and scripts/ as its usage line calls it, from
# a folder other than the repository's root and with relative paths
# (tests/scripts_quick.sh): the benchmarks' quick modes, the plot scripts
# on small runs, the peer benchmarks' message when their peer is missing.
# About 80 s; the benchmarks run 2 MPI ranks, so ctest reserves both cores.
add_test(NAME scripts_quick
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts_quick.sh
          $<TARGET_FILE:signorini> ${CMAKE_SOURCE_DIR}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(scripts_quick PROPERTIES TIMEOUT 600 PROCESSORS 2)
