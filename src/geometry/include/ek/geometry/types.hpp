#pragma once
/// \file
/// The array types of curves (Vec3, VecX, Points, as_vector(), as_points()),
/// defined in the core module (ek/core/types.hpp) so that the optimiser,
/// which depends on core alone, shares them with the geometry.
#include "ek/core/types.hpp"
