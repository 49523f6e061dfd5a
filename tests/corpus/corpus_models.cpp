#include "corpus_models.h"

#include <cmath>
#include <functional>

namespace vissort::test {
namespace {

using Point = std::array<float, 3>;
using Matrix = std::array<float, 16>;

constexpr double kPi = 3.14159265358979323846;

// To 4 decimals: short enough for every text format to write and read back unchanged.
float round4(double v) {
    return float(std::round(v * 1e4) / 1e4);
}

Matrix translation(float x, float y, float z) {
    return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1};
}

// A quarter turn about y, then a move: exact in every format (entries 0, 1, -1).
Matrix quarterTurnY(float x, float y, float z) {
    return {0, 0, 1, x, 0, 1, 0, y, -1, 0, 0, z, 0, 0, 0, 1};
}

Matrix scaled(float s, float x, float y, float z) {
    return {s, 0, 0, x, 0, s, 0, y, 0, 0, s, z, 0, 0, 0, 1};
}

uint32_t addMaterial(CorpusModel& model, const std::string& name, float r, float g, float b,
                     float a = 1.0f) {
    model.materials.push_back({name, r, g, b, a});
    return uint32_t(model.materials.size() - 1);
}

// A mesh placed once by the root node.
uint32_t addMesh(CorpusModel& model, CorpusMesh mesh) {
    model.meshes.push_back(std::move(mesh));
    const uint32_t index = uint32_t(model.meshes.size() - 1);
    model.root.meshes.push_back(index);
    return index;
}

// An axis-aligned box, six quads facing out.
CorpusMesh boxMesh(const std::string& name, Point lo, Point hi, uint32_t material) {
    CorpusMesh mesh{name, {}, {}, material};
    for (int i = 0; i < 8; ++i) {
        // 0..3 at z = lo, 4..7 at z = hi; around x, y: (lo, lo), (hi, lo), (hi, hi), (lo, hi).
        const int corner = i % 4;
        mesh.vertices.push_back({corner == 1 || corner == 2 ? hi[0] : lo[0],
                                 corner >= 2 ? hi[1] : lo[1], i >= 4 ? hi[2] : lo[2]});
    }
    mesh.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                  {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    return mesh;
}

uint32_t addBox(CorpusModel& model, const std::string& name, Point lo, Point hi,
                uint32_t material) {
    return addMesh(model, boxMesh(name, lo, hi, material));
}

// A one-sided quad (a decal, a pane, a rug), counter-clockwise as given.
uint32_t addQuad(CorpusModel& model, const std::string& name, Point a, Point b, Point c, Point d,
                 uint32_t material) {
    return addMesh(model, {name, {a, b, c, d}, {{0, 1, 2, 3}}, material});
}

// A prism between two parallel quads (a slanted bar): bottom a0..a3, top b0..b3, same winding.
uint32_t addPrism(CorpusModel& model, const std::string& name, std::array<Point, 4> a,
                  std::array<Point, 4> b, uint32_t material) {
    CorpusMesh mesh{name, {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]}, {}, material};
    mesh.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    return addMesh(model, std::move(mesh));
}

// A ring of `segments` points of radius r around centre in the plane spanned by u and v.
std::vector<Point> ring(const std::array<double, 3>& centre, const std::array<double, 3>& u,
                        const std::array<double, 3>& v, double r, int segments) {
    std::vector<Point> points;
    for (int k = 0; k < segments; ++k) {
        const double angle = 2 * kPi * k / segments;
        const double c = std::cos(angle), s = std::sin(angle);
        points.push_back({round4(centre[0] + r * (c * u[0] + s * v[0])),
                          round4(centre[1] + r * (c * u[1] + s * v[1])),
                          round4(centre[2] + r * (c * u[2] + s * v[2]))});
    }
    return points;
}

// A tube through rings (open at both ends), or a closed cylinder when capped.
CorpusMesh tubeMesh(const std::string& name, const std::vector<std::vector<Point>>& rings,
                    bool capped, uint32_t material) {
    CorpusMesh mesh{name, {}, {}, material};
    const uint32_t n = uint32_t(rings[0].size());
    for (const auto& r : rings)
        mesh.vertices.insert(mesh.vertices.end(), r.begin(), r.end());
    for (uint32_t i = 0; i + 1 < rings.size(); ++i)
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t a = i * n + k, b = i * n + (k + 1) % n;
            mesh.faces.push_back({a, b, b + n, a + n});
        }
    if (capped) {
        std::vector<uint32_t> first, last;
        for (uint32_t k = 0; k < n; ++k) {
            first.push_back(n - 1 - k);
            last.push_back(uint32_t(rings.size() - 1) * n + k);
        }
        mesh.faces.push_back(first);
        mesh.faces.push_back(last);
    }
    return mesh;
}

} // namespace

