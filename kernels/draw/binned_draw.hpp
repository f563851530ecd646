// draw()'s shading in screen bins on several threads (docs/design/threads.md), and the shading
// batch that both paths hand to the kernels.
#pragma once

#include "draw_stages.hpp"
#include "shading/shade_batch.hpp"

namespace edgewise::detail {

// The kernels' view of a screen mesh under `options`, clipped to `clip`; `texture` is the
// call's texture flattened once (null without one). Plane tiles are given per kernel call, with
// the planes reserved for it (PlaneStore).
ShadeBatch make_shade_batch(Framebuffer& target, const ScreenMesh& screen,
                            const DrawOptions& options, const PixelRect& clip,
                            const TextureDescription* texture);

// shade_screen_mesh() of a binned() call: the screen mesh's triangles binned in ranges, one task
// each, then each bin shaded by one task; the report as one kernel call over the mesh gives it.
void shade_in_bins(DrawCall& call, Framebuffer& target, const ScreenMesh& screen,
                   const DrawOptions& options, const TextureDescription* texture);

}  // namespace edgewise::detail
