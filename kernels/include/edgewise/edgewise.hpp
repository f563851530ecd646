// The whole public API.
#pragma once

#include "edgewise/camera.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/interpolation.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/coverage.hpp"
#include "edgewise/multisample.hpp"
#include "edgewise/path.hpp"
#include "edgewise/pixel_area.hpp"
#include "edgewise/resolve.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/occlusion.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/threads.hpp"
#include "edgewise/vector.hpp"
