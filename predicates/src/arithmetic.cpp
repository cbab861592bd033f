#include "exactgeo/predicates/arithmetic.hpp"

namespace exactgeo {

std::string_view to_string(Arithmetic a) noexcept {
  switch (a) {
    case Arithmetic::exact:
      return "exact";
    case Arithmetic::plain_double:
      return "double";
    case Arithmetic::rational:
      return "rational";
  }
  return "exact";
}

std::optional<Arithmetic> parse_arithmetic(std::string_view name) noexcept {
  if (name == "exact") return Arithmetic::exact;
  if (name == "double") return Arithmetic::plain_double;
  if (name == "rational") return Arithmetic::rational;
  return std::nullopt;
}

}  // namespace exactgeo
