// Fuzz target: SteerSuite test cases (XML), read or refused with
// std::invalid_argument. A case read is read the same again with the same
// seed, to the bit, random regions and all.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "footfall/io/steersuite.hpp"
#include "properties.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const footfall::Scenario scenario = footfall::parse_steersuite(text, "fuzz.xml");
    footfall::fuzz::require(
        footfall::fuzz::same_scenario(footfall::parse_steersuite(text, "fuzz.xml"), scenario),
        "a SteerSuite case read twice is the same");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
