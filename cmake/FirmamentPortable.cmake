# The platform-independent code built natively on Linux (preset 'portable', clang), for the
# sanitizers and the fuzzers (docs/reliability.md): settings and JSON, the command line, EXR and
# PNG I/O, table file headers and the height-field file, flight and state files, HID report
# decoders, the scattering tables' parameterizations, the CPU reference atmosphere and every CPU
# twin. None of these files includes <windows.h> or a Direct3D header; the few platform seams
# (flushing a file to the disk, the test executable's folder) are #ifdef _WIN32 in place.
#
# Targets:
#   firmament_portable        the library
#   firmament_portable_tests  the unit tests that need no Windows API, under ASan and UBSan
#   fuzz_<name>               libFuzzer targets (tests/fuzz), when the compiler is clang
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)
find_package(ZLIB REQUIRED)
find_package(GTest REQUIRED)

set(FIRMAMENT_SANITIZERS "address,undefined" CACHE STRING "-fsanitize= list for the portable build (empty: none)")
set(sanitize_flags)
if(FIRMAMENT_SANITIZERS)
    # Any report ends the process with an error: a test that trips a sanitizer fails.
    set(sanitize_flags -fsanitize=${FIRMAMENT_SANITIZERS} -fno-sanitize-recover=all -fno-omit-frame-pointer)
endif()

set(src ${PROJECT_SOURCE_DIR}/src)
configure_file(${src}/FirmamentVersion.h.in ${CMAKE_CURRENT_BINARY_DIR}/generated/FirmamentVersion.h @ONLY)

add_library(firmament_portable STATIC
    ${src}/app/BenchmarkPlan.cpp
    ${src}/app/BenchmarkReport.cpp
    ${src}/app/CaptureBatch.cpp
    ${src}/app/CommandLine.cpp
    ${src}/app/FlightPath.cpp
    ${src}/app/SoakSchedule.cpp
    ${src}/app/SoakVerdict.cpp
    ${src}/atmosphere/AtmosphereParameters.cpp
    ${src}/reference/ReferenceAtmosphere.cpp
    ${src}/atmosphere/SunAnimation.cpp
    ${src}/atmosphere/bruneton/BrunetonParameterization.cpp
    ${src}/atmosphere/hillaire/HillaireParameterization.cpp
    ${src}/atmosphere/yusov/YusovParameterization.cpp
    ${src}/clouds/CloudField.cpp
    ${src}/clouds/CloudGrid.cpp
    ${src}/reference/CloudFieldTwin.cpp
    ${src}/reference/CloudMedium.cpp
    ${src}/reference/CloudPathTracer.cpp
    ${src}/reference/DeckDiffusion.cpp
    ${src}/reference/HillaireMultipleScatteringTwin.cpp
    ${src}/clouds/DeckDiffusionTable.cpp
    ${src}/clouds/LightSpace.cpp
    ${src}/clouds/OpticalDepthTable.cpp
    ${src}/clouds/ParticleBlending.cpp
    ${src}/clouds/ParticleDensity.cpp
    ${src}/clouds/ParticleScattering.cpp
    ${src}/clouds/SlabDoubling.cpp
    ${src}/reference/SunColumnTwin.cpp
    ${src}/reference/VolumeBlendingTwin.cpp
    ${src}/core/Camera.cpp
    ${src}/core/ExrImage.cpp
    ${src}/core/FileIO.cpp
    ${src}/core/Log.cpp
    ${src}/core/PngImage.cpp
    ${src}/core/SettingsJson.cpp
    ${src}/gpu/ShaderKey.cpp
    ${src}/input/FlyCamera.cpp
    ${src}/input/HidReports.cpp
    ${src}/postfx/ToneMappingCurves.cpp
    ${src}/settings/State.cpp
    ${src}/shadows/CascadeSplits.cpp
    ${src}/tables/TableFileHeaders.cpp
    ${src}/terrain/ClipmapLayout.cpp
    ${src}/terrain/HeightField.cpp
    ${src}/terrain/HeightFieldFile.cpp
    ${src}/terrain/TerrainGenerator.cpp
    ${src}/terrain/TerrainSurface.cpp)
target_include_directories(firmament_portable PUBLIC ${src} ${CMAKE_CURRENT_BINARY_DIR}/generated ${PROJECT_SOURCE_DIR}/shaders)
target_link_libraries(firmament_portable PUBLIC glm::glm nlohmann_json::nlohmann_json OpenEXR::OpenEXR ZLIB::ZLIB)
target_compile_options(firmament_portable PUBLIC ${sanitize_flags})
target_link_options(firmament_portable PUBLIC ${sanitize_flags})
firmament_warnings(firmament_portable)
# The same layer check as the Windows build's (cmake/FirmamentLayers.cmake) before it compiles.
include(FirmamentLayers)
firmament_check_layers(firmament_layers)
add_dependencies(firmament_portable firmament_layers)

