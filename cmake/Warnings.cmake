# pb_warnings(target): the warning set every probebench target compiles with.
function(pb_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter)
endfunction()

# pb_library(name dir [deps...]): a library from every .cpp in `dir` (an INTERFACE library
# while it has none), so adding a source file never means editing a CMakeLists.txt.
function(pb_library name dir)
    file(GLOB _src CONFIGURE_DEPENDS ${dir}/*.cpp)
    if(_src)
        add_library(${name} STATIC ${_src})
        target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/renderer
                                                  ${PROJECT_SOURCE_DIR})
        target_link_libraries(${name} PUBLIC ${ARGN})
        pb_warnings(${name})
        # Compiled ten files to a translation unit (CI builds everything twice; this halves
        # the time spent parsing the same headers). So a helper in a file's anonymous
        # namespace needs a name no other file of its folder uses. Files with options of
        # their own (ProbeSampler.cpp's -ffp-contract=off) are compiled alone, as before.
        set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 10)
    else()
        add_library(${name} INTERFACE)
        target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR}/renderer
                                                     ${PROJECT_SOURCE_DIR})
        target_link_libraries(${name} INTERFACE ${ARGN})
    endif()
    # Remembered for pb_check_layering (cmake/Layering.cmake): one library per folder.
    set_property(GLOBAL APPEND PROPERTY PB_LIBRARIES ${name})
    set_property(GLOBAL PROPERTY PB_LIBRARY_DIR_${name} ${dir})
    set_property(GLOBAL PROPERTY PB_LIBRARY_DEPS_${name} ${ARGN})
endfunction()
