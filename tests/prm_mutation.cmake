# Mutation test of the parameter-file input (tests/prm_mutation.py): 200
# randomly corrupted variants of fast committed scenes (fixed seed) must each
# end in a clear error or a valid run, never in a signal, a hang or exit 1.
# About 1-2 minutes with 2 jobs; it uses both cores, so ctest reserves them.
add_test(NAME prm_mutation
  COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/prm_mutation.py
          $<TARGET_FILE:signorini> ${CMAKE_SOURCE_DIR}
          --variants 200 --seed 2026 --jobs 2)
set_tests_properties(prm_mutation PROPERTIES TIMEOUT 600 PROCESSORS 2)
