# firmament_warnings(TARGET): the project's own code builds with warnings on, as errors.
# Third-party code is compiled by its own build and is not affected.
option(FIRMAMENT_WARNINGS_AS_ERRORS "Treat warnings in Firmament's own code as errors" ON)

function(firmament_warnings target)
    if(MSVC)
        target_compile_options(${target} PRIVATE /W4 /permissive- /utf-8)
        if(FIRMAMENT_WARNINGS_AS_ERRORS)
            target_compile_options(${target} PRIVATE /WX)
        endif()
    else()
        target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
        if(FIRMAMENT_WARNINGS_AS_ERRORS)
            target_compile_options(${target} PRIVATE -Werror)
        endif()
    endif()
    # Windows headers: no min/max macros, Unicode APIs, Windows 10 and later.
    target_compile_definitions(${target} PRIVATE NOMINMAX WIN32_LEAN_AND_MEAN UNICODE _UNICODE
        _WIN32_WINNT=0x0A00)
    if(MSVC)
        # MSVC's C library without its "unsafe function" warnings (getenv, _wgetenv in the
        # tests and the cache folder's look-up), which /WX would make errors.
        target_compile_definitions(${target} PRIVATE _CRT_SECURE_NO_WARNINGS)
    endif()
endfunction()
