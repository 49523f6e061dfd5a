// The built-in grids: deterministic hexahedral lattices over [-1, 1]^3, keeping the cells whose
// centre lies inside a shape, split into tetrahedra by tetrahedralize() (6 per hexahedron), with
// an analytic scalar per point. A convex one (the cube) where every method of ordering cells is
// exact, and non-convex ones (a torus, a trefoil knot) where a ray leaves and enters the grid
// again and ordering cells by their centres composites them out of order.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "grid/builtin_grids.h"
#include "grid/raw_grid.h"
#include "grid/token_scanner.h"
#include "vissort/closest_name.h"
#include "vissort/specification.h"

namespace vissort::detail {
namespace {

struct Shape {
    const char* name;
    const char* description;
    int default_n;
    // Whether a cell centre is inside the shape.
    std::function<bool(const Vec3&)> inside;
    // The scalar at a point, in about [0, 1].
    std::function<double(const Vec3&)> scalar;
};

constexpr double kPi = std::numbers::pi;

// A torus around z: tube radius 0.3 about a circle of radius 0.65.
double torusTubeDistance(const Vec3& p) {
    const double ring = std::hypot(p.x, p.y) - 0.65;
    return std::hypot(ring, p.z);
}

// The trefoil knot, scaled into [-1, 1]^2 x [-0.4, 0.4], as a closed polyline.
const std::vector<Vec3>& trefoil() {
    static const std::vector<Vec3> curve = [] {
        std::vector<Vec3> points;
        constexpr int kSegments = 360;
        for (int i = 0; i <= kSegments; ++i) {
            const double t = 2 * kPi * i / kSegments;
            points.push_back(Vec3{std::sin(t) + 2 * std::sin(2 * t),
                                  std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)} *
                             (0.82 / 3.0));
        }
        return points;
    }();
    return curve;
}

// Distance from p to the trefoil, and where along it (0 to 1) the nearest point is.
std::pair<double, double> trefoilDistance(const Vec3& p) {
    const std::vector<Vec3>& curve = trefoil();
    double best = 1e300, where = 0;
    for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
        const Vec3 a = curve[i], ab = curve[i + 1] - a;
        const double u = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
        const double d = length(p - (a + ab * u));
        if (d < best) {
            best = d;
            where = (i + u) / double(curve.size() - 1);
        }
    }
    return {best, where};
}
constexpr double kKnotTube = 0.17;

const std::vector<Shape>& shapes() {
    static const std::vector<Shape> list{
        {"cube", "a cube of n^3 hexahedra (6 n^3 tetrahedra): convex; two blobs of scalar", 16,
         [](const Vec3&) { return true; },
         [](const Vec3& p) {
             const Vec3 a{0.35, 0.2, 0.1}, b{-0.4, -0.3, -0.2};
             return std::exp(-dot(p - a, p - a) / 0.15) + 0.7 * std::exp(-dot(p - b, p - b) / 0.08);
         }},
        {"torus",
         "a torus of hexahedra on an n^3 lattice (about 1.1 n^3 tetrahedra): non-convex; "
         "scalar highest at the tube's centre, varying around it",
         24, [](const Vec3& p) { return torusTubeDistance(p) < 0.3; },
         [](const Vec3& p) {
             const double core = std::max(0.0, 1 - torusTubeDistance(p) / 0.3);
             return core * (0.65 + 0.35 * std::cos(3 * std::atan2(p.y, p.x)));
         }},
        {"knot",
         "a trefoil knot's tube of hexahedra on an n^3 lattice (about 0.35 n^3 "
         "tetrahedra): non-convex, in front of itself; scalar along the knot",
         40, [](const Vec3& p) { return trefoilDistance(p).first < kKnotTube; },
         [](const Vec3& p) {
             const auto [d, where] = trefoilDistance(p);
             const double core = std::max(0.0, 1 - d / kKnotTube);
             return core * (0.5 + 0.5 * std::sin(6 * kPi * where));
         }},
    };
    return list;
}

constexpr int kMaxLatticeCells = 200; // n at most: 6 * 200^3 = 48M tetrahedra for the cube

