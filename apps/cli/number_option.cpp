#include "number_option.hpp"

#include <CLI/CLI.hpp>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/io/text_scan.hpp"

namespace exactgeo::cli {

std::optional<double> number_option(const std::string& text, std::string& error) {
  return io::parse_number(text, error);
}

void add_number_option(CLI::App& sub, const std::string& name,
                       std::function<std::optional<std::string>(double)> take,
                       const std::string& help) {
  sub.add_option_function<std::string>(
      name,
      [name, take = std::move(take)](const std::string& text) {
        std::string error;
        const auto value = number_option(text, error);
        if (!value) throw CLI::ValidationError(name, error);
        if (const auto refused = take(*value)) {
          throw CLI::ValidationError(name, *refused + ", got " + io::quoted(text));
        }
      },
      help);
}

std::optional<double> parse_min_separation(const std::string& text, std::string& error) {
  const auto value = number_option(text, error);
  if (!value) return std::nullopt;
  if (!ccd::is_valid_min_separation(*value)) {
    error = io::quoted(text) + " is negative";
    return std::nullopt;
  }
  return *value + 0.0;  // -0 as +0
}

}  // namespace exactgeo::cli
