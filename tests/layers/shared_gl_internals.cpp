// Builds: the GL objects and programs are what gl shares with the renderer and the viewer.
#include "gl/gl_program.h"
#include "render/draw_sequence.h"
