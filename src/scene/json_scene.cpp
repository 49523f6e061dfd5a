// JSON scene files (docs/scene-format.md). Strict on purpose: an unknown key is an error, so a
// typo such as "translte" cannot silently leave an object at the origin.

#include "scene/json_scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/mesh_loader.h"
#include "vissort/closest_name.h"

namespace vissort::detail {
namespace {

using Json = nlohmann::json;

constexpr uint64_t kMaxTriangles = 50'000'000;

// Thrown by the readers below and caught in loadJsonScene, which turns it into a Result
// failure: the nesting is deep and every step can fail, so unwinding keeps the readers short.
struct JsonSceneError {
    std::string message; // "<where>: <problem>", without the file name
};

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
    throw JsonSceneError{where + ": " + problem};
}

void expectKeys(const Json& value, const std::string& where,
                std::initializer_list<const char*> allowed) {
    if (!value.is_object())
        fail(where, "expected an object");
    for (const auto& item : value.items()) {
        if (std::find_if(allowed.begin(), allowed.end(),
                         [&](const char* k) { return item.key() == k; }) != allowed.end())
            continue;
        std::string list;
        for (const char* k : allowed)
            list += std::string(list.empty() ? "" : ", ") + k;
        std::vector<std::string_view> names(allowed.begin(), allowed.end());
        fail(where, "unknown key '" + item.key() + "' (" + didYouMeanFirst(item.key(), names) +
                        "allowed: " + list + ")");
    }
}

double readNumber(const Json& value, const std::string& where) {
    if (!value.is_number())
        fail(where, "expected a number");
    const double number = value.get<double>();
    if (!std::isfinite(number))
        fail(where, "number is not finite");
    return number;
}

glm::dvec3 readVec3(const Json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3)
        fail(where, "expected an array of 3 numbers");
    return {readNumber(value[0], where + "[0]"), readNumber(value[1], where + "[1]"),
            readNumber(value[2], where + "[2]")};
}

glm::dvec3 readDirection(const Json& value, const std::string& where) {
    const glm::dvec3 direction = readVec3(value, where);
    if (glm::length(direction) == 0.0)
        fail(where, "direction must not be zero");
    return glm::normalize(direction);
}

std::string readString(const Json& value, const std::string& where) {
    if (!value.is_string())
        fail(where, "expected a string");
    return value.get<std::string>();
}

bool readBool(const Json& value, const std::string& where) {
    if (!value.is_boolean())
        fail(where, "expected true or false");
    return value.get<bool>();
}

Vec3 toVec3(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

/// Rotation about a unit axis through the origin (right-handed: counter-clockwise looking down
/// the axis towards the origin).
glm::dmat3 axisRotation(const glm::dvec3& unit_axis, double degrees) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), unit_axis));
}

/// {"axis": [x,y,z], "degrees": a} or [ax, ay, az]: Euler angles in degrees about the fixed
/// x, then y, then z axes, that is R = Rz * Ry * Rx.
glm::dmat3 readRotation(const Json& value, const std::string& where) {
    if (value.is_array()) {
        const glm::dvec3 angles = readVec3(value, where);
        return axisRotation({0, 0, 1}, angles.z) * axisRotation({0, 1, 0}, angles.y) *
               axisRotation({1, 0, 0}, angles.x);
    }
    expectKeys(value, where, {"axis", "degrees"});
    if (!value.contains("axis") || !value.contains("degrees"))
        fail(where, "needs both axis and degrees");
    return axisRotation(readDirection(value["axis"], where + ".axis"),
                        readNumber(value["degrees"], where + ".degrees"));
}

glm::dvec3 readScale(const Json& value, const std::string& where) {
    const glm::dvec3 scale =
        value.is_array() ? readVec3(value, where) : glm::dvec3(readNumber(value, where));
    if (scale.x == 0 || scale.y == 0 || scale.z == 0)
        fail(where, "scale must not be zero");
    return scale;
}

