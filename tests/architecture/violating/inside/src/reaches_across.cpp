// Fixture for architecture.violations_are_reported: never compiled.
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/mesh.hpp"
