#include "rtamp/ros2/cdr_writer.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::ros2 {

void throw_bound(const char* field, std::size_t size, std::size_t bound) {
  throw Error(std::string("ROS 2 message field '") + field + "': " + std::to_string(size) + " elements, at most " +
              std::to_string(bound) + " allowed");
}

}  // namespace rtamp::ros2
