// Renders a scene with exact order-independent transparency (Vis-sort's order of the
// transparent objects, cycles composited per pixel) and writes it as a PNG, from the camera
// `vissort render` uses when none is asked for: the same pixels as
//   vissort render SCENE --size WIDTHxHEIGHT -o OUT.png
// Usage: render_transparent SCENE OUT.png [WIDTHxHEIGHT]   (default 640x480)

#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <vissort/gl_context.h>
#include <vissort/image.h>
#include <vissort/scene.h>
#include <vissort/transparency_renderer.h>
#include <vissort/view_choice.h>

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::fprintf(stderr, "usage: render_transparent SCENE OUT.png [WIDTHxHEIGHT]\n");
        return 2;
    }
    const std::string specification = argv[1], output = argv[2];
    unsigned width = 640, height = 480;
    if (argc == 4 && std::sscanf(argv[3], "%ux%u", &width, &height) != 2) {
        std::fprintf(stderr, "render_transparent: size '%s' is not WIDTHxHEIGHT\n", argv[3]);
        return 2;
    }
    vissort::Result<vissort::Scene> loaded = vissort::loadScene(specification);
    if (!loaded) {
        std::fprintf(stderr, "render_transparent: %s\n", loaded.error.c_str());
        return 1;
    }
    const vissort::Scene& scene = *loaded.value;

    // The command line's camera policy: the scene's camera, else its geometry framed.
    vissort::ViewDef def;
    def.width = width;
    def.height = height;
    const vissort::Result<vissort::ChosenView> chosen = vissort::chooseView(def, scene);
    if (!chosen) {
        std::fprintf(stderr, "render_transparent: %s\n", chosen.error.c_str());
        return 1;
    }
    const vissort::ViewProjection view =
        vissort::frameCamera(chosen.value->camera, scene.positions.bounds(), width, height);

    // Headless OpenGL through EGL (a GPU's driver, or Mesa's llvmpipe on the CPU).
    vissort::Result<std::shared_ptr<vissort::GlContext>> context = vissort::GlContext::shared();
    if (!context) {
        std::fprintf(stderr, "render_transparent: %s\n", context.error.c_str());
        return 1;
    }
    try {
        vissort::RenderSettings settings; // vissort's method, object level, lit, exact
        vissort::TransparencyRenderer renderer(*context.value, scene, settings);
        vissort::RenderStats stats;
        const vissort::Image image = renderer.render(scene.positions, view, stats);
        if (vissort::Status written = vissort::writeImage(output, width, height, image.toRgba8());
            !written) {
            std::fprintf(stderr, "render_transparent: %s\n", written.error.c_str());
            return 1;
        }
        std::printf("%s: %zu objects, %zu triangles, %ux%u: order %.1f ms, render %.1f ms, "
                    "%u cycle groups a pixel at most; wrote %s\n",
                    specification.c_str(), scene.objects.size(), scene.triangleCount(), width,
                    height, stats.order_ms, stats.render_ms, stats.groups, output.c_str());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "render_transparent: %s\n", error.what());
        return 1;
    }
    return 0;
}
