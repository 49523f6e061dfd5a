#pragma once
// Volume rendering of tetrahedral grids by emission and absorption (docs/volume.md, "The rendering
// law"): each cell that a pixel's ray crosses is one segment of length l (in units of the grid's
// bounding-box diagonal), from scalar s_in to s_out (the scalar is linear in a cell), with colour
// TF_rgb(s_mid) and opacity 1 - exp(-density * TF_extinction(s_mid) * l), s_mid = (s_in + s_out)
// / 2; the segments are composited back to front over the background ("over").
//
// Layer: vissort::volume (the package's `volume` component; docs/architecture.md).

#include <cstdint>
#include <memory>
#include <string_view>

#include "vissort/camera.h"
#include "vissort/enum_names.h"
#include "vissort/geometry.h"
#include "vissort/image.h"
#include "vissort/oracles.h"
#include "vissort/result.h"
#include "vissort/scene.h"
#include "vissort/tet_grid.h"
#include "vissort/transfer_function.h"

namespace vissort {

/// How a grid is rendered.
struct VolumeSettings {
    TransferFunction transfer;
    double density = 4.0; // scales every extinction
    Rgba background{0.3f, 0.32f, 0.36f, 1.0f};
};

/// Empty when settings can render grid, else a one-line problem: the grid has scalars, the
/// transfer function is valid, density is finite and non-negative, the background in [0, 1].
Status validateVolumeSettings(const TetGrid& grid, const VolumeSettings& settings);

/// The picture of grid from view by casting one ray through each pixel centre and walking it
/// from cell to cell across shared faces (Embree finds where it enters the grid, and enters it
/// again past a concavity): exact up to double rounding and independent of any rasterizer, the
/// reference of the tests. The ray is clipped at the near plane (and the far plane,
/// orthographic). thread_count 0 uses the hardware's; the picture is the same for any.
/// Fails (one line) on invalid settings or when no Embree device can be made.
Result<Image> castVolume(const TetGrid& grid, const VolumeSettings& settings,
                         const ViewProjection& view, unsigned thread_count = 0);

/// How a picture's cell segments are put in order before they are composited. Every method
/// cuts each pixel's ray into the same segments as castVolume (one per cell it crosses); they
/// differ only in the order in which those segments are composited.
enum class VolumeMethod {
    vissort,  // cells ordered by Vis-sort's occlusion queries, coherently from the last frame;
              // cells in cycles ordered per pixel: exact
    centroid, // cells sorted by their centres' depth along the view (VTK's
              // vtkCellCenterDepthSort): approximate
    mpvo,     // Williams' MPVO: a topological sort of the face adjacency, each shared face
              // ordering its two cells by the side the eye is on: exact on convex acyclic grids
    lists,    // every pixel's segments gathered and sorted by depth: exact, memory per pixel
    raycast,  // castVolume: one ray a pixel walked from cell to cell: exact, the reference
};
inline constexpr EnumName<VolumeMethod> kVolumeMethodNames[] = {
    {VolumeMethod::vissort, "vissort"}, {VolumeMethod::centroid, "centroid"},
    {VolumeMethod::mpvo, "mpvo"},       {VolumeMethod::lists, "lists"},
    {VolumeMethod::raycast, "raycast"},
};
inline Result<VolumeMethod> parseVolumeMethod(std::string_view name) {
    return parseEnum<VolumeMethod>(kVolumeMethodNames, name, "volume method");
}
inline const char* volumeMethodName(VolumeMethod method) {
    return enumName<VolumeMethod>(kVolumeMethodNames, method);
}

/// What one frame cost.
struct VolumeFrameStats {
    double order_ms = 0;     // putting the cells in order (vissort, centroid, mpvo)
    double composite_ms = 0; // compositing the segments (for raycast: the whole picture)
    uint64_t cells = 0;
    uint64_t queries = 0; // vissort: occlusion queries asked
    uint64_t cycles = 0;  // vissort: cycles found; mpvo: cycles broken
    uint64_t cells_in_cycles = 0;
    uint64_t segments = 0;      // cell segments composited (pixels x cells crossed)
    uint64_t list_segments = 0; // lists, and vissort in cycles: segments held in per-pixel lists
};

/// Renders frames of one grid by one method. Keeps what coherence needs from frame to frame
/// (vissort's last order and cycles), so a sequence of views is rendered by one renderer. The
/// grid must outlive it and not change.
class VolumeRenderer {
public:
    /// oracle: the occlusion queries' backend of the vissort method (ignored by the others);
    /// thread_count 0 uses the hardware's. The picture is the same for any thread count.
    VolumeRenderer(const TetGrid& grid, VolumeMethod method, OracleKind oracle = OracleKind::cpu,
                   unsigned thread_count = 0);
    ~VolumeRenderer();
    VolumeRenderer(const VolumeRenderer&) = delete;
    VolumeRenderer& operator=(const VolumeRenderer&) = delete;

    /// The picture from view, or a one-line problem (invalid settings, an oracle that cannot be
    /// made, a grid that is not conforming).
    Result<Image> render(const VolumeSettings& settings, const ViewProjection& view);
    /// The last render's costs.
    const VolumeFrameStats& stats() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// The grid's boundary faces as a scene of one object: what frames and chooses a grid's cameras
/// (chooseView) as it does a scene's, and what a viewer can outline.
Scene boundaryScene(const TetGrid& grid);

} // namespace vissort
