#pragma once
// Compiles and links the GLSL programs of everything that renders (the oracle, the renderer).

#include "gl/gl_objects.h"

namespace vissort::detail {

/// Links a program from vertex and fragment shader sources; throws std::runtime_error with the
/// driver's log when a stage does not compile or the program does not link. Needs a current
/// context.
GlProgram linkProgram(const char* vertex_source, const char* fragment_source);

/// Links a program from vertex, geometry and fragment shader sources; throws like linkProgram.
GlProgram linkProgram(const char* vertex_source, const char* geometry_source,
                      const char* fragment_source);

/// Links a compute program from one compute shader source; throws like linkProgram.
GlProgram linkComputeProgram(const char* compute_source);

} // namespace vissort::detail
