#pragma once
// Files that are either the old version or the new one, whole: written under a temporary name beside
// the target, flushed to the disk, then renamed over it (rename(2) within a directory is atomic).
#include <string>
#include <string_view>

namespace granmc {

/// Writes `bytes` to `path + ".tmp-<pid>"`, fsyncs it and renames it to `path`. On failure (a full disk,
/// no permission) removes the temporary file, leaves any earlier `path` as it was, and throws
/// std::runtime_error "cannot write <what> '<path>': ... (<reason>)".
void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& what);

}  // namespace granmc