std::vector<WorldMesh> worldMeshes(const CorpusModel& model) {
    struct Instance {
        uint32_t mesh;
        Matrix world;
    };
    std::vector<Instance> instances;
    const std::function<void(const CorpusNode&, const Matrix&)> walk = [&](const CorpusNode& node,
                                                                           const Matrix& parent) {
        Matrix world{};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                for (int k = 0; k < 4; ++k)
                    world[r * 4 + c] += parent[r * 4 + k] * node.transform[k * 4 + c];
        for (uint32_t mesh : node.meshes)
            instances.push_back({mesh, world});
        for (const CorpusNode& child : node.children)
            walk(child, world);
    };
    walk(model.root, translation(0, 0, 0));
    std::vector<WorldMesh> meshes;
    for (uint32_t m = 0; m < model.meshes.size(); ++m)
        for (const Instance& instance : instances) {
            if (instance.mesh != m)
                continue;
            const CorpusMesh& mesh = model.meshes[m];
            WorldMesh world{mesh.name, {}, mesh.faces, mesh.material};
            const Matrix& t = instance.world;
            for (const Point& p : mesh.vertices)
                world.vertices.push_back({t[0] * p[0] + t[1] * p[1] + t[2] * p[2] + t[3],
                                          t[4] * p[0] + t[5] * p[1] + t[6] * p[2] + t[7],
                                          t[8] * p[0] + t[9] * p[1] + t[10] * p[2] + t[11]});
            meshes.push_back(std::move(world));
        }
    return meshes;
}

std::size_t triangleCount(const CorpusModel& model) {
    std::size_t count = 0;
    for (const WorldMesh& mesh : worldMeshes(model))
        for (const auto& face : mesh.faces)
            count += face.size() - 2;
    return count;
}

CorpusModel gridOfBoxes() {
    CorpusModel model{"grid_of_boxes", {}, {}, {"root"}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const uint32_t material =
                addMaterial(model, "box" + std::to_string(i * 3 + j), 0.2f + 0.3f * float(i),
                            0.3f + 0.2f * float(j), 0.6f);
            addBox(model, "box" + std::to_string(i * 3 + j), {float(i), 0, float(j)},
                   {float(i + 1), 1, float(j + 1)}, material);
        }
    return model;
}

CorpusModel smallHouse() {
    CorpusModel model{"small_house", {}, {}, {"root"}};
    const uint32_t concrete = addMaterial(model, "concrete", 0.6f, 0.6f, 0.6f);
    const uint32_t brick = addMaterial(model, "brick", 0.7f, 0.35f, 0.25f);
    const uint32_t roof = addMaterial(model, "roof", 0.35f, 0.2f, 0.15f);
    const uint32_t wood = addMaterial(model, "wood", 0.5f, 0.35f, 0.2f);
    const uint32_t glass = addMaterial(model, "glass", 0.6f, 0.8f, 0.9f, 0.4f);
    addBox(model, "slab", {-3, -0.25f, -2}, {3, 0, 2}, concrete);
    // Walls stand on the slab; the side walls butt against the front and back walls.
    addBox(model, "wall_front", {-3, 0, 1.75f}, {3, 2.5f, 2}, brick);
    addBox(model, "wall_back", {-3, 0, -2}, {3, 2.5f, -1.75f}, brick);
    addBox(model, "wall_left", {-3, 0, -1.75f}, {-2.75f, 2.5f, 1.75f}, brick);
    addBox(model, "wall_right", {2.75f, 0, -1.75f}, {3, 2.5f, 1.75f}, brick);
    addBox(model, "roof", {-3.25f, 2.5f, -2.25f}, {3.25f, 2.75f, 2.25f}, roof);
    addBox(model, "chimney", {1.5f, 2, -1}, {2, 3.5f, -0.5f}, brick); // through the roof
    // A door and a window lying on the walls' outer faces: coplanar with them.
    addQuad(model, "door", {-0.5f, 0, 2}, {0.5f, 0, 2}, {0.5f, 2, 2}, {-0.5f, 2, 2}, wood);
    addQuad(model, "window", {-3, 1, 1}, {-3, 1, -1}, {-3, 2, -1}, {-3, 2, 1}, glass);
    return model;
}

