#include "gl/gl_program.h"

#include <initializer_list>
#include <stdexcept>
#include <string>

namespace vissort::detail {
namespace {

// Shaders and programs report their status and log through parallel entry points.
template <class GetStatus, class GetLog>
void requireStatus(GLuint name, GLenum status, GetStatus get_status, GetLog get_log,
                   const char* failure) {
    GLint ok = GL_FALSE;
    get_status(name, status, &ok);
    if (ok == GL_TRUE)
        return;
    char log[1024] = {};
    get_log(name, sizeof(log), nullptr, log);
    throw std::runtime_error(std::string(failure) + ": " + log);
}

GlShader compile(GLenum stage, const char* source) {
    GlShader shader(glCreateShader(stage));
    glShaderSource(shader.get(), 1, &source, nullptr);
    glCompileShader(shader.get());
    requireStatus(shader.get(), GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog,
                  stage == GL_VERTEX_SHADER     ? "OpenGL vertex shader does not compile"
                  : stage == GL_GEOMETRY_SHADER ? "OpenGL geometry shader does not compile"
                  : stage == GL_COMPUTE_SHADER  ? "OpenGL compute shader does not compile"
                                                : "OpenGL fragment shader does not compile");
    return shader;
}

// Links the compiled stages into one program.
GlProgram link(std::initializer_list<const GlShader*> stages) {
    GlProgram program(glCreateProgram());
    for (const GlShader* stage : stages)
        glAttachShader(program.get(), stage->get());
    glLinkProgram(program.get());
    requireStatus(program.get(), GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog,
                  "OpenGL program does not link");
    return program;
}

} // namespace

GlProgram linkProgram(const char* vertex_source, const char* fragment_source) {
    const GlShader vertex = compile(GL_VERTEX_SHADER, vertex_source);
    const GlShader fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
    return link({&vertex, &fragment});
}

GlProgram linkProgram(const char* vertex_source, const char* geometry_source,
                      const char* fragment_source) {
    const GlShader vertex = compile(GL_VERTEX_SHADER, vertex_source);
    const GlShader geometry = compile(GL_GEOMETRY_SHADER, geometry_source);
    const GlShader fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
    return link({&vertex, &geometry, &fragment});
}

GlProgram linkComputeProgram(const char* compute_source) {
    const GlShader compute = compile(GL_COMPUTE_SHADER, compute_source);
    return link({&compute});
}

} // namespace vissort::detail
