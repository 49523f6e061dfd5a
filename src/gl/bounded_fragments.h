#pragma once
// The exact fragment model (geometry/exact_fragments.h) evaluated by OpenGL with error bounds:
// the gl oracle's program for depth tolerance 0 (gl_oracle.h). A driver cannot decide the model
// exactly, so every fragment the model has is rasterized, and its depth is written as an interval
// bound: the lower end by draws, the upper end by queries. A query then passes GREATER wherever
// the model puts it strictly behind something drawn, and also where the bounds overlap (a tie or
// a near tie within the rounding): a superset of the exact "behind" answers. Internal.

#include "gl/gl_objects.h"
#include "vissort/camera.h"

namespace vissort::detail {

class BoundedFragmentProgram {
public:
    BoundedFragmentProgram() = default;
    /// Compiles and links the program: vertex, geometry and fragment stages, GLSL 4.50 with
    /// doubles, drawing GL_TRIANGLES from attributes 0, 1 and 2 (a corner's x, y and z, as the
    /// plain program reads them). Needs a current context; throws std::runtime_error with the
    /// driver's log.
    static BoundedFragmentProgram link();

    GLuint get() const { return program_.get(); }

    /// Sets the view's uniforms: the pixel rays as PixelRays computes them, the depth range, the
    /// projection, the slack for the driver's rounding of the rays and the coverage margin.
    void setView(const ViewProjection& view) const;
    /// Draws write each fragment's depth rounded down (query false), queries rounded up.
    void setQuery(bool query) const;

private:
    GlProgram program_;
    GLint query_location_ = -1;
    int subpixel_bits_ = 8; // the driver's GL_SUBPIXEL_BITS
};

} // namespace vissort::detail