CorpusModel coplanarFloor() {
    CorpusModel model{"coplanar_floor", {}, {}, {"root"}};
    const uint32_t light = addMaterial(model, "tile_light", 0.9f, 0.9f, 0.85f);
    const uint32_t dark = addMaterial(model, "tile_dark", 0.3f, 0.3f, 0.35f);
    const uint32_t rug = addMaterial(model, "rug", 0.7f, 0.1f, 0.1f);
    const uint32_t mat = addMaterial(model, "mat", 0.1f, 0.5f, 0.2f, 0.5f);
    const uint32_t wood = addMaterial(model, "wood", 0.5f, 0.35f, 0.2f);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const float x = float(i), z = float(j);
            addQuad(model, "tile" + std::to_string(i * 4 + j), {x, 0, z}, {x, 0, z + 1},
                    {x + 1, 0, z + 1}, {x + 1, 0, z}, (i + j) % 2 ? dark : light);
        }
    // Coplanar with the tiles, overlapping several of them and each other.
    addQuad(model, "rug", {0.5f, 0, 0.5f}, {0.5f, 0, 2.5f}, {3, 0, 2.5f}, {3, 0, 0.5f}, rug);
    addQuad(model, "mat", {2, 0, 2}, {2, 0, 3.5f}, {3.5f, 0, 3.5f}, {3.5f, 0, 2}, mat);
    // A low table standing on the rug, a box on it.
    addBox(model, "table", {1, 0, 1}, {2.5f, 0.5f, 2}, wood);
    addBox(model, "crate", {1.25f, 0.5f, 1.25f}, {1.75f, 1, 1.75f}, wood);
    return model;
}

CorpusModel nestedBoxes() {
    CorpusModel model{"nested_boxes", {}, {}, {"root"}};
    for (int i = 0; i < 5; ++i) {
        const float h = 2.0f - 0.5f * float(i) + (i == 4 ? 0.25f : 0.0f); // 2, 1.5, 1, 0.5, 0.25
        const uint32_t material = addMaterial(model, "shell" + std::to_string(i), 0.2f * float(i),
                                              0.5f, 0.9f - 0.15f * float(i), i == 4 ? 1.0f : 0.5f);
        addBox(model, i == 4 ? "core" : "shell" + std::to_string(i), {-h, -h, -h}, {h, h, h},
               material);
    }
    return model;
}

CorpusModel interpenetrating() {
    CorpusModel model{"interpenetrating", {}, {}, {"root"}};
    const uint32_t steel = addMaterial(model, "steel", 0.5f, 0.55f, 0.6f);
    const uint32_t red = addMaterial(model, "red", 0.8f, 0.2f, 0.2f);
    const uint32_t blue = addMaterial(model, "blue", 0.2f, 0.3f, 0.8f);
    addBox(model, "block", {0, 0, 0}, {2, 1, 1}, steel);
    addBox(model, "bar_x", {-1, 0.375f, 0.375f}, {3, 0.625f, 0.625f}, red); // through the block
    addBox(model, "bar_z", {0.875f, 0.5f, -1}, {1.125f, 0.75f, 2}, blue);   // through both
    // Three sticks each lying over the next (the ground-truth tests' cycle), beside the block.
    std::array<Point, 3> corners;
    for (int i = 0; i < 3; ++i) {
        const double angle = kPi / 2 + 2 * kPi * i / 3;
        corners[i] = {round4(5 + 1.5 * std::cos(angle)), 0, round4(0.5 + 1.5 * std::sin(angle))};
    }
    for (int i = 0; i < 3; ++i) {
        const Point a = corners[i], b = corners[(i + 1) % 3];
        const double dx = b[0] - a[0], dz = b[2] - a[2], length = std::hypot(dx, dz);
        const double ux = dx / length, uz = dz / length, w = 0.15;
        const auto at = [&](double t, double side, float y) {
            return Point{round4(a[0] + ux * t - uz * side), y, round4(a[2] + uz * t + ux * side)};
        };
        const double t0 = -0.4, t1 = length + 0.4;
        addPrism(model, "stick" + std::to_string(i),
                 {at(t0, -w, 1.0f), at(t1, -w, 0.0f), at(t1, w, 0.0f), at(t0, w, 1.0f)},
                 {at(t0, -w, 1.125f), at(t1, -w, 0.125f), at(t1, w, 0.125f), at(t0, w, 1.125f)},
                 i == 0   ? red
                 : i == 1 ? blue
                          : steel);
    }
    return model;
}

