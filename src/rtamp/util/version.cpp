#include "rtamp/util/version.hpp"

namespace rtamp {

const char* version() { return RTAMP_VERSION; }

}  // namespace rtamp
