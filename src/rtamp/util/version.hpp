// rtamp's version (the CMake project's VERSION), for what rtamp writes about
// itself: `rtamp --version`, the library field and metadata of MCAP files.
#pragma once

namespace rtamp {

// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
const char* version();

}  // namespace rtamp
