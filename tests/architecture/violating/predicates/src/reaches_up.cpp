// Fixture for architecture.violations_are_reported: never compiled.
#include "exactgeo/predicates/internal/coplanar.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/mesh/mesh.hpp"
