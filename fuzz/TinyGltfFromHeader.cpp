// tinygltf's implementation from Debian's tiny_gltf.h (the header libtinygltf.so is built
// from), compiled into the fuzz build only so that libFuzzer sees its coverage and ASan its
// memory accesses (fuzz/FuzzBuild.cmake). stb_image: Debian's libstb-dev header.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
