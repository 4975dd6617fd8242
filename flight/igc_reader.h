// IGC flight logs (FAI/IGC "Technical Specification for GNSS Flight Recorders", 2nd ed.
// with AL6–AL8, chapter A4): B records, date headers, I-record extensions.
//
// Policy (tests rely on it):
//  * Dates: HFDTEddmmyy and HFDTEDATE:ddmmyy,NN both parse; yy < 80 is 20yy. A date
//    header after B records starts a new day for the fixes that follow.
//  * Times: a B time more than 12 h earlier than the previous one is the next UTC day
//    (loggers just wrap at midnight); otherwise a time that does not advance is an error.
//  * Altitudes: pressure (bytes 26–30) is ISA pressure altitude; GNSS (31–35) is above
//    the WGS 84 ellipsoid, as the spec says (AL6 A4: "GNSS Alt. - Altitude in metres
//    above the WGS84 ellipsoid"), unless the file declares HFALG…:GEO (then MSL).
//    Negative values ("-0012") parse. A channel that is 00000 in every fix of a file was
//    not recorded (the spec's fill for a missing sensor) and is dropped.
//  * Validity: A is a 3-D fix; V is kept, flagged invalid (Fix::valid = false); a V
//    fix's GNSS altitude of 00000 is no altitude.
//  * Track id: HFGID glider id, else HFCID competition id, else the A record's logger id.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "flight/track.h"

namespace skylit::flight {

// One track per file. Throws std::invalid_argument naming `name` and the line.
std::vector<Track> read_igc(std::istream& in, const std::string& name);

}  // namespace skylit::flight
