// Fixture for architecture.violations_are_reported: never compiled. common is below every
// room: it may not include a baseline.
#include "exactgeo/ccd/result.hpp"
#include "exactgeo/ccd/baselines/cubic.hpp"
