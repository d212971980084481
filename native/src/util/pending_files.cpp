#include "util/pending_files.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace footfall::detail {
namespace {

// Fixed slots, so that the handler reads no allocated memory and takes no lock.
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled or emptied, 2 holds a path
  char path[4096];
};
std::array<Slot, 16> slots;

}  // namespace

bool note_pending_file(const std::string& path) {
  if (path.size() >= sizeof(Slot::path)) return false;
  for (Slot& slot : slots) {
    int free = 0;
    if (!slot.state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.state.store(2);
    return true;
  }
  return false;
}

void forget_pending_file(const std::string& path) {
  for (Slot& slot : slots) {
    int held = 2;
    if (slot.state.load() == 2 && path == slot.path && slot.state.compare_exchange_strong(held, 1))
      slot.state.store(0);
  }
}

void remove_pending_files() noexcept {
  for (Slot& slot : slots)
    if (slot.state.load() == 2) ::unlink(slot.path);
}

}  // namespace footfall::detail
