# The rooms of src/ (one folder each) from the bottom up, and the rooms each may include besides
# its own (docs/architecture.md, "Rooms"). src/CMakeLists.txt makes one library per room, linked
# to exactly these; CheckLayers.cmake fails the build when an include in src/ names a room that
# is not listed here for the includer.
#
#   core        errors, logging, files, images, camera, settings listing; no Direct3D
#   gpu         the Direct3D 11 device and what is made on it
#   input       keyboard, mouse, HID devices, pads, the fly camera
#   tables      pre-computed tables made over frames and cached
#   frame       the vocabulary of a frame: what the renderer hands every pass (FrameContext,
#               FrameTargets) and what one technique hands another (shadow inputs, the
#               atmosphere's look-ups); below the techniques so that none includes another
#   techniques  atmosphere, shadows, terrain, lightshafts, clouds, postfx, scene: one room each,
#               none including another
#   reference   the CPU twins and references the tests hold the techniques to; linked by the
#               tests only, and no other room may include it
#   settings    State: every technique's settings as one JSON state
#   ui          the GUI: panels over the settings
#   render      Renderer: the frame order, the one place where techniques meet
#   app         the program: window, loop, captures, benchmark
set(FIRMAMENT_TECHNIQUE_ROOMS atmosphere shadows terrain lightshafts clouds postfx scene)
set(FIRMAMENT_ROOMS core gpu input tables frame ${FIRMAMENT_TECHNIQUE_ROOMS} reference settings ui render app)

set(FIRMAMENT_ROOM_core_MAY_INCLUDE "")
set(FIRMAMENT_ROOM_gpu_MAY_INCLUDE core)
set(FIRMAMENT_ROOM_input_MAY_INCLUDE core)
set(FIRMAMENT_ROOM_tables_MAY_INCLUDE gpu core)
set(FIRMAMENT_ROOM_frame_MAY_INCLUDE gpu core)
foreach(technique IN LISTS FIRMAMENT_TECHNIQUE_ROOMS)
    set(FIRMAMENT_ROOM_${technique}_MAY_INCLUDE frame tables gpu core)
endforeach()
set(FIRMAMENT_ROOM_reference_MAY_INCLUDE ${FIRMAMENT_TECHNIQUE_ROOMS} frame tables gpu core)
set(FIRMAMENT_ROOM_settings_MAY_INCLUDE ${FIRMAMENT_TECHNIQUE_ROOMS} input core)
set(FIRMAMENT_ROOM_ui_MAY_INCLUDE settings ${FIRMAMENT_TECHNIQUE_ROOMS} input gpu core)
set(FIRMAMENT_ROOM_render_MAY_INCLUDE settings ${FIRMAMENT_TECHNIQUE_ROOMS} frame tables gpu core)
set(FIRMAMENT_ROOM_app_MAY_INCLUDE render ui settings ${FIRMAMENT_TECHNIQUE_ROOMS} frame tables input gpu core)

# firmament_check_layers(TARGET): a target that checks every include in src/ against the table
# above whenever a source or the table changes; the rooms' libraries depend on it, so an include
# up the layers stops the build with a message naming the file and the include.
function(firmament_check_layers target)
    file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/*.h ${PROJECT_SOURCE_DIR}/src/*.cpp)
    set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}.stamp)
    add_custom_command(OUTPUT ${stamp}
        COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}/src -P ${PROJECT_SOURCE_DIR}/cmake/CheckLayers.cmake
        COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
        DEPENDS ${sources} ${PROJECT_SOURCE_DIR}/cmake/CheckLayers.cmake ${PROJECT_SOURCE_DIR}/cmake/FirmamentLayers.cmake
        COMMENT "Layers: every include in src/ runs down the rooms"
        VERBATIM)
    add_custom_target(${target} DEPENDS ${stamp})
endfunction()
