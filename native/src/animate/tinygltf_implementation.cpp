// tinygltf's implementation, compiled into the core from Debian's header so
// that the Python module carries no shared library of its own (the module's
// CMakeLists sets how: images carried as bytes, never decoded or encoded).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
