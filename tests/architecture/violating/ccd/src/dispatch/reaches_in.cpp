// Fixture for architecture.violations_are_reported: never compiled.
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/predicates/internal/ray_patch_core.hpp"
