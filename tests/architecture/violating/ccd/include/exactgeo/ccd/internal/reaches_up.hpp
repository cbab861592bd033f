// Fixture for architecture.violations_are_reported: never compiled. The top of
// include/exactgeo/ccd/ is the pair room's, which is below the dispatch (ccd.hpp).
#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/ccd/ccd.hpp"
