#pragma once

// Numbers given as option values (--min-separation, --tolerance), read exactly as every
// number in an input file is (io::parse_number): the whole text one finite double,
// decimals correctly rounded, hexfloats exact, and a value beyond the double range, at
// either end, refused instead of becoming infinity or zero.

#include <optional>
#include <string>

namespace exactgeo::cli {

/// The whole text as one finite double; else nullopt and the reason in `error` (which
/// quotes the text: "'1e-400' is outside the range of double").
std::optional<double> number_option(const std::string& text, std::string& error);

/// A --min-separation value: number_option, and >= 0 (-0 reads as 0).
std::optional<double> parse_min_separation(const std::string& text, std::string& error);

}  // namespace exactgeo::cli
