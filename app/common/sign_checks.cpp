#include "app/common/sign_checks.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace skylit::app {
namespace {

CLI::Validator sign_check(const char* name, const char* wanted, std::function<bool(double)> accepts) {
  return CLI::Validator(
      [wanted, accepts](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) return "expected a number, not '" + text + "'";
        if (!std::isfinite(value)) return "expected a finite number, not '" + text + "'";
        if (!accepts(value)) return std::string("must be ") + wanted + ", not " + text;
        return "";
      },
      name);
}

}  // namespace

const CLI::Validator& positive_number() {
  static const CLI::Validator check = sign_check("POSITIVE", "greater than 0", [](double v) { return v > 0.0; });
  return check;
}

const CLI::Validator& non_negative_number() {
  static const CLI::Validator check = sign_check("NONNEGATIVE", "0 or more", [](double v) { return v >= 0.0; });
  return check;
}

}  // namespace skylit::app