include(CTest)
include(GoogleTest)
set(tests ${PROJECT_SOURCE_DIR}/tests)
add_executable(firmament_portable_tests
    ${tests}/support/TestMain.cpp
    ${tests}/unit/BenchmarkPlanTest.cpp
    ${tests}/unit/CaptureBatchTest.cpp
    ${tests}/unit/CloudPathTracerTest.cpp
    ${tests}/unit/BrunetonParameterizationTest.cpp
    ${tests}/unit/CameraTest.cpp
    ${tests}/unit/CascadeSplitsTest.cpp
    ${tests}/unit/CloudGridTest.cpp
    ${tests}/unit/CommandLineTest.cpp
    ${tests}/unit/ExrImageTest.cpp
    ${tests}/unit/FileIOTest.cpp
    ${tests}/unit/FlightPathTest.cpp
    ${tests}/unit/FlyCameraTest.cpp
    ${tests}/unit/HillaireMultipleScatteringTest.cpp
    ${tests}/unit/HillaireParameterizationTest.cpp
    ${tests}/unit/HidReportsTest.cpp
    ${tests}/unit/ParticleDensityTest.cpp
    ${tests}/unit/ParticleScatteringTest.cpp
    ${tests}/unit/DeckDiffusionTest.cpp
    ${tests}/unit/SlabDoublingTest.cpp
    ${tests}/unit/PngImageTest.cpp
    ${tests}/unit/ReferenceAtmosphereTest.cpp
    ${tests}/unit/SettingsTest.cpp
    ${tests}/unit/ShaderKeyTest.cpp
    ${tests}/unit/SoakScheduleTest.cpp
    ${tests}/unit/StepTimerTest.cpp
    ${tests}/unit/SunAnimationTest.cpp
    ${tests}/unit/SunColumnTwinTest.cpp
    ${tests}/unit/TerrainGeneratorTest.cpp
    ${tests}/unit/ToneMappingCurvesTest.cpp
    ${tests}/unit/VolumeBlendingTest.cpp
    ${tests}/unit/YusovParameterizationTest.cpp)
target_include_directories(firmament_portable_tests PRIVATE ${tests})
target_link_libraries(firmament_portable_tests PRIVATE firmament_portable GTest::gtest)
firmament_warnings(firmament_portable_tests)
# The shipped cloud scattering table, soak schedule and benchmark scenarios, beside the executable
# as in the Windows build.
add_custom_command(TARGET firmament_portable_tests POST_BUILD
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${PROJECT_SOURCE_DIR}/media/clouds $<TARGET_FILE_DIR:firmament_portable_tests>/media/clouds
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${PROJECT_SOURCE_DIR}/media/soak $<TARGET_FILE_DIR:firmament_portable_tests>/media/soak
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${PROJECT_SOURCE_DIR}/media/benchmarks $<TARGET_FILE_DIR:firmament_portable_tests>/media/benchmarks)
# Two processes (GoogleTest's shards) rather than one per case, as the Windows build's unit tests,
# with the same two slow cases in the full tier (tests/CMakeLists.txt), and the reference's
# convergence in deep twilight (20 s here, 65 s under Wine, whose run is full tier too).
include(${CMAKE_CURRENT_LIST_DIR}/FirmamentTestGroups.cmake)
firmament_test_groups(firmament_portable_tests SHARDS 2 TIMEOUT 600
    FULL_TIER CloudScatteringFile ParticleScattering.TheOrdersMatchAMonteCarloRandomWalkThroughTheSameSphere
    ReferenceAtmosphere.PathsTowardSunlightConvergeInDeepTwilight)

# The rooms of src/ (cmake/FirmamentLayers.cmake): the tree's includes all run down them, and
# the check fails on an include up or across them. Checked here, natively, and by every build.
foreach(case IN ITEMS tree upward across new-room reference)
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/layers-${case})
    file(MAKE_DIRECTORY ${scratch})
    add_test(NAME Layers.${case} COMMAND ${CMAKE_COMMAND} -DPROJECT_DIR=${PROJECT_SOURCE_DIR} -DSCRATCH=${scratch} -DCASE=${case}
        -P ${tests}/layers/LayersTest.cmake)
    set_tests_properties(Layers.${case} PROPERTIES LABELS quick TIMEOUT 120)
endforeach()

if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    include(${tests}/fuzz/FuzzTargets.cmake)
else()
    message(STATUS "Firmament: the fuzz targets need clang (libFuzzer); skipped with ${CMAKE_CXX_COMPILER_ID}")
endif()
