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
  mu::Parser parser;
};

Expression::Expression(const std::string& text, const std::string& origin) : impl_(std::make_shared<Impl>()) {
  impl_->text = text;
  impl_->origin = origin;
  try {
    impl_->parser.DefineVar("x", &impl_->x);
    impl_->parser.DefineVar("y", &impl_->y);
    impl_->parser.DefineConst("pi", std::numbers::pi);
    impl_->parser.DefineConst("e", std::numbers::e);
    impl_->parser.SetExpr(text);
    // muparser parses lazily: evaluate once so that syntax errors surface here.
    impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw InputError(origin + ": expression \"" + shortened(text) + "\" does not parse: " + error.GetMsg() +
                     " (variables: x, y; constants: pi, e)");
  }
}

double Expression::operator()(double x, double y) const {
  impl_->x = x;
  impl_->y = y;
  double value = 0.0;
  try {
    value = impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw InputError(impl_->origin + ": expression \"" + shortened(impl_->text) +
                     "\" failed to evaluate: " + error.GetMsg());
  }
  if (!std::isfinite(value)) {
    throw InputError(impl_->origin + ": expression \"" + shortened(impl_->text) + "\" is " + std::to_string(value) +
                     " at (x, y) = (" + std::to_string(x) + ", " + std::to_string(y) +
                     "): it must be finite on the whole domain");
  }
  return value;
}

const std::string& Expression::text() const { return impl_->text; }

}  // namespace hpcontact
