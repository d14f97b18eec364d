# Generates the GL/GLES function loader at configure time with Debian's python3-glad (glad 2).
# One merged loader for desktop GL 4.5 core and GLES 3.2: every GL call goes through function
# pointers filled from the current backend's GetProcAddress, so the binary links no libGL /
# libGLESv2 and one executable serves EGL, OSMesa and GLFW (see platforms/README.md).
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT GLAD_EXECUTABLE)
    find_program(GLAD_EXECUTABLE glad REQUIRED)
endif()
set(PB_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
set(PB_GLAD_EXTENSIONS
    GL_KHR_debug GL_EXT_texture_compression_bptc GL_ARB_texture_compression_bptc
    GL_EXT_disjoint_timer_query GL_ARB_timer_query GL_EXT_color_buffer_float
    GL_EXT_color_buffer_half_float GL_ARB_ES3_compatibility GL_EXT_shader_framebuffer_fetch
    GL_EXT_float_blend GL_OES_texture_float_linear)
list(JOIN PB_GLAD_EXTENSIONS "," _pb_glad_ext)
if(NOT EXISTS ${PB_GLAD_DIR}/src/gl.c)
    message(STATUS "Generating GL loader with ${GLAD_EXECUTABLE}")
    execute_process(
        COMMAND /usr/bin/python3 -m glad --quiet --reproducible
                --api gl:core=4.5,gles2=3.2 --extensions ${_pb_glad_ext}
                --merge --out-path ${PB_GLAD_DIR} c
        RESULT_VARIABLE _pb_glad_rc OUTPUT_QUIET ERROR_VARIABLE _pb_glad_err)
    if(NOT _pb_glad_rc EQUAL 0)
        file(REMOVE_RECURSE ${PB_GLAD_DIR})
        message(FATAL_ERROR "glad failed (${_pb_glad_rc}): ${_pb_glad_err}")
    endif()
endif()
add_library(pb_glad STATIC ${PB_GLAD_DIR}/src/gl.c)
target_include_directories(pb_glad SYSTEM PUBLIC ${PB_GLAD_DIR}/include)
set_target_properties(pb_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
