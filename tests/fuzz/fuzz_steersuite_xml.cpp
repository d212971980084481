// Fuzz target: SteerSuite test cases (XML), read or refused with
// std::invalid_argument.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "footfall/io/steersuite.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    footfall::parse_steersuite(std::string(reinterpret_cast<const char*>(data), size), "fuzz.xml");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
