#include "scene/file_cameras.h"

#include <assimp/scene.h>

#include <cmath>
#include <numbers>

namespace vissort::detail {
namespace {

aiMatrix4x4 worldTransform(const aiNode* node) {
    aiMatrix4x4 world;
    for (; node != nullptr; node = node->mParent)
        world = node->mTransformation * world;
    return world;
}

bool isGltf(const std::string& extension) {
    return extension == "gltf" || extension == "glb";
}

Vec3 toVec3(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}

// The vertical field of view in degrees, from what the importer stored.
double verticalFovDegrees(const aiCamera& camera, const std::string& extension) {
    const double aspect = camera.mAspect > 0 ? camera.mAspect : 1.0;
    const double horizontal = camera.mHorizontalFOV;
    const double vertical = isGltf(extension)
                                ? horizontal / aspect // assimp 5.2: mHorizontalFOV = yfov * aspect
                                : 2 * std::atan(std::tan(horizontal / 2) / aspect);
    return vertical * 180 / std::numbers::pi;
}

} // namespace

std::vector<StoredCamera> fileCameras(const aiScene& scene, const std::string& extension,
                                      const Bounds& bounds) {
    std::vector<StoredCamera> cameras;
    for (unsigned i = 0; i < scene.mNumCameras; ++i) {
        const aiCamera& source = *scene.mCameras[i];
        StoredCamera stored;
        stored.name = source.mName.C_Str();
        if (stored.name.empty())
            stored.name = "camera_" + std::to_string(i);
        const aiNode* node = scene.mRootNode ? scene.mRootNode->FindNode(source.mName) : nullptr;
        const aiMatrix4x4 world = worldTransform(node);
        const aiMatrix3x3 rotation(world); // directions: no translation
        // glTF places a camera by its node alone; assimp 5.2 also copies the node's translation
        // into mPosition, which would apply it twice.
        const Vec3 eye = toVec3(world * (isGltf(extension) ? aiVector3D() : source.mPosition));
        const aiVector3D look = rotation * source.mLookAt;
        const Vec3 up = toVec3(rotation * source.mUp);
        const double length = look.Length();
        CameraSpec& camera = stored.camera;
        if (source.mOrthographicWidth > 0) {
            // vissort's orthographic views frame the scene along a direction; the width is not
            // used.
            camera.projection = Projection::orthographic;
            camera.ortho_direction = toVec3(look);
        } else {
            camera.projection = Projection::perspective;
            camera.eye = eye;
            camera.up = up;
            camera.fov_degrees = verticalFovDegrees(source, extension);
            const double reach = vissort::length(bounds.centre() - eye);
            camera.target =
                length > 0 ? eye + toVec3(look) * ((reach > 0 ? reach : 1.0) / length) : eye;
        }
        stored.problem = validateCamera(camera).error;
        cameras.push_back(std::move(stored));
    }
    return cameras;
}

} // namespace vissort::detail
