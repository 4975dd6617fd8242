// The command line's names for the library options that errors point at. No library
// message names a flag (DESIGN.md "Layout"): an error that concerns one option says which
// in the library's own terms (terrain::DemError::option(), terrain::RasterWriteError::option(),
// shading::LightingError::option()), and the front ends add their flag for it here.
#pragma once

#include <exception>
#include <string>

namespace skylit::app {

// e.what(), with the flag of the option it concerns: "--lat: latitude 95 outside …",
// "… give its scale (metres per map unit) with -s/--scale", "… the file exists (pass
// --overwrite to replace it)". Errors that name no option are returned unchanged.
std::string message_with_flags(const std::exception& e);

}  // namespace skylit::app