CorpusModel pipeRun() {
    CorpusModel model{"pipe_run", {}, {}, {"root"}};
    const uint32_t pipe = addMaterial(model, "pipe", 0.8f, 0.6f, 0.2f, 0.6f);
    const uint32_t flange = addMaterial(model, "flange", 0.4f, 0.4f, 0.45f);
    const uint32_t support = addMaterial(model, "support", 0.3f, 0.3f, 0.3f);
    constexpr int kSegments = 12;
    constexpr double kRadius = 0.25, kBend = 0.75, kY = 1.0;
    // Rings across the run: along +x at z = 0 up to x = 3, a quarter bend about (3, y, 0.75),
    // then along +z from z = 0.75 at x = 3.75. Neighbouring pieces share their end rings.
    const auto straightX = [&](double x) {
        return ring({x, kY, 0}, {0, 1, 0}, {0, 0, 1}, kRadius, kSegments);
    };
    const auto bend = [&](double phi) {
        const std::array<double, 3> centre = {3 + kBend * std::sin(phi), kY,
                                              kBend * (1 - std::cos(phi))};
        return ring(centre, {0, 1, 0}, {-std::sin(phi), 0, std::cos(phi)}, kRadius, kSegments);
    };
    const auto straightZ = [&](double z) {
        return ring({3 + kBend, kY, z}, {0, 1, 0}, {-1, 0, 0}, kRadius, kSegments);
    };
    addMesh(model, tubeMesh("pipe_a", {straightX(0), straightX(1.5)}, false, pipe));
    addMesh(model, tubeMesh("pipe_b", {straightX(1.5), straightX(3)}, false, pipe));
    for (int i = 0; i < 3; ++i)
        addMesh(model, tubeMesh("elbow" + std::to_string(i),
                                {bend(kPi / 6 * i), bend(kPi / 6 * (i + 1))}, false, pipe));
    addMesh(model, tubeMesh("pipe_c", {straightZ(kBend), straightZ(3)}, false, pipe));
    // Flanges around the joints (the tubes pass through them), a bigger radius.
    const auto flangeX = [&](double x) {
        return ring({x, kY, 0}, {0, 1, 0}, {0, 0, 1}, 0.375, kSegments);
    };
    addMesh(model, tubeMesh("flange_ab", {flangeX(1.4375), flangeX(1.5625)}, true, flange));
    const auto flangeZ = [&](double z) {
        return ring({3 + kBend, kY, z}, {0, 1, 0}, {-1, 0, 0}, 0.375, kSegments);
    };
    addMesh(model, tubeMesh("flange_c", {flangeZ(1.875), flangeZ(2)}, true, flange));
    // Supports whose tops touch the tubes' lowest edge (ring point k = 6: y = 1 - 0.25).
    addBox(model, "support_a", {0.5f, 0, -0.25f}, {0.75f, 0.75f, 0.25f}, support);
    addBox(model, "support_c", {3.5f, 0, 2.25f}, {4, 0.75f, 2.5f}, support);
    return model;
}

