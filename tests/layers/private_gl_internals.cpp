// Must not build: bounded_fragments.h is the gl oracle's own (not shared by src/gl/CMakeLists.txt).
#include "gl/bounded_fragments.h"
