#pragma once

// `--method` of the CCD subcommands (ccd, ccd-mesh): one of the methods a subcommand
// offers, by the library's name for it (ccd::to_string, ccd::parse_method).

#include <initializer_list>
#include <string>

#include "exactgeo/ccd/ccd.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// Registers `--method` on `sub`, accepting the names of `offered` (in that order in the
/// help and in the error for any other name); `method` must outlive the parse.
void add_ccd_method_option(CLI::App& sub, ccd::Method& method,
                           std::initializer_list<ccd::Method> offered,
                           const std::string& description);

}  // namespace exactgeo::cli
