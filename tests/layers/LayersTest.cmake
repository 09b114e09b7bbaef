# cmake -DPROJECT_DIR=<the repository> -DSCRATCH=<an empty folder to use> -DCASE=<case> -P LayersTest.cmake
#
# The layer check (cmake/CheckLayers.cmake, run by every build) held to what it must do:
#   tree      the repository's src/ passes;
#   upward    a copy of src/ with one deliberate upward include (the clouds including the
#             renderer) fails, and the message names the file and the include;
#   across    a copy where one technique includes another (the clouds the terrain's header)
#             fails likewise;
#   new-room  a copy with a folder that is not a room fails, naming the folder;
#   reference a copy where the program includes a test's twin (the clouds' GPU reference the CPU
#             path tracer) fails.
cmake_minimum_required(VERSION 3.25)

function(run_check source_dir out_result out_output)
    execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${source_dir} -P ${PROJECT_DIR}/cmake/CheckLayers.cmake
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    set(${out_result} ${result} PARENT_SCOPE)
    set(${out_output} "${output}" PARENT_SCOPE)
endfunction()

# A copy of src/ with `line` appended to `file`, checked; it must fail with `expected` in the
# message.
function(expect_failure file line expected)
    file(REMOVE_RECURSE ${SCRATCH}/src)
    file(COPY ${PROJECT_DIR}/src DESTINATION ${SCRATCH})
    get_filename_component(folder ${SCRATCH}/src/${file} DIRECTORY)
    file(MAKE_DIRECTORY ${folder})
    file(APPEND ${SCRATCH}/src/${file} "\n${line}\n")
    run_check(${SCRATCH}/src result output)
    if(result EQUAL 0)
        message(FATAL_ERROR "the check passed a tree where src/${file} has '${line}':\n${output}")
    endif()
    string(FIND "${output}" "${expected}" found)
    if(found EQUAL -1)
        message(FATAL_ERROR "the check failed without naming '${expected}':\n${output}")
    endif()
    message(STATUS "failed as it must: ${expected}")
endfunction()

if(CASE STREQUAL "tree")
    run_check(${PROJECT_DIR}/src result output)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "src/ has includes up or across the rooms:\n${output}")
    endif()
    message(STATUS "${output}")
elseif(CASE STREQUAL "upward")
    expect_failure(clouds/Clouds.cpp "#include \"render/Renderer.h\""
        "src/clouds/Clouds.cpp includes \"render/Renderer.h\": the room clouds may include only itself and frame, tables, gpu, core")
elseif(CASE STREQUAL "across")
    expect_failure(clouds/Clouds.h "#include \"terrain/Terrain.h\"" "src/clouds/Clouds.h includes \"terrain/Terrain.h\"")
elseif(CASE STREQUAL "new-room")
    expect_failure(weather/Rain.cpp "#include \"core/Log.h\"" "src/weather/Rain.cpp: 'weather' is not a room")
elseif(CASE STREQUAL "reference")
    expect_failure(clouds/CloudReference.h "#include \"reference/CloudPathTracer.h\"" "src/clouds/CloudReference.h includes \"reference/CloudPathTracer.h\"")
else()
    message(FATAL_ERROR "LayersTest: unknown CASE '${CASE}'")
endif()
