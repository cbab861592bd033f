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
  return "?";
}

std::optional<Arithmetic> parse_arithmetic(std::string_view name) noexcept {
  for (const Arithmetic a : {Arithmetic::exact, Arithmetic::plain_double, Arithmetic::rational}) {
    if (name == to_string(a)) return a;
  }
  return std::nullopt;
}

}  // namespace exactgeo
