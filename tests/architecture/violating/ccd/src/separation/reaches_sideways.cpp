// Fixture for architecture.violations_are_reported: never compiled. separation and pair
// are peers: what both use lives in common.
#include "exactgeo/ccd/common/internal/closest_direction.hpp"
#include "exactgeo/ccd/separation/internal/features.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
