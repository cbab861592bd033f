#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace exactgeo::io {

/// Bad user input, with the place it was found: "<source>:<line>: <what>".
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, std::size_t line, const std::string& what)
      : std::runtime_error(source + ":" + std::to_string(line) + ": " + what) {}
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace exactgeo::io
