# pb_build_info(target): gives `target` a generated BuildInfo.cpp (pb::app::buildCommit(),
# buildType(), buildMesa()) for `probebench --version`. The commit is read at every build (a
# configure-time value would go stale with the next commit); the file is rewritten only when
# its text changes, so an unchanged commit recompiles nothing.
function(pb_build_info target)
    set(_out ${CMAKE_CURRENT_BINARY_DIR}/BuildInfo.cpp)
    # The Mesa that was installed where the binary was built: what it was tested against.
    # The driver in use at run time needs a GL context (`probebench info`).
    execute_process(COMMAND dpkg-query -W "-f=\${Version}" libgl1-mesa-dri
                    OUTPUT_VARIABLE _mesa ERROR_QUIET RESULT_VARIABLE _rc)
    if(NOT _rc EQUAL 0 OR _mesa STREQUAL "")
        set(_mesa "unknown (libgl1-mesa-dri not installed as a Debian package)")
    endif()
    add_custom_target(${target}_build_info
        COMMAND ${CMAKE_COMMAND} -DOUT=${_out} -DSRC=${PROJECT_SOURCE_DIR}
                "-DTYPE=${CMAKE_BUILD_TYPE}" "-DMESA=${_mesa}"
                -P ${PROJECT_SOURCE_DIR}/cmake/BuildInfoScript.cmake
        BYPRODUCTS ${_out}
        COMMENT "Build info (commit)")
    add_dependencies(${target} ${target}_build_info)
    target_sources(${target} PRIVATE ${_out})
endfunction()