// The lattice of n^3 cells over [-1, 1]^3, keeping the cells whose centre is inside the shape;
// points are numbered in lattice order, so every hexahedron is split by the same rule.
Result<TetGrid> latticeGrid(const Shape& shape, int n) {
    const auto lattice_index = [n](int i, int j, int k) {
        return (uint64_t(k) * (n + 1) + j) * (n + 1) + i;
    };
    const auto lattice_point = [n](int i, int j, int k) {
        return Vec3{-1 + 2.0 * i / n, -1 + 2.0 * j / n, -1 + 2.0 * k / n};
    };
    std::vector<uint32_t> numbering(uint64_t(n + 1) * (n + 1) * (n + 1), UINT32_MAX);
    RawGrid raw;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec3 centre = lattice_point(i, j, k) + Vec3{1.0 / n, 1.0 / n, 1.0 / n};
                if (!shape.inside(centre))
                    continue;
                // VTK's hexahedron order: the bottom quad counter-clockwise seen from above.
                const std::array<std::array<int, 3>, 8> corners{{{i, j, k},
                                                                 {i + 1, j, k},
                                                                 {i + 1, j + 1, k},
                                                                 {i, j + 1, k},
                                                                 {i, j, k + 1},
                                                                 {i + 1, j, k + 1},
                                                                 {i + 1, j + 1, k + 1},
                                                                 {i, j + 1, k + 1}}};
                uint32_t cell[8];
                for (int c = 0; c < 8; ++c)
                    cell[c] = uint32_t(lattice_index(corners[c][0], corners[c][1], corners[c][2]));
                raw.addCell(CellType::hexahedron, cell);
            }
    if (raw.cell_types.empty())
        return Result<TetGrid>::failure(std::string("builtin:") + shape.name +
                                        " has no cells at n=" + std::to_string(n) +
                                        ": take a larger n");
    // Number the points used in lattice order (which keeps every cell's smallest corner).
    for (const uint32_t p : raw.cell_points)
        numbering[p] = 0;
    uint32_t next = 0;
    for (uint64_t p = 0; p < numbering.size(); ++p) {
        if (numbering[p] == UINT32_MAX)
            continue;
        numbering[p] = next++;
        const int i = int(p % (n + 1)), j = int(p / (n + 1) % (n + 1)),
                  k = int(p / (uint64_t(n + 1) * (n + 1)));
        raw.points.push_back(lattice_point(i, j, k));
        raw.scalars.push_back(shape.scalar(raw.points.back()));
    }
    for (uint32_t& p : raw.cell_points)
        p = numbering[p];
    raw.scalar_name = "analytic";
    return tetrahedralize(std::move(raw),
                          std::string("builtin:") + shape.name + "?n=" + std::to_string(n));
}

} // namespace

Result<TetGrid> makeBuiltinGrid(const std::string& name_and_parameters) {
    using R = Result<TetGrid>;
    const std::size_t question = name_and_parameters.find('?');
    const std::string name = name_and_parameters.substr(0, question);
    const auto& list = shapes();
    const auto shape =
        std::find_if(list.begin(), list.end(), [&](const Shape& s) { return name == s.name; });
    if (shape == list.end()) {
        std::vector<std::string> names;
        for (const Shape& s : list)
            names.push_back(s.name);
        return R::failure(oneLine("unknown built-in grid '" + name + "'") +
                          didYouMean(name, names) + "; the built-in grids are " +
                          builtinGridList());
    }
    const std::string specification = "builtin:" + name_and_parameters;
    Result<SpecificationParameters> parameters = parseSpecificationQuery(
        question == std::string::npos ? "" : name_and_parameters.substr(question + 1),
        specification);
    if (!parameters)
        return R::failure(oneLine(parameters.error));
    int n = shape->default_n;
    for (const auto& [key, text] : *parameters.value) {
        if (key != "n")
            return R::failure(oneLine("builtin:" + name + " has no parameter '" + key +
                                      "'; it takes n (cells along each side of its lattice)"));
        const std::optional<int64_t> value = TokenScanner::parseInteger(text);
        if (!value || *value < 1 || *value > kMaxLatticeCells)
            return R::failure(oneLine("builtin:" + name + "'s n must be a whole number from 1 to " +
                                      std::to_string(kMaxLatticeCells) + ", not '" + text + "'"));
        n = int(*value);
    }
    return latticeGrid(*shape, n);
}

std::string builtinGridList() {
    std::string list;
    for (const Shape& s : shapes())
        list += (list.empty() ? "" : ", ") + std::string(s.name);
    return list;
}

std::vector<BuiltinGridInfo> builtinGrids() {
    std::vector<BuiltinGridInfo> infos;
    for (const Shape& s : shapes())
        infos.push_back({s.name, s.description});
    return infos;
}

} // namespace vissort::detail
