// A scalar function of (x, y) given as text (muparser syntax), e.g. "-x^2" or "(1-x)^2".
#pragma once

#include <memory>
#include <string>

namespace hpcontact {

/// Parsed once at construction; evaluation is cheap. Variables: x, y (and z in 3-D); constants:
/// pi, e. Copies share the parser (not thread-safe, like muparser itself).
class Expression {
 public:
  /// @param text      the expression
  /// @param origin    where it came from, for error messages (e.g. "scene.toml: key 'f'")
  /// @param dimension 2 (variables x, y) or 3 (x, y, z)
  /// @throws InputError if the text does not parse or uses unknown names.
  Expression(const std::string& text, const std::string& origin, int dimension = 2);

  /// Value at (x, y) (z = 0). @throws InputError if the value is NaN or infinite.
  double operator()(double x, double y) const { return (*this)(x, y, 0.0); }
  /// Value at (x, y, z), for an expression of dimension 3.
  double operator()(double x, double y, double z) const;

  const std::string& text() const;

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace hpcontact
