# PB_FUZZ=ON: everything is compiled with libFuzzer's coverage instrumentation plus ASan and
# UBSan (UB aborts, so the fuzzer records it as a crash). Included from the top-level
# CMakeLists.txt instead of find_package(TinyGLTF); fuzz/README.md has the commands.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PB_FUZZ=ON needs clang (libFuzzer): "
                        "CC=clang CXX=clang++ cmake -S . -B build-fuzz -DPB_FUZZ=ON")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
# Source-based line coverage of what the corpus reaches (fuzz/coverage.sh).
option(PB_FUZZ_COVERAGE "Fuzz targets with llvm-cov instrumentation" OFF)
if(PB_FUZZ_COVERAGE)
    add_compile_options(-fprofile-instr-generate -fcoverage-mapping)
    add_link_options(-fprofile-instr-generate)
endif()

# tinygltf and toml++ come from Debian as shared libraries built without coverage: the fuzzer
# would be blind inside them and ASan would not see their out-of-bounds accesses. Here they
# are compiled from the very headers those libraries are built from (Debian's tiny_gltf.h,
# stb_image.h, toml++), instrumented like the rest.
add_library(pb_tinygltf_instrumented STATIC ${CMAKE_CURRENT_LIST_DIR}/TinyGltfFromHeader.cpp)
target_include_directories(pb_tinygltf_instrumented SYSTEM PUBLIC ${STB_INCLUDE_DIRS})
target_link_libraries(pb_tinygltf_instrumented PUBLIC nlohmann_json::nlohmann_json)
add_library(TinyGLTF::TinyGLTF ALIAS pb_tinygltf_instrumented)
set_property(TARGET tomlplusplus::tomlplusplus PROPERTY INTERFACE_COMPILE_OPTIONS
             -DTOML_HEADER_ONLY=1)
