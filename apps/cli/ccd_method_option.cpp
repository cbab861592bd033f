#include "cli/ccd_method_option.hpp"

#include <CLI/CLI.hpp>

#include <vector>

namespace exactgeo::cli {

void add_ccd_method_option(CLI::App& sub, ccd::Method& method,
                           std::initializer_list<ccd::Method> offered,
                           const std::string& description) {
  std::vector<std::string> names;
  for (const ccd::Method m : offered)
    names.emplace_back(ccd::to_string(m));
  sub.add_option_function<std::string>(
         "--method", [&method](const std::string& m) { method = *ccd::parse_method(m); },
         description)
      ->check(CLI::IsMember(std::move(names)));
}

}  // namespace exactgeo::cli
