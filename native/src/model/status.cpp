#include "footfall/model/status.hpp"

namespace footfall {

const char* to_string(Status status) {
  switch (status) {
    case Status::kSuccess:
      return "success";
    case Status::kPartial:
      return "partial";
    case Status::kNoPath:
      return "no_path";
    case Status::kInvalidStart:
      return "invalid_start";
    case Status::kInvalidGoal:
      return "invalid_goal";
    case Status::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace footfall
