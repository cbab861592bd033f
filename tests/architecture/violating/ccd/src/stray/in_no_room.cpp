// Fixture for architecture.violations_are_reported: never compiled. Every file of ccd/ is
// in a room (cmake/CheckArchitecture.cmake lists them).
#include "exactgeo/ccd/queries.hpp"
