#pragma once
// What every vissort command shares: exit codes, errors, the camera and frame options.

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/scene.h"
#include "vissort/view_choice.h"

namespace vissort::cli {

// Distinct codes so scripts can tell a mistyped command from a bad input file.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1; // could not write an output, or an internal failure
inline constexpr int kExitUsage = 2;   // bad command-line syntax or values
inline constexpr int kExitInput = 3;   // the scene or a mesh could not be loaded

/// Prints "vissort: error: MESSAGE" on one line to stderr and returns code.
int fail(int code, const std::string& message);

/// A vissort built without OpenGL (VISSORT_WITH_GL=OFF): prints "vissort: error: this vissort
/// was built without OpenGL (VISSORT_WITH_GL=OFF): WHAT is not available" and returns kExitFailure.
int failWithoutGl(const std::string& what);

struct ViewOptions {
    std::string eye, target, up, ortho_dir, camera, size = "1024x1024", path = "static";
    std::optional<double> fov, azimuth, elevation, distance;
    int frames = 1;
};

/// Parses --size's WxH; empty on success, else a one-line message naming the option.
std::string parseSize(const std::string& text, uint32_t& width, uint32_t& height);

/// Adds --eye --target --up --fov --ortho-dir --camera --azimuth --elevation --distance --size,
/// and with_frames --frames --path (a command
/// about one view, like info, takes no frames).
void addViewOptions(CLI::App& command, ViewOptions& options, bool with_frames = true);

/// "camera: perspective from ... (framed to the geometry)", plus what --path does to it.
std::string cameraLine(const ChosenView& view);

/// Empty on success, else a one-line message naming the bad option.
std::string resolveView(const ViewOptions& options, const Scene& scene, ChosenView& view);

/// Adds --objects: how a mesh file's meshes become objects (ObjectGrouping, scene.h).
void addObjectsOption(CLI::App& command, std::string& objects);

/// Loads a scene; `objects` is --objects's text, empty when not given. kExitOk with scene set,
/// else the exit code after the error is printed (kExitUsage for --objects, kExitInput for the
/// scene).
int loadSceneOrReport(const std::string& specification, const std::string& objects,
                      std::optional<Scene>& scene);

/// loadSceneOrReport, then resolveView: kExitOk with both set, else the exit code after the
/// error is printed (kExitInput for the scene, kExitUsage for an option).
int loadSceneAndView(const std::string& specification, const std::string& objects,
                     const ViewOptions& options, std::optional<Scene>& scene, ChosenView& view);

} // namespace vissort::cli
