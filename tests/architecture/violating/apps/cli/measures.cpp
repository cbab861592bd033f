// Fixture for architecture.violations_are_reported: never compiled.
#include "exactgeo/testbed/resident_memory.hpp"
