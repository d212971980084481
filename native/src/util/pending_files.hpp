// Footfall — files being written, which a signal handler removes if the
// program is stopped before they are finished (a half-written plan must not
// be left behind).
#pragma once

#include <string>

namespace footfall::detail {

/// Notes `path` as being written (false if too many are, or it is too long
/// to note; it is then only removed by a later run).
bool note_pending_file(const std::string& path);
/// `path` is finished or gone.
void forget_pending_file(const std::string& path);
/// Removes every noted file. Async-signal-safe: for a SIGINT or SIGTERM
/// handler.
void remove_pending_files() noexcept;

}  // namespace footfall::detail
