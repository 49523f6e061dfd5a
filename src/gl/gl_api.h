#pragma once
// The OpenGL 4.5 core API, called directly: glvnd's libOpenGL exports every core entry point and
// dispatches it to the driver of the context current on the calling thread, so vissort needs no
// function loader. Only src/gl includes this.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
