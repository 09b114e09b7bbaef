# Checks a capture with OpenEXR's own command-line tools (not our reader):
#   cmake -DEXRHEADER=... -DEXRINFO=... -DEXR=file.exr -DWIDTH=320 -DHEIGHT=200 -P this-file
# exrinfo must open the file; exrheader must list half RGBA channels, the resolution and
# every attribute Firmament writes.
foreach(tool EXRHEADER EXRINFO)
    execute_process(COMMAND ${${tool}} ${EXR} OUTPUT_VARIABLE output_${tool} ERROR_VARIABLE errors RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${${tool}} ${EXR} failed (${status}): ${errors}")
    endif()
endforeach()
set(header "${output_EXRHEADER}")
set(expected
    "R, 16-bit floating-point"
    "G, 16-bit floating-point"
    "B, 16-bit floating-point"
    "A, 16-bit floating-point"
    "dataWindow (type box2i): (0 0) - (${WIDTH_MINUS_ONE} ${HEIGHT_MINUS_ONE})"
    "firmament.resolution (type v2i): (${WIDTH} ${HEIGHT})"
    "firmament.version (type string)"
    "firmament.view (type m44f)"
    "firmament.projection (type m44f)"
    "firmament.directionToSun (type v3f)"
    "firmament.settings (type string)"
    "firmament.adapter (type string)"
    "firmament.d3d11 (type string)"
    "firmament.frame (type int)")
foreach(line IN LISTS expected)
    string(FIND "${header}" "${line}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "exrheader output lacks '${line}':\n${header}")
    endif()
endforeach()
message(STATUS "exrheader and exrinfo accept ${EXR}")