Rgba readColour(const Json& value, const std::string& where) {
    if (!value.is_array() || (value.size() != 3 && value.size() != 4))
        fail(where, "expected [r, g, b] or [r, g, b, a]");
    float channels[4] = {1, 1, 1, 1};
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string channel = where + "[" + std::to_string(i) + "]";
        const double c = readNumber(value[i], channel);
        if (c < 0 || c > 1)
            fail(channel, "colour channels must be in [0, 1]");
        channels[i] = static_cast<float>(c);
    }
    return {channels[0], channels[1], channels[2], channels[3]};
}

CameraSpec readCamera(const Json& value, const std::string& where) {
    expectKeys(value, where, {"eye", "target", "up", "fov", "ortho_dir"});
    CameraSpec camera;
    if (value.contains("ortho_dir")) {
        if (value.size() != 1)
            fail(where, "ortho_dir cannot be combined with eye, target, up or fov");
        camera.projection = Projection::orthographic;
        camera.ortho_direction = toVec3(readDirection(value["ortho_dir"], where + ".ortho_dir"));
    } else {
        if (!value.contains("eye") || !value.contains("target"))
            fail(where, "needs eye and target (perspective) or ortho_dir (orthographic)");
        camera.projection = Projection::perspective;
        camera.eye = toVec3(readVec3(value["eye"], where + ".eye"));
        camera.target = toVec3(readVec3(value["target"], where + ".target"));
        if (value.contains("up"))
            camera.up = toVec3(readVec3(value["up"], where + ".up"));
        if (value.contains("fov"))
            camera.fov_degrees = readNumber(value["fov"], where + ".fov");
    }
    const std::string problem = validateCamera(camera).error;
    if (!problem.empty())
        fail(where, problem);
    return camera;
}

/// Key frames: [{"time": seconds, "eye", "target", "up", "fov"}, ...], perspective cameras at
/// increasing times from 0 on.
std::vector<CameraKey> readCameraPath(const Json& value, const std::string& where) {
    if (!value.is_array() || value.empty())
        fail(where, "expected a non-empty array of key frames");
    std::vector<CameraKey> keys;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = where + "[" + std::to_string(i) + "]";
        const Json& key = value[i];
        if (!key.is_object())
            fail(at, "expected an object");
        expectKeys(key, at, {"time", "eye", "target", "up", "fov"});
        if (!key.contains("time"))
            fail(at, "missing 'time' (seconds)");
        const double time = readNumber(key["time"], at + ".time");
        if (time < 0)
            fail(at + ".time", "must not be negative");
        if (!keys.empty() && time <= keys.back().time)
            fail(at + ".time", "must be later than the key frame before it");
        Json camera = key;
        camera.erase("time");
        keys.push_back({time, readCamera(camera, at)});
    }
    return keys;
}

/// A unit cube centred at the origin: 12 triangles, counter-clockwise seen from outside.
Scene makeBox() {
    // Each face: the outward axis, then a corner order that winds counter-clockwise around it.
    static constexpr int kFaces[6][4][3] = {
        {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},     // +x
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}, // -x
        {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},     // +y
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}, // -y
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},     // +z
        {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}}, // -z
    };
    Scene box;
    box.positions.resize(12);
    std::size_t corner = 0;
    for (const auto& face : kFaces) {
        for (const int quad_corner : {0, 1, 2, 0, 2, 3}) {
            box.positions.x[corner] = 0.5f * static_cast<float>(face[quad_corner][0]);
            box.positions.y[corner] = 0.5f * static_cast<float>(face[quad_corner][1]);
            box.positions.z[corner] = 0.5f * static_cast<float>(face[quad_corner][2]);
            ++corner;
        }
    }
    box.objects.push_back({"box", Rgba{}, false, 0, 12});
    return box;
}

