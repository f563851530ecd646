// The whole public API.
#pragma once

#include "edgewise/isa.hpp"
#include "edgewise/raster.hpp"
