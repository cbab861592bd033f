#pragma once

// Numbers given as option values (--min-separation, --tolerance), read exactly as every
// number in an input file is (io::parse_number): the whole text one finite double,
// decimals correctly rounded, hexfloats exact, and a value beyond the double range, at
// either end, refused instead of becoming infinity or zero.

#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// The whole text as one finite double; else nullopt and the reason in `error` (which
/// quotes the text: "'1e-400' is outside the range of double").
std::optional<double> number_option(const std::string& text, std::string& error);

/// Registers `name` on `sub` with its value read by number_option, then handed to `take`,
/// which may refuse it by returning a reason (a range: "expected a positive number"); the
/// option's error names it and quotes the text. CLI11's own number conversion rounds
/// through long double, twice; this reads as every input number is read.
void add_number_option(CLI::App& sub, const std::string& name,
                       std::function<std::optional<std::string>(double)> take,
                       const std::string& help);

/// A --min-separation value: number_option, and >= 0 (-0 reads as 0).
std::optional<double> parse_min_separation(const std::string& text, std::string& error);

}  // namespace exactgeo::cli