/// Constant linear and angular velocity of one JSON object (all its meshes move rigidly).
struct RigidMotion {
    uint32_t first_triangle = 0, triangle_count = 0;
    glm::dvec3 velocity{0.0};      // units per second
    glm::dvec3 spin_axis{0, 0, 1}; // unit
    double spin_degrees_per_second = 0;
    glm::dvec3 spin_centre{0.0}; // the object's bounding-box centre at t = 0
};

/// Moves each animated object rigidly from its t = 0 positions; the others stay put.
class RigidMotionAnimation final : public Animation {
public:
    RigidMotionAnimation(TrianglePositions rest, std::vector<RigidMotion> motions)
        : rest_(std::move(rest)), motions_(std::move(motions)) {}

    void positionsAt(double t, TrianglePositions& out) const override {
        out = rest_;
        for (const RigidMotion& motion : motions_) {
            const glm::dmat3 rotation =
                axisRotation(motion.spin_axis, motion.spin_degrees_per_second * t);
            const glm::dvec3 offset = motion.spin_centre + motion.velocity * t;
            const std::size_t begin = std::size_t{motion.first_triangle} * 3;
            const std::size_t end = begin + std::size_t{motion.triangle_count} * 3;
            for (std::size_t i = begin; i < end; ++i) {
                const glm::dvec3 p{rest_.x[i], rest_.y[i], rest_.z[i]};
                const glm::dvec3 moved = offset + rotation * (p - motion.spin_centre);
                out.x[i] = static_cast<float>(moved.x);
                out.y[i] = static_cast<float>(moved.y);
                out.z[i] = static_cast<float>(moved.z);
            }
        }
    }

private:
    TrianglePositions rest_;
    std::vector<RigidMotion> motions_;
};

RigidMotion readAnimation(const Json& value, const std::string& where) {
    expectKeys(value, where, {"velocity", "spin"});
    RigidMotion motion;
    if (value.contains("velocity"))
        motion.velocity = readVec3(value["velocity"], where + ".velocity");
    if (value.contains("spin")) {
        const Json& spin = value["spin"];
        const std::string spin_where = where + ".spin";
        expectKeys(spin, spin_where, {"axis", "degrees_per_second"});
        if (!spin.contains("axis") || !spin.contains("degrees_per_second"))
            fail(spin_where, "needs both axis and degrees_per_second");
        motion.spin_axis = readDirection(spin["axis"], spin_where + ".axis");
        motion.spin_degrees_per_second =
            readNumber(spin["degrees_per_second"], spin_where + ".degrees_per_second");
    }
    return motion;
}

class JsonSceneBuilder {
public:
    explicit JsonSceneBuilder(std::filesystem::path folder) : folder_(std::move(folder)) {}

