// Loads a scene (a mesh file or a JSON scene) and prints the visibility order of its objects
// (or triangles), front to back, seen from the camera `vissort order` uses when none is asked
// for (the scene's own, else its geometry framed, at 1024x1024): the order
// `vissort order SCENE --level L` prints.
//   order_mesh SCENE [object|triangle|multistage]
// (The vissort command's builtin:NAME scenes are its samples', not the installed library's.)

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include <vissort/oracles.h>
#include <vissort/scene.h>
#include <vissort/scene_orderer.h>
#include <vissort/view_choice.h>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: order_mesh SCENE [object|triangle|multistage]\n");
        return 2;
    }
    const std::string specification = argv[1];
    const vissort::Result<vissort::OrderLevel> level =
        vissort::parseOrderLevel(argc > 2 ? argv[2] : "object");
    if (!level) {
        std::fprintf(stderr, "order_mesh: %s\n", level.error.c_str());
        return 2;
    }
    vissort::Result<vissort::Scene> loaded = vissort::loadScene(specification);
    if (!loaded) {
        std::fprintf(stderr, "order_mesh: %s: %s\n", specification.c_str(), loaded.error.c_str());
        return 1;
    }
    const vissort::Scene& scene = *loaded.value;
    vissort::Result<std::unique_ptr<vissort::GeometryOracle>> oracle =
        vissort::makeOracle(vissort::OracleKind::cpu);
    if (!oracle) {
        std::fprintf(stderr, "order_mesh: %s\n", oracle.error.c_str());
        return 1;
    }

    // The command line's camera policy (view_choice.h), with nothing asked.
    const vissort::Result<vissort::ChosenView> chosen = vissort::chooseView({}, scene);
    if (!chosen) {
        std::fprintf(stderr, "order_mesh: %s\n", chosen.error.c_str());
        return 1;
    }
    const vissort::ViewProjection view = vissort::frameCamera(
        chosen.value->camera, scene.positions.bounds(), chosen.value->width, chosen.value->height);
    // The orderer takes each object's triangle range, not the Scene: any mesh source will do.
    vissort::SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                  *level.value, **oracle.value);
    const vissort::FrameOrder frame = orderer.orderFrame(scene.positions, view);

    std::printf("%s: %zu objects, %zu triangles, %s level\n", specification.c_str(),
                scene.objects.size(), scene.triangleCount(), vissort::orderLevelName(frame.level));
    std::printf("order:");
    for (uint32_t id : frame.order)
        std::printf(" %u", id);
    std::printf("\ncycles: %zu, queries: %llu\n", frame.cycles.size(),
                static_cast<unsigned long long>(frame.stats.queries));
    return 0;
}
