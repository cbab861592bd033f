// Fixture for architecture.violations_are_reported: never compiled. CCD reads no files:
// the query files are ccd_files', which alone may include io.
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/io/input_error.hpp"
