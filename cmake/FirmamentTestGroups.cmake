# One CTest test per GoogleTest suite, or per shard, instead of one per test case.
#
# Under Wine every process costs a start of its own (the runtime, the Direct3D device, for the
# app tests the capture program and its tables: tests/support/HeadlessCapture.h), so a test
# executable runs as few processes as the two cores can keep busy:
#
#   firmament_test_groups(TARGET SUITES [FULL_TIER suite...] [TIMEOUT s])
#       a test <TARGET>.<Suite> for each suite, which runs --gtest_filter=<Suite>.*; the suites
#       are listed when CTest starts (the executable asked with --gtest_list_tests, again only
#       after it was rebuilt)
#   firmament_test_groups(TARGET SHARDS n [FULL_TIER entry...] [TIMEOUT s])
#       n tests <TARGET>.shard-i-of-n, GoogleTest's own sharding (GTEST_SHARD_INDEX)
#
# Every test gets the label "quick" or "full": tools/test runs the quick tier (ctest -LE full),
# tools/test --full everything. FULL_TIER names what only the full tier runs, each entry a
# suite ("Soak") or one case ("TableCache.BothModelsCacheAndExportTheirTables"), each then a
# test of its own (docs/building.md, "The tests"). A failed case names itself in the output
# (GoogleTest's [  FAILED  ] lines, which tools/test prints for a failed group).
set(FIRMAMENT_TEST_GROUPS_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/FirmamentTestGroupsList.cmake)

function(firmament_test_groups target)
    cmake_parse_arguments(PARSE_ARGV 1 G "SUITES" "SHARDS;TIMEOUT" "FULL_TIER")
    if(NOT G_TIMEOUT)
        set(G_TIMEOUT 1500)
    endif()
    set(emulator "")
    if(CMAKE_CROSSCOMPILING_EMULATOR)
        set(emulator ${CMAKE_CROSSCOMPILING_EMULATOR})
    endif()
    if(G_SHARDS)
        # The full tier's entries are left out of the shards (a negative GTEST_FILTER) and run
        # each as a test of its own.
        set(excluded "")
        foreach(entry IN LISTS G_FULL_TIER)
            set(pattern ${entry})
            if(NOT entry MATCHES "\\.")
                set(pattern ${entry}.*)
            endif()
            list(APPEND excluded ${pattern})
            add_test(NAME ${target}.${entry} COMMAND ${target} --gtest_filter=${pattern})
            set_tests_properties(${target}.${entry} PROPERTIES TIMEOUT ${G_TIMEOUT} LABELS full)
        endforeach()
        set(filter "")
        if(excluded)
            list(JOIN excluded ":" negative)
            set(filter "GTEST_FILTER=-${negative}")
        endif()
        foreach(index RANGE 1 ${G_SHARDS})
            math(EXPR zero_based "${index} - 1")
            set(name ${target}.shard-${index}-of-${G_SHARDS})
            add_test(NAME ${name} COMMAND ${target})
            set_tests_properties(${name} PROPERTIES TIMEOUT ${G_TIMEOUT} LABELS quick
                ENVIRONMENT "GTEST_TOTAL_SHARDS=${G_SHARDS};GTEST_SHARD_INDEX=${zero_based};${filter}")
        endforeach()
        return()
    endif()
    set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_groups.cmake)
    file(GENERATE OUTPUT ${include_file} CONTENT
"set(FIRMAMENT_GROUP_TARGET [==[${target}]==])
set(FIRMAMENT_GROUP_EXECUTABLE [==[$<TARGET_FILE:${target}>]==])
set(FIRMAMENT_GROUP_EMULATOR [==[${emulator}]==])
set(FIRMAMENT_GROUP_LIST [==[${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.txt]==])
set(FIRMAMENT_GROUP_FULL_TIER [==[${G_FULL_TIER}]==])
set(FIRMAMENT_GROUP_TIMEOUT [==[${G_TIMEOUT}]==])
include([==[${FIRMAMENT_TEST_GROUPS_SCRIPT}]==])
")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
