// tinyobjloader's parser compiled here, from the Debian package's header, rather than taken from
// its shared library: the same code (the same version), but built with this project's flags, so
// that the sanitizers and the fuzzers' coverage see inside it (fuzz/obj_fuzzer.cpp).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
