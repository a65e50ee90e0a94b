#include "rtamp/robot/ompl_logging.hpp"

#include <ompl/util/Console.h>

namespace rtamp::robot {

void quiet_ompl_logging() { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }

}  // namespace rtamp::robot
