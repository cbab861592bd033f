#pragma once

#include <string>
#include <string_view>

namespace exactgeo::cli {

/// A JSON string literal (quotes included) for arbitrary bytes.
std::string json_string(std::string_view text);

}  // namespace exactgeo::cli