CorpusModel shelves() {
    CorpusModel model{"shelves", {}, {}, {"root"}};
    const uint32_t wood = addMaterial(model, "wood", 0.55f, 0.4f, 0.25f);
    const uint32_t board_wood = addMaterial(model, "board", 0.75f, 0.6f, 0.4f, 0.7f);
    // Two meshes placed many times, never by the root itself.
    model.meshes.push_back(boxMesh("upright", {0, 0, 0}, {0.125f, 2, 0.5f}, wood));
    model.meshes.push_back(boxMesh("board", {0, 0, 0}, {1, 0.125f, 0.5f}, board_wood));
    const auto unit = [](const std::string& name, const Matrix& transform) {
        CorpusNode node{name, transform, {}, {}};
        node.children.push_back({name + "_left", translation(0, 0, 0), {0}, {}});
        node.children.push_back({name + "_right", translation(1.125f, 0, 0), {0}, {}});
        for (int i = 0; i < 4; ++i) // boards between the uprights, touching their inner faces
            node.children.push_back({name + "_board" + std::to_string(i),
                                     translation(0.125f, 0.625f * float(i), 0),
                                     {1},
                                     {}});
        return node;
    };
    model.root.children.push_back(unit("unit_a", translation(0, 0, 0)));
    // Turned a quarter, its back against unit_a's right upright.
    model.root.children.push_back(unit("unit_b", quarterTurnY(1.25f, 0, 1.75f)));
    // Half size, standing on unit_a's top board (y = 2), nested one level deeper.
    CorpusNode top{"top", translation(0, 2, 0), {}, {}};
    top.children.push_back(unit("unit_c", scaled(0.5f, 0.25f, 0, 0)));
    model.root.children.push_back(top);
    return model;
}

CorpusModel glassCase() {
    CorpusModel model{"glass_case", {}, {}, {"root"}};
    const uint32_t wood = addMaterial(model, "wood", 0.45f, 0.3f, 0.2f);
    const uint32_t stone = addMaterial(model, "stone", 0.8f, 0.8f, 0.75f);
    const uint32_t glass = addMaterial(model, "glass", 0.7f, 0.9f, 1.0f, 0.3f);
    addBox(model, "table_top", {0, 0.875f, 0}, {2, 1, 1}, wood);
    for (int i = 0; i < 4; ++i) {
        const float x = i % 2 ? 1.875f : 0, z = i / 2 ? 0.875f : 0;
        addBox(model, "leg" + std::to_string(i), {x, 0, z}, {x + 0.125f, 0.875f, z + 0.125f}, wood);
    }
    addBox(model, "statue", {0.75f, 1, 0.25f}, {1.25f, 1.625f, 0.75f}, stone);
    // The case stands on the table: its bottom face lies on the table top (coplanar).
    addBox(model, "case", {0.5f, 1, 0.125f}, {1.5f, 1.875f, 0.875f}, glass);
    return model;
}

CorpusModel stairs() {
    CorpusModel model{"stairs", {}, {}, {"root"}};
    const uint32_t concrete = addMaterial(model, "concrete", 0.65f, 0.65f, 0.6f);
    const uint32_t steel = addMaterial(model, "steel", 0.3f, 0.35f, 0.4f, 0.8f);
    constexpr int kSteps = 6;
    constexpr float kRise = 0.25f, kRun = 0.375f;
    // Step i spans two treads; step i + 1 rests on the back half of its top face.
    for (int i = 0; i < kSteps; ++i)
        addBox(model, "step" + std::to_string(i), {0, kRise * float(i), kRun * float(i)},
               {1.5f, kRise * float(i + 1), kRun * float(i + 2)}, concrete);
    addBox(model, "landing", {0, kRise * kSteps, kRun * (kSteps + 1)},
           {1.5f, kRise * (kSteps + 1), kRun * (kSteps + 4)}, concrete);
    // Posts standing on steps 0, 2 and 4, and a slanted handrail through their tops.
    for (int i = 0; i < kSteps; i += 2) {
        const float y = kRise * float(i + 1), z = kRun * float(i + 1);
        addBox(model, "post" + std::to_string(i), {1.375f, y, z}, {1.5f, y + 1, z + 0.125f}, steel);
    }
    const auto rail = [&](float x, float y, float z) { return Point{x, y, z}; };
    const float y0 = kRise + 0.875f, z0 = kRun, y1 = kRise * 5 + 0.875f, z1 = kRun * 5 + 0.125f;
    addPrism(model, "handrail",
             {rail(1.375f, y0, z0), rail(1.375f, y1, z1), rail(1.5f, y1, z1), rail(1.5f, y0, z0)},
             {rail(1.375f, y0 + 0.125f, z0), rail(1.375f, y1 + 0.125f, z1),
              rail(1.5f, y1 + 0.125f, z1), rail(1.5f, y0 + 0.125f, z0)},
             steel);
    return model;
}

} // namespace vissort::test
