// Private: writing an output file atomically, shared by the plan file and the
// crowd's glTF writer.
#pragma once

#include <string>

namespace footfall::detail {

/// Writes `bytes` to `path` through a temporary file beside it (hidden,
/// unique to the process and the write: ".NAME.<pid>-<n>.partial"), renamed
/// into place, so that a failure leaves no half-written file and two writers
/// of one path do not collide. Temporaries that stopped runs left are removed
/// first; a signal handler removes this one (util/pending_files). A NUL byte
/// in `path` is std::invalid_argument; other failures footfall::Error.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace footfall::detail
