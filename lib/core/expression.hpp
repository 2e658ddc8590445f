// A scalar function of (x, y) given as text (muparser syntax), e.g. "-x^2" or "(1-x)^2".
#pragma once

#include <memory>
#include <string>

namespace hpcontact {

/// Parsed once at construction; evaluation is cheap. Variables: x, y; constants: pi, e.
/// Copies share the parser (not thread-safe, like muparser itself).
class Expression {
 public:
  /// @param text   the expression
  /// @param origin where it came from, for error messages (e.g. "scene.toml: key 'f'")
  /// @throws InputError if the text does not parse or uses unknown names.
  Expression(const std::string& text, const std::string& origin);

  /// Value at (x, y). @throws InputError if the value is NaN or infinite.
  double operator()(double x, double y) const;

  const std::string& text() const;

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace hpcontact
