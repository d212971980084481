// Fuzz target: scenario JSON. Every input is read or refused with
// std::invalid_argument; anything else (a crash, a sanitizer report, another
// exception) is a finding. A scenario read is read the same again, to the
// bit: what the reader makes depends on the text alone.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "footfall/io/scenario_file.hpp"
#include "properties.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const footfall::Scenario scenario = footfall::parse_scenario(text, "fuzz.json");
    footfall::fuzz::require(
        footfall::fuzz::same_scenario(footfall::parse_scenario(text, "fuzz.json"), scenario),
        "a scenario read twice is the same");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