    Scene build(const Json& root, const std::string& default_name) {
        expectKeys(root, "top level", {"name", "description", "camera", "camera_path", "objects"});
        scene_.name = root.contains("name") ? readString(root["name"], "name") : default_name;
        if (root.contains("description"))
            readString(root["description"], "description");
        if (root.contains("camera"))
            scene_.camera = readCamera(root["camera"], "camera");
        if (root.contains("camera_path")) {
            scene_.camera_path = readCameraPath(root["camera_path"], "camera_path");
            if (!scene_.camera)
                scene_.camera = scene_.camera_path.front().camera;
        }
        if (!root.contains("objects"))
            fail("top level", "missing 'objects'");
        const Json& objects = root["objects"];
        if (!objects.is_array())
            fail("objects", "expected an array");
        if (objects.empty())
            fail("objects", "the scene has no objects");
        for (std::size_t i = 0; i < objects.size(); ++i)
            addObject(objects[i], i);
        if (!motions_.empty())
            scene_.animation =
                std::make_shared<RigidMotionAnimation>(scene_.positions, std::move(motions_));
        return std::move(scene_);
    }

private:
    const Scene& source(const Json& object, const std::string& where) {
        const bool has_mesh = object.contains("mesh"), has_shape = object.contains("shape");
        if (has_mesh == has_shape)
            fail(where, "needs exactly one of 'mesh' or 'shape'");
        if (has_shape && object.contains("objects"))
            fail(where + ".objects", "says how a mesh file becomes objects: a shape is one");
        if (has_shape) {
            const std::string shape = readString(object["shape"], where + ".shape");
            if (shape != "box")
                fail(where + ".shape", "unknown shape '" + shape + "' (known: box)");
            if (!box_)
                box_ = makeBox();
            return *box_;
        }
        const std::string mesh = readString(object["mesh"], where + ".mesh");
        if (mesh.empty())
            fail(where + ".mesh", "empty path");
        // An entry is the object its user named, whatever the file's meshes.
        ObjectGrouping grouping = ObjectGrouping::file;
        if (object.contains("objects")) {
            const Result<ObjectGrouping> named = parseEnum<ObjectGrouping>(
                kObjectGroupingNames, readString(object["objects"], where + ".objects"),
                "grouping");
            if (!named)
                fail(where + ".objects", named.error);
            grouping = *named.value;
        }
        const std::string path = (folder_ / mesh).lexically_normal().string();
        const std::pair<std::string, ObjectGrouping> key{path, grouping};
        auto cached = meshes_.find(key);
        if (cached == meshes_.end()) {
            Result<Scene> loaded = loadMeshFile(path, grouping);
            if (!loaded)
                fail(where + ".mesh", loaded.error);
            cached = meshes_.emplace(key, std::move(*loaded.value)).first;
            // The JSON scene read what the mesh's loading read.
            for (const std::string& read : cached->second.source_files)
                if (std::find(scene_.source_files.begin(), scene_.source_files.end(), read) ==
                    scene_.source_files.end())
                    scene_.source_files.push_back(read);
        }
        return cached->second;
    }

    void addObject(const Json& object, std::size_t index) {
        const std::string where = "objects[" + std::to_string(index) + "]";
        expectKeys(object, where,
                   {"name", "mesh", "objects", "shape", "translate", "rotate", "scale", "colour",
                    "transparent", "animation"});
        const Scene& part = source(object, where);

        std::string name;
        if (object.contains("name"))
            name = readString(object["name"], where + ".name");
        else if (object.contains("mesh"))
            name = std::filesystem::path(object["mesh"].get<std::string>()).stem().string();
        else
            name = "box_" + std::to_string(index);

        glm::dvec3 scale{1.0}, translate{0.0};
        glm::dmat3 rotate{1.0};
        if (object.contains("scale"))
            scale = readScale(object["scale"], where + ".scale");
        if (object.contains("rotate"))
            rotate = readRotation(object["rotate"], where + ".rotate");
        if (object.contains("translate"))
            translate = readVec3(object["translate"], where + ".translate");
        // Scale, then rotate, then translate.
        const glm::dmat3 linear =
            rotate * glm::dmat3(glm::dvec3(scale.x, 0, 0), glm::dvec3(0, scale.y, 0),
                                glm::dvec3(0, 0, scale.z));

        std::optional<Rgba> colour;
        std::optional<bool> transparent;
        if (object.contains("colour"))
            colour = readColour(object["colour"], where + ".colour");
        if (object.contains("transparent"))
            transparent = readBool(object["transparent"], where + ".transparent");
        std::optional<RigidMotion> motion;
        if (object.contains("animation"))
            motion = readAnimation(object["animation"], where + ".animation");

        const std::size_t first_triangle = scene_.triangleCount();
        if (first_triangle + part.triangleCount() > kMaxTriangles)
            fail(where, "the scene exceeds " + std::to_string(kMaxTriangles) + " triangles");
        for (const SceneObject& part_object : part.objects) {
            SceneObject added = part_object;
            added.name = part.objects.size() > 1 ? name + "/" + part_object.name : name;
            added.first_triangle =
                static_cast<uint32_t>(first_triangle + part_object.first_triangle);
            for (ObjectPart& mesh_part : added.parts) {
                mesh_part.first_triangle += static_cast<uint32_t>(first_triangle);
                if (colour)
                    mesh_part.colour = *colour;
            }
            if (colour)
                added.colour = *colour;
            added.transparent = transparent ? *transparent : added.colour.a < 1.0f;
            scene_.objects.push_back(std::move(added));
        }

        TrianglePositions& out = scene_.positions;
        const std::size_t first_corner = first_triangle * 3;
        out.resize(first_triangle + part.triangleCount());
        Bounds bounds;
        for (std::size_t i = 0; i < part.positions.x.size(); ++i) {
            const glm::dvec3 p =
                linear * glm::dvec3(part.positions.x[i], part.positions.y[i], part.positions.z[i]) +
                translate;
            const std::size_t c = first_corner + i;
            out.x[c] = static_cast<float>(p.x);
            out.y[c] = static_cast<float>(p.y);
            out.z[c] = static_cast<float>(p.z);
            if (!std::isfinite(out.x[c]) || !std::isfinite(out.y[c]) || !std::isfinite(out.z[c]))
                fail(where, "transformed coordinates overflow single precision");
            bounds.add(out.corner(c));
        }

        if (motion) {
            motion->first_triangle = static_cast<uint32_t>(first_triangle);
            motion->triangle_count = static_cast<uint32_t>(part.triangleCount());
            const Vec3 centre = bounds.centre();
            motion->spin_centre = {centre.x, centre.y, centre.z};
            motions_.push_back(*motion);
        }
    }

