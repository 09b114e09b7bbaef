# One fuzz target's short run for CTest: a fresh copy of its seeds, then libFuzzer for SECONDS,
# failing on any finding (a crash, a sanitizer report, a leak, a time-out or running out of memory).
# The random seed is fixed, so that every run walks the same inputs in the same order and a
# machine explores a prefix of what a faster one does: the suite's result does not depend on
# luck. tools/fuzz, for exploring, draws a new seed each run.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
file(GLOB seeds ${SEEDS}/*)
if(NOT seeds)
    message(FATAL_ERROR "no seeds in ${SEEDS}")
endif()
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
execute_process(COMMAND ${FUZZER} -seed=1 -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
                        -artifact_prefix=${WORK}/artifacts/ ${WORK}/corpus
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the fuzzer found an input that fails (exit ${result}); it is in ${WORK}/artifacts")
endif()
