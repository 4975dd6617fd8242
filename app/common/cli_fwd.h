// CLI11's types as the front ends' headers name them. CLI11 2.1 is header-only and
// builds its validators in every file that includes it (7 s of -O3 each), so headers
// declare these and only the files that register options include <CLI/CLI.hpp>.
#pragma once

namespace CLI {
class App;
class Validator;
}  // namespace CLI
