# pb_embed_shaders(target dir): compiles every GLSL file under dir into the binary as a
# string table, so the executable does not depend on where it is run from.
function(pb_embed_shaders target dir)
    file(GLOB _files CONFIGURE_DEPENDS ${dir}/*.vert ${dir}/*.frag ${dir}/*.glsl)
    set(_out ${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp)
    string(REPLACE ";" "," _joined "${_files}") # a list cannot cross the command line as is
    add_custom_command(
        OUTPUT ${_out}
        COMMAND ${CMAKE_COMMAND} -DOUT=${_out} -DFILES=${_joined}
                -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
        DEPENDS ${_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
        COMMENT "Embedding shaders")
    target_sources(${target} PRIVATE ${_out})
endfunction()
