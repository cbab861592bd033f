// Fixture for architecture.violations_are_reported: never compiled. mesh may include every
// room below it, but not a header in no room.
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/separation/internal/min_separation.hpp"
#include "exactgeo/ccd/unlisted.hpp"
