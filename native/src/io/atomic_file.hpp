// Private: writing an output file atomically, shared by the plan file and the
// crowd's glTF writer.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace footfall::detail {

/// Writes `bytes` to `path` through a temporary file beside it (hidden,
/// unique to the process and the write: ".NAME.<pid>-<n>.partial"), renamed
/// into place, so that a failure leaves no half-written file and two writers
/// of one path do not collide. Temporaries that stopped runs left are removed
/// first; a signal handler removes this one (util/pending_files). A NUL byte
/// in `path` is std::invalid_argument; other failures footfall::Error.
void write_file_atomically(const std::string& path, const std::string& bytes);

/// The same, the bytes written by `write` to a stream on the temporary file
/// as they come, so that a large file is never held in memory. What `write`
/// throws leaves no file either, and goes on to the caller.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace footfall::detail
