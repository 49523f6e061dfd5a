#pragma once
// The OpenGL 4.5 core API, called directly: glvnd's libOpenGL exports every core entry point and
// dispatches it to the driver of the context current on the calling thread, so vissort needs no
// function loader. Only the OpenGL backends include this: src/gl (the context, the oracle, the
// RAII objects of gl_objects.h) and src/render (the transparency renderer draws with OpenGL
// itself, through those objects). No public header does: no GL type appears in include/.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
