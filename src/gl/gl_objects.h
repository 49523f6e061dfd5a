#pragma once
// Owning handles for OpenGL objects: non-copyable, movable, deleted with their context current.

#include <utility>

#include "gl/gl_api.h"

namespace vissort::detail {

/// One GL object name, deleted by Delete{}(name) unless 0.
template <class Delete> class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) {}
    ~GlObject() {
        if (name_ != 0)
            Delete{}(name_);
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            if (name_ != 0)
                Delete{}(name_);
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GLuint get() const { return name_; }

private:
    GLuint name_ = 0;
};

struct DeleteBuffer {
    void operator()(GLuint name) const { glDeleteBuffers(1, &name); }
};
struct DeleteVertexArray {
    void operator()(GLuint name) const { glDeleteVertexArrays(1, &name); }
};
struct DeleteFramebuffer {
    void operator()(GLuint name) const { glDeleteFramebuffers(1, &name); }
};
struct DeleteRenderbuffer {
    void operator()(GLuint name) const { glDeleteRenderbuffers(1, &name); }
};
struct DeleteTexture {
    void operator()(GLuint name) const { glDeleteTextures(1, &name); }
};
struct DeleteProgram {
    void operator()(GLuint name) const { glDeleteProgram(name); }
};
struct DeleteShader {
    void operator()(GLuint name) const { glDeleteShader(name); }
};
struct DeleteQuery {
    void operator()(GLuint name) const { glDeleteQueries(1, &name); }
};

using GlBuffer = GlObject<DeleteBuffer>;
using GlVertexArray = GlObject<DeleteVertexArray>;
using GlFramebuffer = GlObject<DeleteFramebuffer>;
using GlRenderbuffer = GlObject<DeleteRenderbuffer>;
using GlTexture = GlObject<DeleteTexture>;
using GlProgram = GlObject<DeleteProgram>;
using GlShader = GlObject<DeleteShader>;
using GlQuery = GlObject<DeleteQuery>;

} // namespace vissort::detail
