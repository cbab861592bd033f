#pragma once

#include <string>
#include <string_view>

namespace exactgeo::cli {

/// A JSON string literal (quotes included) for arbitrary bytes.
std::string json_string(std::string_view text);

/// The shortest decimal that reads back as exactly x (a JSON number for finite x).
std::string shortest(double x);

}  // namespace exactgeo::cli
