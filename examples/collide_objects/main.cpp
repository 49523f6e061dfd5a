// Finds which objects of a scene collide, frame after frame (a dynamic scene moves 1/30 s a
// frame), with vissort's visibility-culled collision detection: the pairs of objects whose
// triangles intersect, by id and name, as `vissort collide SCENE --frames N` says them.
// Usage: collide_objects SCENE [FRAMES]   (default 1)

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <vissort/collision.h>
#include <vissort/scene.h>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: collide_objects SCENE [FRAMES]\n");
        return 2;
    }
    const std::string specification = argv[1];
    const int frames = argc > 2 ? std::atoi(argv[2]) : 1;
    if (frames < 1) {
        std::fprintf(stderr, "collide_objects: FRAMES must be a positive number\n");
        return 2;
    }
    vissort::Result<vissort::Scene> loaded = vissort::loadScene(specification);
    if (!loaded) {
        std::fprintf(stderr, "collide_objects: %s\n", loaded.error.c_str());
        return 1;
    }
    const vissort::Scene& scene = *loaded.value;
    try {
        // The detector takes each object's triangle range: any mesh source will do.
        vissort::CollisionDetector detector(scene.objectPrimitives(), vissort::CollisionSettings{});
        vissort::TrianglePositions positions;
        for (int frame = 0; frame < frames; ++frame) {
            scene.frame(frame * vissort::kFrameInterval, positions);
            const vissort::CollisionResult result = detector.collide(positions);
            const std::size_t pairs = result.pairs.size(), objects = result.object_pairs.size();
            std::printf("frame %d: %zu intersecting triangle pair%s, %zu colliding object pair%s\n",
                        frame, pairs, pairs == 1 ? "" : "s", objects, objects == 1 ? "" : "s");
            for (const vissort::ObjectPair& pair : result.object_pairs)
                std::printf("  %u '%s' and %u '%s'\n", pair.first,
                            scene.objects[pair.first].name.c_str(), pair.second,
                            scene.objects[pair.second].name.c_str());
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "collide_objects: %s\n", error.what());
        return 1;
    }
    return 0;
}
