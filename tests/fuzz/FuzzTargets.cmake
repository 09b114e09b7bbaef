# libFuzzer targets (clang's -fsanitize=fuzzer) over the platform-independent code, with ASan and
# UBSan, included by cmake/FirmamentPortable.cmake. tools/fuzz runs each for a given time;
# CTest runs each from its seeds for a few seconds in the quick tier (fuzz.<name>) and longer in
# the full tier (fuzz.<name>.long), and on its minimized findings (fuzz.<name>.regressions). Seeds: tests/fuzz/corpus/<name>/; findings: tests/fuzz/regressions/<name>/.
set(FIRMAMENT_FUZZ_SECONDS 20 CACHE STRING "How long the full tier's run of each fuzz target lasts")
set(FIRMAMENT_FUZZ_QUICK_SECONDS 2 CACHE STRING "How long the quick tier's run of each fuzz target lasts")
set(FIRMAMENT_FUZZ_TARGETS command_line exr_table flight_file height_field hid_report png set_value settings_json state_file)
set(fuzz_dir ${CMAKE_CURRENT_LIST_DIR})

foreach(name IN LISTS FIRMAMENT_FUZZ_TARGETS)
    add_executable(fuzz_${name} ${fuzz_dir}/fuzz_${name}.cpp)
    target_link_libraries(fuzz_${name} PRIVATE firmament_portable)
    target_compile_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
    target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
    firmament_warnings(fuzz_${name})
    # The short run works on a copy of the seeds in the build folder, so that what it adds
    # never lands in the checkout.
    foreach(tier IN ITEMS quick full)
        set(test fuzz.${name})
        set(seconds ${FIRMAMENT_FUZZ_QUICK_SECONDS})
        if(tier STREQUAL "full")
            set(test fuzz.${name}.long)
            set(seconds ${FIRMAMENT_FUZZ_SECONDS})
        endif()
        set(work ${CMAKE_BINARY_DIR}/fuzz-work/${test})
        add_test(NAME ${test}
            COMMAND ${CMAKE_COMMAND} -DFUZZER=$<TARGET_FILE:fuzz_${name}> -DSEEDS=${fuzz_dir}/corpus/${name} -DWORK=${work}
                -DSECONDS=${seconds} -P ${fuzz_dir}/run_fuzz_target.cmake)
        set_tests_properties(${test} PROPERTIES TIMEOUT 300 LABELS ${tier})
    endforeach()
    file(GLOB findings ${fuzz_dir}/regressions/${name}/*)
    if(findings)
        add_test(NAME fuzz.${name}.regressions COMMAND fuzz_${name} ${findings})
        set_tests_properties(fuzz.${name}.regressions PROPERTIES LABELS quick)
    endif()
endforeach()

add_executable(fuzz_write_seeds ${fuzz_dir}/fuzz_write_seeds.cpp)
target_link_libraries(fuzz_write_seeds PRIVATE firmament_portable)
firmament_warnings(fuzz_write_seeds)
