// Checks for numeric options bounded only by their sign. CLI11's PositiveNumber and
// NonNegativeNumber print their range up to DBL_MAX ("Value 0 not in range 0.000000 to
// 17976931348623157…"); these say what is wanted in one short line.
#pragma once

#include "app/common/cli_fwd.h"

namespace skylit::app {

// A finite number > 0: "must be greater than 0, not -2".
const CLI::Validator& positive_number();
// A finite number ≥ 0: "must be 0 or more, not -1".
const CLI::Validator& non_negative_number();

}  // namespace skylit::app
