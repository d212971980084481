// Fuzz target: scenario JSON. Every input is read or refused with
// std::invalid_argument; anything else (a crash, a sanitizer report, another
// exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "footfall/io/scenario_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    footfall::parse_scenario(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
