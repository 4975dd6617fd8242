#include "app/common/date_daylight.h"

#include <stdexcept>

#include "shading/time_series.h"

namespace skylit::app {

std::optional<std::pair<double, double>> date_daylight(const std::string& time, const sky::Observer& place,
                                                       std::ostream* notes) {
  if (time.empty()) return std::nullopt;
  shading::TimeSpec spec;
  try {
    spec = shading::parse_time_spec(time);
  } catch (const std::invalid_argument& e) {
    // A day that does not exist is a date's error; anything else is not a date, and the
    // caller's parse of a time says what is wrong with it.
    if (shading::looks_like_date(time)) throw std::invalid_argument(std::string("--time: ") + e.what());
    return std::nullopt;
  }
  if (!shading::needs_place(spec)) return std::nullopt;
  const shading::TimeSeries day = shading::resolve_time_series(spec, place);
  if (day.instants.empty()) throw std::invalid_argument("--time " + time + ": " + day.note);
  if (!day.note.empty() && notes) *notes << "skylit: note: " << day.note << "\n";
  return std::pair{day.instants.front().unix_seconds, day.instants.back().unix_seconds};
}

}  // namespace skylit::app
