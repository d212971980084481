// Footfall — expected outcomes (Status) and the one exception type for failures
// that are neither misuse (std::invalid_argument) nor a bad index
// (std::out_of_range).
#pragma once

#include <stdexcept>
#include <string>

namespace footfall {

/// Outcome of a planning call. Expected outcomes are values, not exceptions.
/// (Why an agent's whole walk ended early, at the crowd's time limit for
/// one, is its plan's AgentStatus and reason.)
enum class Status {
  kSuccess,  ///< The goal was reached.
  kPartial,  ///< The horizon was reached first; the result leads toward the goal.
  kNoPath,   ///< No progress toward the goal is possible from the start.
  kInvalidStart,  ///< The start state collides with an obstacle.
  kInvalidGoal,   ///< The goal lies inside an obstacle.
  kCancelled,     ///< Stopped by the caller's cancel flag.
};

/// Lower-case name of a status, as written in files ("success", "partial", ...).
const char* to_string(Status status);

/// A failure that is not caused by a bad argument: I/O errors, for instance.
/// Python sees it as `footfall.FootfallError`.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace footfall
