// tinyobjloader's parser compiled here, from the Debian package's header, as the reference the
// tests hold whitted's own OBJ line parser to (obj_line_test.cpp): the grammar whitted's meshes
// were always read with, the same numbers to the bit.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
