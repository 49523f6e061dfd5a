#pragma once
// The resolve of a supersampled render (RenderSettings::samples): each pixel's samples, a grid
// of columns x rows texels of the render target, averaged into one pixel, once a frame, on the
// GPU (reading back every sample would cost samples times the transfer).

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"
#include "render/render_target.h"
#include "vissort/transparency_renderer.h"

namespace vissort::detail {

class SampleResolve {
public:
    SampleResolve();

    /// The target's colour with each grid's samples averaged (in a fixed order, so the same
    /// samples give the same bits): target.width() / columns x target.height() / rows pixels,
    /// 4 floats each, row 0 at the top. The target's size is a multiple of the grid.
    std::vector<float> resolve(const RenderTarget& target, const SampleGrid& grid);

private:
    GlProgram program_;
    GlTexture resolved_;
    uint32_t width_ = 0, height_ = 0;
};

} // namespace vissort::detail
