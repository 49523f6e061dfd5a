// Orders the objects of a small animation frame after frame, each frame starting from the last
// one's order (SceneOrderer, scene_orderer.h), with the cpu oracle (cpu_oracle.h): the
// ordering component alone, no scene loading and no other oracle.
// Three squares of two triangles each pass one another along the view direction: square 0
// moves from behind the others to in front of them. The last frame's order, nearest first, is
// 0 1 2.

#include <cstdint>
#include <cstdio>
#include <vector>

#include <vissort/camera.h>
#include <vissort/cpu_oracle.h>
#include <vissort/geometry.h>
#include <vissort/scene_orderer.h>

namespace {

// A square of side 2 centred at (cx, cy) in the plane z, as two triangles.
void addSquare(vissort::TrianglePositions& p, float cx, float cy, float z) {
    const float x0 = cx - 1, x1 = cx + 1, y0 = cy - 1, y1 = cy + 1;
    p.x.insert(p.x.end(), {x0, x1, x1, x0, x1, x0});
    p.y.insert(p.y.end(), {y0, y0, y1, y0, y1, y1});
    p.z.insert(p.z.end(), {z, z, z, z, z, z});
}

} // namespace

int main() {
    const std::vector<vissort::PrimitiveRange> objects = {{0, 2}, {2, 2}, {4, 2}};
    const uint32_t triangles = 6;
    vissort::CpuOracle oracle;
    vissort::SceneOrderer orderer(objects, triangles, vissort::OrderLevel::object, oracle);

    vissort::CameraSpec camera; // at (0, 0, 5), looking down -z at the origin
    vissort::FrameOrder frame;
    const int frames = 5;
    for (int f = 0; f < frames; ++f) {
        vissort::TrianglePositions positions;
        const float z0 = -3.0f + 1.4f * static_cast<float>(f); // from -3 to 2.6
        addSquare(positions, 0.0f, 0.0f, z0);
        addSquare(positions, 0.8f, 0.5f, -1.0f);
        addSquare(positions, -0.6f, 0.7f, -2.0f);
        const vissort::ViewProjection view =
            vissort::frameCamera(camera, positions.bounds(), 256, 256);
        orderer.orderFrame(positions, view, frame);
        std::printf("frame %d: order", f);
        for (uint32_t id : frame.order)
            std::printf(" %u", id);
        std::printf(" (%llu queries)\n", static_cast<unsigned long long>(frame.stats.queries));
    }
    std::printf("order:");
    for (uint32_t id : frame.order)
        std::printf(" %u", id);
    std::printf("\n");
    return frame.cycles.empty() ? 0 : 1;
}
