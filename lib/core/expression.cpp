// Expression on top of muparser: parse errors and non-finite values become InputError.
#include "core/expression.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace hpcontact {
namespace {

// Messages quote an expression, but not a megabyte of it.
std::string shortened(const std::string& text) {
  constexpr std::size_t kShown = 120;
  if (text.size() <= kShown) return text;
  return text.substr(0, kShown) + "... (" + std::to_string(text.size()) + " characters)";
}

}  // namespace

struct Expression::Impl {
  std::string text;
  std::string origin;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  int dimension = 2;
  mu::Parser parser;
};

Expression::Expression(const std::string& text, const std::string& origin, int dimension)
    : impl_(std::make_shared<Impl>()) {
  HPC_VERIFY(dimension == 2 || dimension == 3, "expressions in two or three variables");
  impl_->text = text;
  impl_->origin = origin;
  impl_->dimension = dimension;
  try {
    impl_->parser.DefineVar("x", &impl_->x);
    impl_->parser.DefineVar("y", &impl_->y);
    if (dimension == 3) impl_->parser.DefineVar("z", &impl_->z);
    impl_->parser.DefineConst("pi", std::numbers::pi);
    impl_->parser.DefineConst("e", std::numbers::e);
    impl_->parser.SetExpr(text);
    // muparser parses lazily: evaluate once so that syntax errors surface here.
    impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw InputError(
        origin + ": expression \"" + shortened(text) + "\" does not parse: " + error.GetMsg() +
        (dimension == 3 ? " (variables: x, y, z; constants: pi, e)" : " (variables: x, y; constants: pi, e)"));
  }
}

double Expression::operator()(double x, double y, double z) const {
  impl_->x = x;
  impl_->y = y;
  impl_->z = z;
  double value = 0.0;
  try {
    value = impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw InputError(impl_->origin + ": expression \"" + shortened(impl_->text) +
                     "\" failed to evaluate: " + error.GetMsg());
  }
  if (!std::isfinite(value)) {
    throw InputError(
        impl_->origin + ": expression \"" + shortened(impl_->text) + "\" is " + std::to_string(value) + " at " +
        (impl_->dimension == 3
             ? "(x, y, z) = (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + ")"
             : "(x, y) = (" + std::to_string(x) + ", " + std::to_string(y) + ")") +
        ": it must be finite on the whole domain");
  }
  return value;
}

const std::string& Expression::text() const { return impl_->text; }

}  // namespace hpcontact
