#pragma once
// JSON scenes: objects made of mesh files or built-in shapes, placed with transforms, with an
// optional default camera and per-object rigid motion. The format is docs/scene-format.md.
// Internal: loadScene is the public entry point.

#include <string>

#include "vissort/scene.h"

namespace vissort::detail {

/// Reads a JSON scene; mesh paths are relative to the JSON file's folder.
/// Any problem (syntax, unknown key, wrong type, missing mesh, non-finite number, zero scale)
/// gives a one-line error that starts with the JSON file's path.
Result<Scene> loadJsonScene(const std::string& path);

} // namespace vissort::detail