    std::filesystem::path folder_;
    Scene scene_;
    std::optional<Scene> box_;
    // By normalised path and grouping: a mesh used twice is read once.
    std::map<std::pair<std::string, ObjectGrouping>, Scene> meshes_;
    std::vector<RigidMotion> motions_;
};

} // namespace

Result<Scene> loadJsonScene(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path file(path);
    if (!std::filesystem::is_regular_file(file, ec))
        return Result<Scene>::failure(path + (std::filesystem::exists(file, ec)
                                                  ? ": not a regular file"
                                                  : ": file not found"));
    try {
        std::ifstream stream(file, std::ios::binary);
        std::ostringstream text;
        text << stream.rdbuf();
        if (!stream)
            return Result<Scene>::failure(path + ": cannot read the file");
        // nlohmann keeps the last of repeated keys; a repeated key is as likely a mistake as a
        // typo.
        std::vector<std::set<std::string>> keys_per_object;
        const Json::parser_callback_t reject_duplicates = [&](int, Json::parse_event_t event,
                                                              Json& parsed) {
            if (event == Json::parse_event_t::object_start)
                keys_per_object.emplace_back();
            else if (event == Json::parse_event_t::object_end)
                keys_per_object.pop_back();
            else if (event == Json::parse_event_t::key &&
                     !keys_per_object.back().insert(parsed.get<std::string>()).second)
                throw JsonSceneError{"duplicate key '" + parsed.get<std::string>() + "'"};
            return true;
        };
        Json root;
        try {
            root = Json::parse(text.str(), reject_duplicates);
        } catch (const Json::exception& e) {
            // Syntax errors carry nlohmann's "at line L, column C"; a number too large for a
            // double (1e400) is reported as an overflow, naming the number.
            return Result<Scene>::failure(path + ": invalid JSON: " + e.what());
        }
        JsonSceneBuilder builder(file.parent_path());
        Scene scene = builder.build(root, file.stem().string());
        scene.source_files.insert(scene.source_files.begin(), path);
        return {std::move(scene), {}};
    } catch (const JsonSceneError& e) {
        return Result<Scene>::failure(path + ": " + e.message);
    } catch (const std::exception& e) {
        return Result<Scene>::failure(path + ": " + e.what());
    }
}

} // namespace vissort::detail
