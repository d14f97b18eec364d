# pb_build_info(source): the configure-time facts `probebench --version` prints, as compile
# definitions of that one source file (changing them recompiles nothing else): the build type
# and the Mesa package installed where it was built (what it was tested against; the driver in
# use needs a GL context: `probebench info`). The commit comes from bench/runner/BuildInfo.cmake,
# refreshed at every build.
function(pb_build_info source)
    execute_process(COMMAND dpkg-query -W "-f=\${Version}" libgl1-mesa-dri
                    OUTPUT_VARIABLE _mesa ERROR_QUIET RESULT_VARIABLE _rc)
    if(NOT _rc EQUAL 0 OR _mesa STREQUAL "")
        set(_mesa "unknown (libgl1-mesa-dri not installed as a Debian package)")
    endif()
    set(_type "${CMAKE_BUILD_TYPE}")
    if(_type STREQUAL "")
        set(_type "none (CMAKE_BUILD_TYPE empty)")
    endif()
    set_source_files_properties(${source} PROPERTIES COMPILE_DEFINITIONS
        "PB_BUILD_TYPE=\"${_type}\";PB_BUILD_MESA=\"${_mesa}\"")
endfunction()
